"""Discontinuities: frames where some joint accelerates harder than a threshold (pops,
jumps between poses). The threshold is usually taken from the training data (e.g. a
multiple of the largest acceleration seen there)."""

from __future__ import annotations

import numpy as np


def peak_acceleration(positions: np.ndarray, fps: float) -> np.ndarray:
    """(T - 2,) largest joint acceleration magnitude (cm/s^2) at each interior frame."""
    p = np.asarray(positions, dtype=float)
    if p.ndim != 3 or p.shape[-1] != 3 or p.shape[0] < 3:
        raise ValueError(f"peak_acceleration: positions must be (T>=3, J, 3); got {p.shape}")
    acc = np.diff(p, n=2, axis=0) * fps**2
    return np.linalg.norm(acc, axis=-1).max(axis=1)


def count_discontinuities(positions: np.ndarray, fps: float, threshold: float) -> int:
    """Number of frames whose peak joint acceleration exceeds ``threshold`` (cm/s^2)."""
    return int(np.sum(peak_acceleration(positions, fps) > threshold))
