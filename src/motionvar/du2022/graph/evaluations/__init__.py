"""The evaluations of Du 2022 ch. 4 (Sec. 4.6), one module per figure or section; each
``evaluate_*`` returns a :class:`motionvar.claims.EvaluationResult` (table, claims, the
numbers its figure in :mod:`motionvar.du2022.graph.figures` draws).

- :mod:`.fig4_9`: sample coverage of the training data (binned KDE, :func:`coverage`).
- :mod:`.fig4_10`: constrained generation (path following, reaching).
- :mod:`.fig4_12`: search comparison of the trees, random sampling and brute force
  (:func:`search_primitive` per primitive, :func:`evaluate_fig4_12` over all of them).
- :mod:`.sec4_6_1`: compactness (model bytes against data bytes).
- :mod:`.common`: semantic joints of a primitive's skeleton.
"""

from .fig4_9 import binned_kde, coverage, evaluate_fig4_9
from .fig4_10 import evaluate_fig4_10
from .fig4_12 import (
    CONSTRAINT_KINDS, METHODS, SearchSettings, evaluate_fig4_12, search_comparison, search_primitive, summarize_search,
)
from .sec4_6_1 import evaluate_sec4_6_1, motion_bytes

__all__ = [
    "CONSTRAINT_KINDS", "METHODS", "SearchSettings", "binned_kde", "coverage", "evaluate_fig4_10", "evaluate_fig4_12",
    "evaluate_fig4_9", "evaluate_sec4_6_1", "motion_bytes", "search_comparison", "search_primitive",
    "summarize_search",
]
