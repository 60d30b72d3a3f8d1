"""Latent variation parameters (Ma et al. 2010, Sec. 5.2, Eq. 7-9)."""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from ..core.quaternions import qdistance_sinusoidal


def joint_variation(rotations: np.ndarray) -> np.ndarray:
    """Eq. 7: delta_j(M) = sum_t ||rot_j(t+1) - rot_j(t)||_s, the sinusoidal rotational
    distance summed over consecutive frames.

    Args:
        rotations: (N, T, J, 4) local rotations of N clips on the common timeline.

    Returns:
        (N, J) delta of every joint of every clip.
    """
    rotations = np.asarray(rotations, dtype=float)
    if rotations.ndim != 4 or rotations.shape[-1] != 4 or rotations.shape[1] < 2:
        raise ValueError(f"joint_variation: rotations must be (N, T>=2, J, 4); got {rotations.shape}")
    return qdistance_sinusoidal(rotations[:, 1:], rotations[:, :-1]).sum(axis=1)


def joint_importance(delta: np.ndarray) -> np.ndarray:
    """Eq. 8: eta_j = Var[delta_j(M)] over the motions of one behaviour; (N, J) -> (J,)."""
    return np.var(np.asarray(delta, dtype=float), axis=0)


def determinative_joints(eta: np.ndarray, groups: Mapping[str, np.ndarray]) -> dict[str, int]:
    """Eq. 9: tau(I) = argmax_{j in I} eta_j for every joint group I."""
    out = {}
    for name, joints in groups.items():
        joints = np.asarray(joints, dtype=np.int64)
        if len(joints) == 0:
            raise ValueError(f"determinative_joints: joint group {name!r} is empty")
        out[name] = int(joints[np.argmax(eta[joints])])
    return out


def latent_variation(delta: np.ndarray, tau: Mapping[str, int]) -> np.ndarray:
    """xi_I = delta_tau(I)(M) for every group, in the order of ``tau``; (N, J) -> (N, G)."""
    return np.stack([np.asarray(delta)[:, j] for j in tau.values()], axis=1)
