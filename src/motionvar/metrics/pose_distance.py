"""Distance of poses to the nearest pose of a reference set (e.g. the training data): a
naturalness measure (Ma et al. 2010, Sec. 7.4: synthesized poses should stay plausible),
and the set distance between two pose sets (how different two sequences are)."""

from __future__ import annotations

import numpy as np
from scipy.spatial import cKDTree


def pose_features(positions: np.ndarray, root_index: int = 0) -> np.ndarray:
    """(T, J*3) joint positions relative to the root joint (cm): translation-invariant
    pose vectors for nearest-neighbour comparisons of clips that head the same way."""
    p = np.asarray(positions, dtype=float)
    rel = p - p[:, root_index : root_index + 1]
    return rel.reshape(len(p), -1)


def nearest_pose_distance(poses: np.ndarray, reference: np.ndarray) -> np.ndarray:
    """(T,) RMS per-joint distance (cm) of each pose to its nearest reference pose.

    Args:
        poses: (T, J*3) pose vectors (:func:`pose_features`).
        reference: (M, J*3) pose vectors of the reference set.
    """
    poses = np.asarray(poses, dtype=float)
    reference = np.asarray(reference, dtype=float)
    if poses.ndim != 2 or reference.ndim != 2 or poses.shape[1] != reference.shape[1] or poses.shape[1] % 3:
        raise ValueError(f"nearest_pose_distance: need (T, 3J) and (M, 3J); got {poses.shape}, {reference.shape}")
    d, _ = cKDTree(reference).query(poses, k=1)
    return d / np.sqrt(poses.shape[1] // 3)


def pose_set_distance(a: np.ndarray, b: np.ndarray) -> float:
    """Symmetric mean nearest-pose distance (cm, RMS per joint) between two pose sets:
    zero exactly when every pose of each set occurs in the other (identical sequences),
    and insensitive to timing. Measures how different two synthesized sequences look."""
    return float(0.5 * (nearest_pose_distance(a, b).mean() + nearest_pose_distance(b, a).mean()))
