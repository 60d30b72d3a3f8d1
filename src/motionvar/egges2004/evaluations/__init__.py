"""The Egges et al. 2004 evaluations, one module per evaluation or figure. Each
evaluation takes the fitted :class:`~motionvar.egges2004.pipeline.IdleModel` (and the
analysed recordings where it needs them) and returns a
:class:`~motionvar.claims.EvaluationResult`; :mod:`motionvar.egges2004.figures` draws it.

- :mod:`.fig3_categories`: categories vs ground truth (Sec. 5.1, 5.3), transition graphs (Fig. 3)
- :mod:`.sec5_4_fitting`: fitted animations hit their end postures and join smoothly (Sec. 5.4.4, 7.1)
- :mod:`.sec6_repetition`: repetition of generated variations and idle motion (Sec. 6.2)
- :mod:`.fig7_8_extrema`: a PC curve over a resting segment and its extrema (Fig. 7-8)
- :mod:`.sec8_identification`: generated idle motion identifies its person (Sec. 5.6, 8)
- :mod:`.sec8_speed`: generation in real time (Sec. 8)
- :mod:`.fig10_animation`: generated idle motion per subject, for the GIF (Fig. 10)
- :mod:`.common`: the claims' paper key, per-subject random streams, the Perlin baseline
"""

from ...core.lazy import lazy_exports

# imported on first use (PEP 562): an evaluation's rule loads only its own module (the
# identification's scikit-learn and scipy.stats only for that rule)
_EXPORTS = {
    ".fig3_categories": ["category_check"],
    ".fig7_8_extrema": ["pc_extrema"],
    ".fig10_animation": ["idle_animation"],
    ".sec5_4_fitting": ["FittingParams", "fitting"],
    ".sec6_repetition": ["RepetitionParams", "repetition"],
    ".sec8_identification": ["IdentificationParams", "identification"],
    ".sec8_speed": ["SpeedParams", "speed"],
}
__getattr__, __dir__ = lazy_exports(__name__, _EXPORTS)

__all__ = [
    "FittingParams",
    "IdentificationParams",
    "RepetitionParams",
    "SpeedParams",
    "category_check",
    "fitting",
    "identification",
    "idle_animation",
    "pc_extrema",
    "repetition",
    "speed",
]
