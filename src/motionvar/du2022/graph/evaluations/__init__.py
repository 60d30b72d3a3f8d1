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

from ....core.lazy import lazy_exports

_EXPORTS = {
    ".fig4_9": ["binned_kde", "coverage", "evaluate_fig4_9"],
    ".fig4_10": ["evaluate_fig4_10"],
    ".fig4_12": [
        "CONSTRAINT_KINDS",
        "METHODS",
        "evaluate_fig4_12",
        "search_comparison",
        "search_primitive",
        "summarize_search",
    ],
    ".sec4_6_1": ["evaluate_sec4_6_1", "motion_bytes"],
}
__getattr__, __dir__ = lazy_exports(__name__, _EXPORTS)

__all__ = [
    "CONSTRAINT_KINDS",
    "METHODS",
    "binned_kde",
    "coverage",
    "evaluate_fig4_10",
    "evaluate_fig4_12",
    "evaluate_fig4_9",
    "evaluate_sec4_6_1",
    "motion_bytes",
    "search_comparison",
    "search_primitive",
    "summarize_search",
]
