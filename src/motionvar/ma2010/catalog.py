"""The evaluations of Ma et al. 2010 (:class:`motionvar.claims.Evaluation`): the one list the
workflow's rules, the applicability table (:mod:`.requirements`) and the claims are read off."""

from ..claims import Evaluation

EVALUATIONS: tuple[Evaluation, ...] = (
    Evaluation(
        "ma2010_fig3",
        "Fig. 3",
        "Key frames (foot strikes, Eq. 1-4) align the walking cycles of different clips.",
        "ma2010",
        inputs="ma2010_data",
        measure="motionvar.ma2010.evaluations.fig3:fig3_keyframes",
        draw="motionvar.ma2010.figures:draw_fig3",
    ),
    Evaluation(
        "ma2010_fig6",
        "Fig. 6",
        "Leave-one-out: the synthesized cycle has the held-out clip's stride (within 1.2 cm); Kriging beats RBF (MK05).",
        "ma2010",
        inputs="ma2010_walks",
        measure="motionvar.ma2010.evaluations.fig6:fig6_leave_one_out",
        draw="motionvar.ma2010.figures:draw_fig6",
        mem_mb=4000,
    ),
    Evaluation(
        "ma2010_variogram",
        "Sec. 6 (variogram)",
        "Diagnostic, no claim: the semivariograms of the Kriging residuals per joint group, with the fitted variograms.",
        "ma2010",
        inputs="ma2010_walks",
        measure="motionvar.ma2010.evaluations.variogram:variogram_fits",
        draw="motionvar.ma2010.figures:draw_variogram",
    ),
    Evaluation(
        "ma2010_fig7b",
        "Fig. 7b",
        "Strides far outside the examples are synthesized less reliably.",
        "ma2010",
        inputs="ma2010_walks_model",
        measure="motionvar.ma2010.evaluations.fig7b:fig7b_reliability",
        draw="motionvar.ma2010.figures:draw_fig7b",
    ),
    Evaluation(
        "ma2010_fig8",
        "Fig. 8a",
        "At a fixed style, variants differ as much as the examples do, at the same stride.",
        "ma2010",
        inputs="ma2010_walks_model",
        measure="motionvar.ma2010.evaluations.fig8:fig8_fixed_style",
        draw="motionvar.ma2010.figures:draw_fig8",
    ),
    Evaluation(
        "ma2010_sec7_4",
        "Sec. 7.4",
        "Ours is the most natural of six methods (foot skating, jerk, discontinuities).",
        "ma2010",
        inputs="ma2010_walks",
        measure="motionvar.ma2010.evaluations.sec7_4:sec7_4_comparison",
        draw="motionvar.ma2010.figures:draw_sec7_4",
        mem_mb=4000,
    ),
    Evaluation(
        "ma2010_sec8",
        "Sec. 8",
        "Synthesis runs faster than real time.",
        "ma2010",
        inputs="ma2010_walks_model",
        measure="motionvar.ma2010.evaluations.sec8:sec8_timing",
        draw="motionvar.ma2010.figures:draw_sec8",
    ),
)
