"""The Egges et al. 2004 evaluations, one module per evaluation or figure. Each
evaluation takes the fitted :class:`~motionvar.egges2004.pipeline.IdleModel` (and the
analysed recordings where it needs them) and the section's
:class:`~motionvar.egges2004.settings.Egges2004Settings`, and returns a
:class:`~motionvar.claims.EvaluationResult`; :mod:`motionvar.egges2004.figures` draws it.

- :mod:`.fig3_categories`: categories vs ground truth (Sec. 5.1, 5.3), transition graphs (Fig. 3)
- :mod:`.fitting`: fitted animations hit their end postures and join smoothly (Sec. 5.4.4, 7.1)
- :mod:`.repetition`: repetition of generated variations and idle motion (Sec. 6.2)
- :mod:`.fig7_8_extrema`: a PC curve over a resting segment and its extrema (Fig. 7-8)
- :mod:`.identification`: generated idle motion identifies its person (Sec. 5.6, 8)
- :mod:`.speed`: generation in real time (Sec. 8)
- :mod:`.fig10_animation`: generated idle motion per subject, for the GIF (Fig. 10)
- :mod:`.common`: the claims' paper key, per-subject random streams, the Perlin baseline
"""

from ...core.lazy import lazy_exports

# imported on first use (PEP 562), so that a rule loads only its own module. The four
# evaluations are named as their modules (as their rules): import them from those,
# e.g. ``from motionvar.egges2004.evaluations.fitting import fitting`` (the
# identification's scikit-learn and scipy.stats then load only for that rule).
_EXPORTS = {
    ".fig3_categories": ["category_check"],
    ".fig7_8_extrema": ["pc_extrema"],
    ".fig10_animation": ["idle_animation"],
}
__getattr__, __dir__ = lazy_exports(__name__, _EXPORTS)

__all__ = [
    "category_check",
    "idle_animation",
    "pc_extrema",
]
