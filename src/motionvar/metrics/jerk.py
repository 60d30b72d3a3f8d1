"""Jerk: the third time derivative of joint positions, a standard smoothness measure
(lower is smoother; Flash & Hogan 1985)."""

from __future__ import annotations

import numpy as np


def mean_jerk(positions: np.ndarray, fps: float) -> float:
    """Mean magnitude of the jerk of every joint over all frames, in cm/s^3.

    Args:
        positions: (T, J, 3) global joint positions in cm, T >= 4.
        fps: frames per second.
    """
    positions = np.asarray(positions, dtype=float)
    if positions.ndim != 3 or positions.shape[-1] != 3:
        raise ValueError(f"mean_jerk: positions must be (T, J, 3); got {positions.shape}")
    if positions.shape[0] < 4:
        raise ValueError(f"mean_jerk: need at least 4 frames; got {positions.shape[0]}")
    jerk = np.diff(positions, n=3, axis=0) * fps**3
    return float(np.linalg.norm(jerk, axis=-1).mean())
