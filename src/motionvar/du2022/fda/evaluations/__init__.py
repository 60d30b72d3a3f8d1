"""The Du 2022 ch. 3 evaluations, one module per figure or table; each returns a
:class:`motionvar.claims.EvaluationResult` drawn by :mod:`motionvar.du2022.fda.figures`.

- :mod:`.fig3_9`: :func:`evaluate_fig3_9`, B-spline RMSE against K (Sec. 3.3.3).
- :mod:`.curves`: :func:`reconstruction_curves`, the per-primitive measurements behind
  Fig. 3.10-3.11 (reconstruction errors per dimension, latent coordinates).
- :mod:`.fig3_10`: :func:`evaluate_fig3_10`, reconstruction error against dimensions.
- :mod:`.fig3_11`: :func:`evaluate_fig3_11`, separation of labels in the latent spaces.
- :mod:`.table3_1`: :func:`evaluate_table3_1`, latent dimensions per primitive.
- :mod:`.measures`: :func:`feature_error`, :func:`observation_error`,
  :func:`knn_accuracy`, :func:`latent_separation` (Sec. 3.3.5), shared by the above.
"""

from ....core.lazy import lazy_exports

# imported on first use (PEP 562): an evaluation's rule loads only its own module
_EXPORTS = {
    ".curves": ["curves_table", "reconstruction_curves"],
    ".fig3_9": ["evaluate_fig3_9"],
    ".fig3_10": ["evaluate_fig3_10"],
    ".fig3_11": ["evaluate_fig3_11"],
    ".measures": ["feature_error", "knn_accuracy", "latent_separation", "observation_error"],
    ".table3_1": ["evaluate_table3_1"],
}
__getattr__, __dir__ = lazy_exports(__name__, _EXPORTS)

__all__ = [
    "curves_table",
    "evaluate_fig3_10",
    "evaluate_fig3_11",
    "evaluate_fig3_9",
    "evaluate_table3_1",
    "feature_error",
    "knn_accuracy",
    "latent_separation",
    "observation_error",
    "reconstruction_curves",
]
