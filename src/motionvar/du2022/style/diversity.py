"""Diversity measures of Du 2022 Sec. 5.4.5 (Tables 5.2-5.3), on clips' features
(:mod:`.features`), N clips of T frames:

- pose_SD (Eq. 5.13): sqrt(sum_i ||p_i - p_mean||^2 / (N - 1)) over every frame i of every
  clip, p_i the frame's normalised pose (feature-joint positions relative to the root's
  ground point, facing +x), in cm.
- V_SD (Eq. 5.14): sqrt(sum_i [(v_trans,i - mean)^2 + (v_r,i - mean)^2] / (N - 1)) over
  every frame, v_trans the root's ground speed (cm per frame) and v_r its rotation speed
  about the vertical (rad per frame), both on the clips' (canonical) timeline.
- step_SD (Eq. 5.15): the standard deviation over clips of the step length l_i, "the sum
  over relative root translation": the sum of the per-frame ground displacements' lengths
  (the T - 1 real differences; the last feature frame repeats the one before), in cm.
"""

from __future__ import annotations

import numpy as np

from .features import split_features


def _sd(x: np.ndarray) -> float:
    """sqrt(sum ||x_i - mean||^2 / (N - 1)) over rows of x (N, ...)."""
    x = x.reshape(len(x), -1)
    if len(x) < 2:
        raise ValueError("diversity: need at least 2 values for a standard deviation")
    dev = x - x.mean(axis=0)
    np.square(dev, out=dev)  # in place: one temporary the size of x, not two
    return float(np.sqrt(dev.sum() / (len(x) - 1)))


def pose_sd(features: np.ndarray, n_joints: int) -> float:
    """Eq. 5.13 over all frames of features (N, T, C)."""
    local, _, _ = split_features(features, n_joints)
    return _sd(local.reshape(-1, n_joints * 3))


def velocity_sd(features: np.ndarray, n_joints: int) -> float:
    """Eq. 5.14 over all frames of features (N, T, C)."""
    _, vel, yaw = split_features(features, n_joints)
    speed = np.linalg.norm(vel, axis=-1).ravel()
    yaw = yaw.ravel()
    n = len(speed)
    if n < 2:
        raise ValueError("diversity: need at least 2 frames")
    return float(np.sqrt((((speed - speed.mean()) ** 2) + ((yaw - yaw.mean()) ** 2)).sum() / (n - 1)))


def step_lengths(features: np.ndarray, n_joints: int) -> np.ndarray:
    """(N,) step length per clip: sum of the ground displacements' lengths (cm)."""
    _, vel, _ = split_features(features, n_joints)
    return np.linalg.norm(vel[:, :-1], axis=-1).sum(axis=-1)


def step_sd(features: np.ndarray, n_joints: int) -> float:
    """Eq. 5.15 over clips."""
    return _sd(step_lengths(features, n_joints))


def diversity(features: np.ndarray, n_joints: int) -> dict[str, float]:
    """pose_SD, V_SD and step_SD (Table 5.2's columns) of features (N, T, C)."""
    features = np.asarray(features, dtype=float)
    if features.ndim != 3 or features.shape[-1] != 3 * n_joints + 3:
        raise ValueError(f"diversity: features must be (N, T, {3 * n_joints + 3}); got {features.shape}")
    return {
        "pose_sd": pose_sd(features, n_joints),
        "v_sd": velocity_sd(features, n_joints),
        "step_sd": step_sd(features, n_joints),
    }
