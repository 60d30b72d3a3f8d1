"""The evaluations of Du 2022 ch. 5, one module per table or figure: each function takes
the data (the dataset, the feature joints, the trained feature space and the VAEs/CVAEs)
and the section's :class:`~motionvar.du2022.style.settings.StyleSettings`, and returns a :class:`motionvar.claims.EvaluationResult` (table, claims, the
numbers its figure draws; drawn by :mod:`motionvar.du2022.style.figures`).

- :func:`evaluate_table5_1`: style distance D(m, s) (Eq. 5.12), Table 5.1.
- :func:`evaluate_table5_2`: diversity pose_SD, V_SD, step_SD (Eq. 5.13-5.15), Tables 5.2-5.3.
- :func:`evaluate_fig5_4`: random samples of the VAEs and CVAEs, Fig. 5.4-5.5.
"""

from .fig5_4 import evaluate_fig5_4
from .table5_1 import diagonal_minima, evaluate_table5_1, style_distance_matrix
from .table5_2 import evaluate_table5_2

__all__ = ["diagonal_minima", "evaluate_fig5_4", "evaluate_table5_1", "evaluate_table5_2", "style_distance_matrix"]
