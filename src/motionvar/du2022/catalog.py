"""The evaluations of Du 2022 (:class:`motionvar.claims.Evaluation`), chapter by chapter: the one
list the workflow's rules, the applicability table (:mod:`.requirements`) and the claims are read
off. Each reads its chapter's config section (``fda``, ``graph``, ``style``)."""

from ..claims import Evaluation

EVALUATIONS: tuple[Evaluation, ...] = (
    Evaluation(
        "du2022_fig3_9", "Fig. 3.9", "The B-spline fit error falls as basis functions are added; the cut-off K.", "fda"
    ),
    Evaluation(
        "du2022_fig3_10",
        "Fig. 3.10",
        "Reconstruction error vs latent dimensions: FPCA lowest in feature space, SFPCA lowest in observation space.",
        "fda",
    ),
    Evaluation("du2022_fig3_11", "Fig. 3.11", "SFPCA's latent space separates the labelled variants best.", "fda"),
    Evaluation(
        "du2022_table3_1", "Table 3.1", "Latent dimensions needed for 1 cm observation error, per primitive.", "fda"
    ),
    Evaluation(
        "du2022_fig4_12",
        "Fig. 4.12",
        "k-means tree search halves random sampling's constraint error; median trees are close to random.",
        "graph",
    ),
    Evaluation(
        "du2022_fig4_9",
        "Fig. 4.9",
        "Samples of a primitive cover the training clips' end positions (walk leftStance ankle, pick reach hands).",
        "graph",
    ),
    Evaluation(
        "du2022_sec4_6_1",
        "Sec. 4.6.1",
        "The primitive models are far smaller than the motion data they model.",
        "graph",
    ),
    Evaluation("du2022_fig4_10", "Fig. 4.10", "A Morphable Graph walk follows a path and reaches targets.", "graph"),
    Evaluation(
        "du2022_table5_1",
        "Table 5.1",
        "Each style's samples are closest (Gram-matrix style distance) to that style's example.",
        "style",
    ),
    Evaluation(
        "du2022_table5_2",
        "Tables 5.2-5.3",
        "Samples keep the training data's diversity (pose, velocity and step SDs).",
        "style",
    ),
    Evaluation("du2022_fig5_4", "Fig. 5.4-5.5", "Random samples of the neutral and the stylised models.", "style"),
)
