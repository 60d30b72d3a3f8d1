"""Perlin-noise baseline of Ma et al. 2010, Sec. 7.4 [Per95]: noise added to joint rotations
(the noise itself: :func:`motionvar.core.noise.perlin_noise`)."""

from __future__ import annotations

import numpy as np

from ...core.noise import perlin_noise
from ...core.quaternions import qexp, qmul

__all__ = ["add_rotation_noise", "perlin_noise"]


def add_rotation_noise(
    rotations: np.ndarray,
    fps: float,
    amplitude: float,
    frequency_hz: float,
    seed: int,
    joints: np.ndarray | None = None,
    octaves: int = 2,
    persistence: float = 0.5,
) -> np.ndarray:
    """Rotations (T, J, 4) with Perlin noise on the given joints (default: all but the
    root): each joint is turned by a rotation vector of up to ``amplitude`` radians per
    axis, varying at ``frequency_hz`` [Per95]."""
    T, J = rotations.shape[:2]
    joints = np.arange(1, J) if joints is None else np.asarray(joints, dtype=np.int64)
    noise = perlin_noise(np.arange(T) / fps, len(joints) * 3, frequency_hz, seed, octaves, persistence)
    rotvec = amplitude * noise.reshape(T, len(joints), 3)
    out = rotations.copy()
    out[:, joints] = qmul(rotations[:, joints], qexp(0.5 * rotvec))
    return out
