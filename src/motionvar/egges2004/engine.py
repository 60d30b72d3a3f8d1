"""The idle-motion engine: balance shifting plus small posture variations (Egges et al.
2004, Sec. 4, Fig. 9): the two layers are added in PC space and brought back to joint
rotations through the posture PCA.
"""

from __future__ import annotations

import numpy as np

from ..core.motion import Motion
from ..core.skeleton import Skeleton
from .balance import Event, synthesize_balance
from .database import IdleDatabase
from .pca import PosturePCA


def generate_idle_pcs(
    db: IdleDatabase,
    n_frames: int,
    rng: np.random.Generator,
    variations: bool = True,
    ramp: str = "linear",
) -> tuple[np.ndarray, list[Event]]:
    """(n_frames, D) PC values of personalised idle motion: balance changes (Sec. 5.4)
    with the small variations of Sec. 6 added to the leading PCs (Sec. 7.2)."""
    pcs, events = synthesize_balance(db, n_frames, rng, ramp=ramp)
    pcs = np.array(pcs, copy=True)
    if variations:
        pcs[:, db.variations.pcs] += db.variations.generate(n_frames, db.fps, rng)
    return pcs, events


def generate_idle(
    db: IdleDatabase,
    pca: PosturePCA,
    skeleton: Skeleton,
    duration_s: float,
    rng: np.random.Generator,
    variations: bool = True,
    ramp: str = "linear",
) -> Motion:
    """``duration_s`` seconds of idle motion for the person of ``db`` on ``skeleton``."""
    if not duration_s > 0:
        raise ValueError(f"generate_idle: duration must be positive, got {duration_s}")
    n = int(round(duration_s * db.fps)) + 1
    pcs, _ = generate_idle_pcs(db, n, rng, variations, ramp)
    return pca.reconstruct(pcs, skeleton, db.fps)
