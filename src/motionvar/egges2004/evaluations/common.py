"""What several Egges et al. 2004 evaluations share: the paper key of their claims, one
random stream per (subject, purpose), and the Perlin-noise baseline (Sec. 6) built on a
fitted model (identification and repetition compare against it).
"""

from __future__ import annotations

import numpy as np

from ..baselines import perlin_pcs
from ..database import Recording
from ..pipeline import IdleModel

PAPER = "egges2004"


def subject_rng(seed: int, subject: str, purpose: str) -> np.random.Generator:
    """A generator per (seed, subject, purpose), so results do not depend on the order
    in which subjects are processed."""
    return np.random.default_rng([seed, sum(map(ord, purpose)), *map(ord, subject)])


def perlin_sds(model: IdleModel, recordings: dict[str, list[Recording]]) -> np.ndarray:
    """One generic amplitude per varied PC for the Perlin baseline: the RMS deviation of
    each PC from its subject's mean posture, pooled over all subjects (not personalised)."""
    n = next(iter(model.databases.values())).variations.pcs.size
    dev = [
        r.pcs[:, :n] - np.concatenate([q.pcs for q in recs]).mean(axis=0)[:n]
        for recs in recordings.values()
        for r in recs
    ]
    return np.sqrt(np.mean(np.concatenate(dev) ** 2, axis=0))


def perlin_sequence(
    model: IdleModel, recordings: list[Recording], sds: np.ndarray, frequency_hz: float, n: int, seed: int
) -> np.ndarray:
    """The Perlin baseline for one subject: their mean training posture plus Perlin noise."""
    base = np.concatenate([r.pcs for r in recordings]).mean(axis=0)
    return perlin_pcs(base, sds, frequency_hz, n, recordings[0].fps, seed)
