"""Jerk: the third time derivative of joint positions, a standard smoothness measure
(lower is smoother; Flash & Hogan 1985). :func:`mean_jerk` takes the global positions (the
whole body, root path included); :func:`root_free_jerk` the positions relative to the
root joint (the pose alone: a jolt of the root, e.g. from footskate cleanup switching the
support foot, does not count)."""

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


def root_free_jerk(positions: np.ndarray, fps: float, root: int = 0) -> float:
    """Mean jerk magnitude (cm/s^3) of every joint but the root, relative to the root
    joint's position (the root's own path left out; its rotation still moves the others).

    Args:
        positions: (T, J, 3) global joint positions in cm, T >= 4, J >= 2.
        fps: frames per second.
        root: index of the root joint.
    """
    positions = np.asarray(positions, dtype=float)
    if positions.ndim != 3 or positions.shape[-1] != 3 or positions.shape[1] < 2:
        raise ValueError(f"root_free_jerk: positions must be (T, J>=2, 3); got {positions.shape}")
    if not 0 <= root < positions.shape[1]:
        raise ValueError(f"root_free_jerk: root {root} is not a joint index (J = {positions.shape[1]})")
    rel = np.delete(positions - positions[:, root : root + 1], root, axis=1)
    return mean_jerk(rel, fps)
