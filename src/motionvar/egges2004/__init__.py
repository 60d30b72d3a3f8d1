"""Egges, Molet, Magnenat-Thalmann 2004: personalised real-time idle motion synthesis.

- :mod:`.pca`: posture PCA of log-mapped joint rotations plus root translation (Sec. 3.2)
- :mod:`.categories`: resting segments, posture categories, support ratio (Sec. 5.1, 5.3)
- :mod:`.category_graph`: category transition graph, T_min / T_max, shortest routes (Fig. 3, Sec. 7.1)
- :mod:`.fitting`: posture distance (Eq. 4), best-fitting animation, fitAnim (Fig. 5)
- :mod:`.database`: one person's idle database (Sec. 5.1-5.3, 5.6)
- :mod:`.balance`: synthesis of balance changes (Sec. 5.4)
- :mod:`.variations`: small posture variations (Sec. 6)
- :mod:`.integration`: idle motion between animations, blending with masks (Sec. 7)
- :mod:`.engine`: both layers together (Sec. 4, Fig. 9)
- :mod:`.baselines`: looping a recorded clip, Perlin noise on the PCs (Sec. 1, 6)
- :mod:`.pipeline`: from a dataset's idle clips to the fitted model of all subjects;
  :mod:`.storage`: that model as .npz + .json
- :mod:`.evaluations`: the paper's evaluations, one module each; :mod:`.figures` draws them
- :mod:`.settings`: config section ``egges2004`` (:class:`Egges2004Settings`), the one place its defaults are written
"""

from ..core.lazy import lazy_exports

# The names below are imported on first use (PEP 562), so that a rule that needs one module
# (the applicability table's .requirements, an evaluation) does not load all the others.
_EXPORTS = {
    ".balance": ["Event", "synthesize_balance", "time_scale"],
    ".categories": ["CategoryModel", "find_categories", "posture_speed", "static_segments", "support_ratio"],
    ".database": ["IdleDatabase", "Recording", "analyse_recording", "build_database"],
    ".engine": ["generate_idle", "generate_idle_pcs"],
    ".fitting": ["best_fitting_animation", "fit_anim", "fit_anim_part", "posture_distance"],
    ".category_graph": ["CategoryGraph"],
    ".integration": ["add_variations", "blend_motions", "idle_between", "joint_mask"],
    ".pca": ["PosturePCA", "posture_vectors"],
    ".settings": ["AnalysisSettings", "Egges2004Settings"],
    ".variations": ["VariationModel", "extrema_pairs", "find_extrema", "fit_variation_model"],
}
__getattr__, __dir__ = lazy_exports(__name__, _EXPORTS)

__all__ = [
    "AnalysisSettings",
    "CategoryGraph",
    "CategoryModel",
    "Egges2004Settings",
    "Event",
    "IdleDatabase",
    "PosturePCA",
    "Recording",
    "VariationModel",
    "add_variations",
    "analyse_recording",
    "best_fitting_animation",
    "blend_motions",
    "build_database",
    "extrema_pairs",
    "find_categories",
    "find_extrema",
    "fit_anim",
    "fit_anim_part",
    "fit_variation_model",
    "generate_idle",
    "generate_idle_pcs",
    "idle_between",
    "joint_mask",
    "posture_distance",
    "posture_speed",
    "posture_vectors",
    "static_segments",
    "support_ratio",
    "synthesize_balance",
    "time_scale",
]
