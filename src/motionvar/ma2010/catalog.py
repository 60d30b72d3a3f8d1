"""The evaluations of Ma et al. 2010 (:class:`motionvar.claims.Evaluation`): the one list the
workflow's rules, the applicability table (:mod:`.requirements`) and the claims are read off."""

from ..claims import Evaluation

EVALUATIONS: tuple[Evaluation, ...] = (
    Evaluation(
        "ma2010_fig3",
        "Fig. 3",
        "Key frames (foot strikes, Eq. 1-4) align the walking cycles of different clips.",
        "ma2010",
    ),
    Evaluation(
        "ma2010_fig6",
        "Fig. 6",
        "Leave-one-out: the synthesized cycle has the held-out clip's stride (within 1.2 cm); Kriging beats RBF (MK05).",
        "ma2010",
    ),
    Evaluation(
        "ma2010_variogram",
        "Sec. 6 (variogram)",
        "Diagnostic, no claim: the semivariograms of the Kriging residuals per joint group, with the fitted variograms.",
        "ma2010",
    ),
    Evaluation("ma2010_fig7b", "Fig. 7b", "Strides far outside the examples are synthesized less reliably.", "ma2010"),
    Evaluation(
        "ma2010_fig8",
        "Fig. 8a",
        "At a fixed style, variants differ as much as the examples do, at the same stride.",
        "ma2010",
    ),
    Evaluation(
        "ma2010_sec7_4",
        "Sec. 7.4",
        "Ours is the most natural of six methods (foot skating, jerk, discontinuities).",
        "ma2010",
    ),
    Evaluation("ma2010_sec8", "Sec. 8", "Synthesis runs faster than real time.", "ma2010"),
)
