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

from .fig3_categories import category_check
from .fig7_8_extrema import pc_extrema
from .fig10_animation import idle_animation
from .sec5_4_fitting import FittingParams, fitting
from .sec6_repetition import RepetitionParams, repetition
from .sec8_identification import IdentificationParams, identification
from .sec8_speed import SpeedParams, speed

__all__ = [
    "FittingParams", "IdentificationParams", "RepetitionParams", "SpeedParams", "category_check", "fitting",
    "identification", "idle_animation", "pc_extrema", "repetition", "speed",
]
