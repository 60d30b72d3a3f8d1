"""Personalised idle motion from a fitted model (Egges et al. 2004, Sec. 4, 5.4, 6, Fig. 9),
for the ``motionvar egges2004`` command: the person's balance shifts (the category graph
and the fitted animations of their database) with the small posture variations of Sec. 6
added in PC space, turned into joint rotations on the person's own skeleton
(:func:`.engine.generate_idle`, the engine every evaluation uses).

Idle motion has no place to go: the clip starts where the person's recordings stood.
"""

from __future__ import annotations

import numpy as np

from ..core.motion import Motion
from .engine import generate_idle
from .pipeline import IdleModel


def check_subject(model: IdleModel, subject: str) -> str:
    """``subject`` if the model has a database for it; ValueError listing those it has."""
    subject = str(subject)
    if subject not in model.databases:
        raise ValueError(
            f"subject {subject!r} has no idle database; the model has subjects {', '.join(sorted(model.databases))}"
        )
    return subject


def idle_motion(model: IdleModel, subject: str, seconds: float, seed: int = 0, variations: bool = True) -> Motion:
    """``seconds`` of idle motion of ``subject`` (``round(seconds * fps) + 1`` frames at the
    database's frame rate), drawn from ``numpy.random.default_rng(seed)``."""
    subject = check_subject(model, subject)
    if not (np.isfinite(seconds) and seconds > 0):
        raise ValueError(f"seconds must be a positive number; got {seconds}")
    db = model.databases[subject]
    return generate_idle(
        db, model.pca, model.skeletons[subject], float(seconds), np.random.default_rng(seed), variations=variations
    )
