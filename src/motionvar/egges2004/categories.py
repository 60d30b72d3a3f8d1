"""Resting postures and their categories (Egges et al. 2004, Sec. 5.1, 5.3).

The paper names the categories (balance on the left foot, on the right foot, on both)
but not how they were found in the recordings. Here:

1. resting (static) segments are the stretches where the smoothed posture speed in PC
   space, sqrt(sum_i w_i (dp_i/dt)^2) with the weights of Eq. 4, stays below a
   threshold for at least a minimum time; the frames between two of them are a
   posture shift (:func:`static_segments`);
   consecutive static segments whose mean postures differ by less than a few times the
   resting sway (:func:`rest_spread`) are joined: the gap was sway, not a shift
   (:func:`merge_close_rests`);
2. the mean postures of the static segments are clustered with k-means in PC space
   scaled by sqrt(w_i), so that Euclidean distance there is the distance of Eq. 4, with
   k = the most categories allowed (:func:`find_categories`);
3. a cluster is named by where its pelvis stands between the feet: the support ratio
   lambda (0 over the right ankle, 1 over the left, :func:`support_ratio`) gives
   "left" above 0.5 + margin, "right" below 0.5 - margin, else "both"; clusters with
   the same name are merged (so k-means splitting a category does no harm).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.ndimage import gaussian_filter1d
from threadpoolctl import threadpool_limits

from ..core.joint_map import JointMap
from ..core.motion import Motion
from ..io.intervals import parse_named
from ..metrics.standing import support_ratio as _support_ratio
from .fitting import posture_distance

CATEGORY_ORDER = ("left", "both", "right")
HORIZONTAL = (0, 2)  # x and z: y is up (docs/design.md, Conventions)


def support_ratio(motion: Motion, joint_map: JointMap) -> np.ndarray:
    """(T,) position of the pelvis between the ankles in the ground plane: the projection
    of hips - right ankle onto left ankle - right ankle, over its squared length."""
    sk = motion.skeleton
    hips, la, ra = (joint_map.index(sk, s) for s in ("hips", "left_ankle", "right_ankle"))
    pos = motion.positions()[..., HORIZONTAL]
    return _support_ratio(pos[:, hips], pos[:, la], pos[:, ra])


def posture_speed(pcs: np.ndarray, weights: np.ndarray, fps: float, smooth_s: float) -> np.ndarray:
    """(T,) speed of the posture in the metric of Eq. 4 (per second), after Gaussian
    smoothing of the PC curves with standard deviation ``smooth_s`` seconds."""
    k = len(weights)
    x = gaussian_filter1d(np.asarray(pcs, dtype=float)[:, :k], sigma=max(smooth_s * fps, 1e-6), axis=0, mode="nearest")
    v = np.gradient(x, axis=0) * fps if len(x) > 1 else np.zeros_like(x)
    return np.sqrt(np.sum(weights * v * v, axis=1))


def static_segments(speed: np.ndarray, fps: float, threshold: float, min_duration_s: float) -> np.ndarray:
    """(n, 2) [start, stop) frame intervals where ``speed`` < ``threshold`` for at least
    ``min_duration_s`` seconds, in time order."""
    still = np.concatenate([[False], np.asarray(speed) < threshold, [False]])
    edges = np.flatnonzero(np.diff(still.astype(np.int8)))
    runs = edges.reshape(-1, 2)
    return runs[(runs[:, 1] - runs[:, 0]) >= max(1, int(round(min_duration_s * fps)))]


@dataclass(frozen=True)
class CategoryModel:
    """Named resting-posture categories: k-means centroids (in sqrt(w)-scaled PC space)
    and the category index of each centroid."""

    names: tuple[str, ...]
    centroids: np.ndarray
    centroid_category: np.ndarray
    scale: np.ndarray

    def assign(self, postures: np.ndarray) -> np.ndarray:
        """Category index of postures (n, D): that of the nearest centroid (Eq. 4)."""
        x = np.asarray(postures)[..., : self.scale.size] * self.scale
        d = np.sum((x[..., None, :] - self.centroids) ** 2, axis=-1)
        return self.centroid_category[np.argmin(d, axis=-1)]


def name_by_support(lam: float, margin: float) -> str:
    """'left', 'right' or 'both' from a support ratio (see the module docstring)."""
    if lam > 0.5 + margin:
        return "left"
    if lam < 0.5 - margin:
        return "right"
    return "both"


def find_categories(
    postures: np.ndarray,
    support: np.ndarray,
    weights: np.ndarray,
    max_categories: int,
    margin: float,
    seed: int,
) -> tuple[CategoryModel, np.ndarray]:
    """Cluster the mean postures (n, D) of static segments into categories.

    k-means with k = ``max_categories`` (fewer when there are fewer segments); each
    cluster is named by the mean support ratio of its members, and clusters with the same
    name are merged, so a category split by k-means is joined again. Returns the model
    and each segment's category index.
    """
    from sklearn.cluster import KMeans  # only fitting needs scikit-learn (a slow import)

    postures = np.asarray(postures, dtype=float)
    support = np.asarray(support, dtype=float)
    if len(postures) == 0:
        raise ValueError("find_categories: no static segments to cluster")
    if max_categories < 1:
        raise ValueError(f"find_categories: max_categories must be >= 1, got {max_categories}")
    scale = np.sqrt(np.asarray(weights, dtype=float))
    x = postures[:, : scale.size] * scale
    with threadpool_limits(1):  # tens of points: threads only cost start-up
        km = KMeans(n_clusters=min(max_categories, len(x)), n_init=10, random_state=seed).fit(x)
    labels, centres = km.labels_, km.cluster_centers_
    cluster_names = [
        name_by_support(float(support[labels == c].mean()), margin) if np.any(labels == c) else ""
        for c in range(len(centres))
    ]
    names = tuple(n for n in CATEGORY_ORDER if n in cluster_names)
    used = np.array([n != "" for n in cluster_names])
    centroid_category = np.array([names.index(n) for n in np.array(cluster_names)[used]], dtype=np.int64)
    model = CategoryModel(names, centres[used], centroid_category, scale)
    return model, model.centroid_category[np.cumsum(used)[labels] - 1]


def merge_close_rests(segments: np.ndarray, pcs: np.ndarray, weights: np.ndarray, min_shift: float) -> np.ndarray:
    """Join consecutive static segments whose mean postures lie closer than ``min_shift``
    (Eq. 4 distance, square-rooted): the gap between them was sway, not a balance shift.
    The merged segment spans the gap."""
    out = [list(segments[0])] if len(segments) else []
    for a, b in segments[1:]:
        pa, pb = out[-1]
        d = posture_distance(pcs[pa:pb].mean(axis=0), pcs[a:b].mean(axis=0), weights)
        if np.sqrt(d) < min_shift:
            out[-1][1] = b
        else:
            out.append([a, b])
    return np.array(out, dtype=np.int64).reshape(-1, 2)


def rest_spread(segments: np.ndarray, pcs: np.ndarray, weights: np.ndarray) -> float:
    """RMS distance (Eq. 4, square-rooted) of resting frames from their segment's mean:
    the size of the small variations (sway) while resting."""
    d = [posture_distance(pcs[a:b], pcs[a:b].mean(axis=0), weights) for a, b in segments]
    return float(np.sqrt(np.mean(np.concatenate(d)))) if d else 0.0


def parse_postures(spec: str, clip: str = "clip") -> list[tuple[str, int, int]]:
    """Ground-truth resting postures "left:0:480;both:480:900" -> [(name, start, stop)]
    (:func:`motionvar.io.intervals.parse_named`)."""
    return parse_named(spec, f"{clip}: idle_postures")


def frame_labels(intervals: list[tuple[str, int, int]], n_frames: int) -> np.ndarray:
    """(T,) name per frame from intervals, '' where none applies."""
    labels = np.full(n_frames, "", dtype=object)
    for name, start, stop in intervals:
        labels[max(start, 0) : min(stop, n_frames)] = name
    return labels


def segment_agreement(segments: np.ndarray, predicted: list[str], truth: np.ndarray) -> tuple[float, float]:
    """Agreement of named static segments with per-frame ground-truth names:
    (share of segments whose name is the majority true name over the segment, adjusted
    Rand index between predicted names and those majority names)."""
    from sklearn.metrics import adjusted_rand_score  # scikit-learn is a slow import

    majority = []
    for start, stop in segments:
        vals, counts = np.unique(truth[start:stop].astype(str), return_counts=True)
        majority.append(str(vals[np.argmax(counts)]))
    if not majority:
        return float("nan"), float("nan")
    acc = float(np.mean([p == m for p, m in zip(predicted, majority)]))
    return acc, float(adjusted_rand_score(majority, predicted))
