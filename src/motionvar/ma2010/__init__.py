"""Ma, Xia, Hodgins et al. 2010, "Modeling Style and Variation in Human Motion".

- :mod:`.keyframes` — key-frame extraction (Eq. 1-4) and cycles.
- :mod:`.correspondence` — standard skeleton, space warping (Eq. 5-6), time warping.
- :mod:`.examples` — example clips: cycles -> aligned :class:`ClipSet` with style parameters;
  the walking cycles of a dataset (:func:`.examples.walk_cycles`, :class:`.examples.WalkCycles`).
- :mod:`.representation` — clips as feature vectors (tangent space of mean rotations).
- :mod:`.variation` — latent variation parameters (Eq. 7-9).
- :mod:`.network` — parameter propagation network (Eq. 10, Fig. 5).
- :mod:`.kriging` — variogram and universal Kriging (Sec. 6.1).
- :mod:`.svi` — style-and-variation interpolation per joint group (Eq. 11-13), the model;
  the "auto" network structure from D_l and D_u (Eq. 3, Fig. 5).
- :mod:`.postprocess` — transitions (Eq. 14-15) and footskate cleanup (Sec. 6.3).
- :mod:`.synthesis` — predicted clips -> real-time, stitched, root-solved motions.
- :mod:`.baselines` — Perlin noise, RBF, style-only Kriging, GPLVM helix, DBN (Sec. 7.4).
- :mod:`.comparison` — long sequences of every method and their measures (Sec. 7.4).
- :mod:`.evaluations` — one module per figure or section (Fig. 3, 6, 7b, 8, Sec. 7.4, 8).
- :mod:`.figures` — the evaluations' figures.
- :mod:`.settings` — :class:`.settings.Ma2010Settings`, config section ``ma2010`` (every
  option's one default).

Only the model's names are exported here (not baselines, comparison, evaluations or
figures), so that the baselines can import the model's modules without a cycle; they are
imported on first use (PEP 562), so that a rule that needs one module (the applicability
table's .requirements) does not load the model's scikit-learn and scipy.signal.
"""

from ..core.lazy import lazy_exports

_EXPORTS = {
    ".examples": ["build_clipset", "cut", "extract_cycles", "normalized_strides", "root_solver", "support_strides"],
    ".kriging": ["UniversalKriging", "Variogram", "fit_variogram"],
    ".network": ["PropagationNetwork", "choose_structure"],
    ".representation": ["ClipCodec", "ClipSet"],
    ".svi": ["ClipPrediction", "StyleVariationModel", "resolve_structure", "structure_evidence"],
    ".synthesis": ["RootSolver", "sequence_motion"],
}
__getattr__, __dir__ = lazy_exports(__name__, _EXPORTS)

__all__ = [
    "ClipCodec",
    "ClipPrediction",
    "ClipSet",
    "PropagationNetwork",
    "RootSolver",
    "StyleVariationModel",
    "UniversalKriging",
    "Variogram",
    "build_clipset",
    "choose_structure",
    "cut",
    "extract_cycles",
    "fit_variogram",
    "normalized_strides",
    "resolve_structure",
    "root_solver",
    "sequence_motion",
    "structure_evidence",
    "support_strides",
]
