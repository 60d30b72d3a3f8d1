"""Automatic key-frame extraction and segmentation into cycles (Ma et al. 2010, Sec. 4.1).

Eq. 1-2: the joint positions of the lower body (legs) and of the upper body (the rest)
are stacked over frames and reduced by PCA; row t of the score matrix is P*(t).
Eq. 3: D = sqrt(Tr(P* P*')) measures how much each part moves.
Eq. 4: S_M(t) = ||P*(t)|| of the part that moves more; its local minima and maxima are
the key frames (found with a prominence test in the spirit of [IST01]).

Reading of Eq. 1-2 (the paper leaves it open): positions are taken relative to the root
(global positions would make S_M(t) follow the distance walked), and PCA runs over the
frames of one part's flattened pose vector, so S_M(t) is the distance of the part's
pose from its mean pose and D the square root of its total variance times T. With this
reading D_l >= D_u for walking and running (the legs move most) and D_l < D_u for
arm-driven behaviours, as Sec. 4.1 and 5.3 describe.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class KeyframeSignal:
    """S_M(t) of one motion (Eq. 4) and the importance of both parts (Eq. 3)."""

    signal: np.ndarray  # (T,) S_M(t)
    d_lower: float  # D_l
    d_upper: float  # D_u

    @property
    def part(self) -> str:
        """'lower' when D_l >= D_u (Eq. 4's first case), else 'upper'."""
        return "lower" if self.d_lower >= self.d_upper else "upper"


def part_scores(positions: np.ndarray, joints: np.ndarray, n_components: int | None = None) -> np.ndarray:
    """P*(t) for one part (Eq. 1-2): PCA scores (T, k) of the part's root-relative positions.

    Args:
        positions: (T, J, 3) global joint positions; joint 0 is the root.
        joints: indices of the part's joints.
        n_components: principal components kept (None: all, then ||P*(t)|| is the
            distance from the mean pose).
    """
    from sklearn.decomposition import PCA  # here: the model's users never find key frames

    rel = positions[:, joints] - positions[:, :1]
    flat = rel.reshape(len(positions), -1)
    k = min(flat.shape) if n_components is None else min(n_components, *flat.shape)
    return PCA(n_components=k, svd_solver="full").fit_transform(flat)


def keyframe_signal(
    positions: np.ndarray, lower: np.ndarray, upper: np.ndarray, n_components: int | None = None
) -> KeyframeSignal:
    """S_M(t), D_l and D_u of one motion (Eq. 1-4).

    Args:
        positions: (T, J, 3) global joint positions (T >= 3); joint 0 is the root.
        lower: joint indices of the lower body (the legs).
        upper: joint indices of the upper body (the rest of the body).
        n_components: principal components kept per part (None: all).
    """
    positions = np.asarray(positions, dtype=float)
    if positions.ndim != 3 or positions.shape[-1] != 3 or positions.shape[0] < 3:
        raise ValueError(f"keyframe_signal: positions must be (T>=3, J, 3); got {positions.shape}")
    p_l = part_scores(positions, np.asarray(lower), n_components)
    p_u = part_scores(positions, np.asarray(upper), n_components)
    d_l = float(np.sqrt(np.sum(p_l**2)))  # Eq. 3: sqrt(Tr(P_l* P_l*'))
    d_u = float(np.sqrt(np.sum(p_u**2)))
    chosen = p_l if d_l >= d_u else p_u
    return KeyframeSignal(signal=np.linalg.norm(chosen, axis=1), d_lower=d_l, d_upper=d_u)  # Eq. 4


def find_extrema(signal: np.ndarray, min_prominence: float, min_distance: int = 1) -> tuple[np.ndarray, np.ndarray]:
    """Key frames: alternating local maxima and minima of S_M(t) (Sec. 4.1, Fig. 3).

    Args:
        signal: (T,) S_M(t).
        min_prominence: an extremum must stand out by this fraction of the signal's range.
        min_distance: frames between two extrema of the same kind, at least.

    Returns:
        (frames, kinds): increasing frame indices and +1 (maximum) / -1 (minimum); two
        neighbours of the same kind are merged into the more extreme one.
    """
    from scipy.signal import find_peaks  # here: the model's users never find key frames

    s = np.asarray(signal, dtype=float)
    span = float(np.ptp(s)) if len(s) else 0.0
    if span <= 0:
        return np.zeros(0, dtype=np.int64), np.zeros(0, dtype=np.int64)
    kw = dict(prominence=min_prominence * span, distance=max(int(min_distance), 1))
    maxima, _ = find_peaks(s, **kw)
    minima, _ = find_peaks(-s, **kw)
    frames = np.concatenate([maxima, minima])
    kinds = np.concatenate([np.ones(len(maxima), np.int64), -np.ones(len(minima), np.int64)])
    order = np.argsort(frames, kind="stable")
    frames, kinds = frames[order], kinds[order]
    keep_f: list[int] = []
    keep_k: list[int] = []
    for f, k in zip(frames.tolist(), kinds.tolist()):  # loop over a handful of extrema, not frames
        if keep_k and keep_k[-1] == k:
            if k * s[f] > k * s[keep_f[-1]]:
                keep_f[-1] = f
            continue
        keep_f.append(f)
        keep_k.append(k)
    return np.array(keep_f, dtype=np.int64), np.array(keep_k, dtype=np.int64)


@dataclass(frozen=True)
class Cycle:
    """One gait cycle cut out of a motion: frames [start, stop] (inclusive) and its key
    frames relative to ``start`` (maximum, minimum, maximum, minimum, maximum)."""

    start: int
    stop: int
    key_frames: np.ndarray


def segment_cycles(
    frames: np.ndarray,
    kinds: np.ndarray,
    left_foot: np.ndarray,
    right_foot: np.ndarray,
    heading: np.ndarray,
    max_length_ratio: float = 1.5,
) -> list[Cycle]:
    """Cut a locomotion into cycles at the key frames (Sec. 4.2: "divide each motion into
    several clips").

    A cycle starts at a maximum of S_M(t) where the left foot is ahead (the left support
    phase begins), runs through the next maximum (the right support phase begins) and
    ends at the maximum after that; it must hold exactly five alternating key frames.
    The maximum in the middle must have the right foot ahead. Cycles longer or shorter
    than ``max_length_ratio`` times the median cycle are dropped (starts, stops, pauses).

    Args:
        frames, kinds: key frames from :func:`find_extrema`.
        left_foot, right_foot: (T, 3) positions of a joint of each foot (e.g. the ankles).
        heading: (3,) horizontal walking direction.
    """
    heading = np.asarray(heading, dtype=float)
    left_ahead = (left_foot[frames] - right_foot[frames]) @ heading > 0
    cycles = []
    for i in range(len(frames) - 4):  # loop over key frames
        if not (kinds[i] == 1 and left_ahead[i]):
            continue
        if not np.array_equal(kinds[i : i + 5], [1, -1, 1, -1, 1]) or left_ahead[i + 2] or not left_ahead[i + 4]:
            continue
        keys = frames[i : i + 5]
        cycles.append(Cycle(start=int(keys[0]), stop=int(keys[-1]), key_frames=keys - keys[0]))
    if cycles:
        med = np.median([c.stop - c.start for c in cycles])
        cycles = [c for c in cycles if med / max_length_ratio <= c.stop - c.start <= max_length_ratio * med]
    return cycles
