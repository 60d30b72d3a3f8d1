"""Continuous small posture variations (Egges et al. 2004, Sec. 6, Fig. 7-8).

Per principal component: remove each resting segment's mean (Sec. 6.1), reduce the
curve to its maxima and minima with an error epsilon, describe each extremum by its
(distance in ms to the previous extremum, PC value) pair, cluster the pairs with
k-means and count the transitions between the clusters of consecutive pairs (Sec. 6.2).
New curves follow the seven-step algorithm of Sec. 6.2, independently per PC.

Choices the paper leaves open (stated here, not tuned): epsilon is given relative to
the standard deviation of the PC's mean-removed values; the pairs are standardised
(z-scores) before k-means so that milliseconds and PC units weigh alike; generated key
frames are joined by monotone cubic (PCHIP) interpolation, which keeps every generated
extremum an extremum (zero slope there); a cluster without observed successors
continues with the overall cluster frequencies.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from scipy.interpolate import PchipInterpolator
from threadpoolctl import threadpool_limits


def remove_segment_mean(segment: np.ndarray) -> np.ndarray:
    """Sec. 6.1: subtract the mean of each PC over the segment (T, n) -> (T, n)."""
    segment = np.asarray(segment, dtype=float)
    return segment - segment.mean(axis=0, keepdims=True)


def find_extrema(x: np.ndarray, eps: float) -> tuple[np.ndarray, np.ndarray]:
    """Maxima and minima of a curve with error ``eps`` (Sec. 6.2): an extremum counts once
    the curve has moved back from it by more than ``eps``. Returns (frame indices, True
    for a maximum), alternating, in time order.

    Hysteresis peak detection; it only needs the curve's turning points (between them the
    curve is monotone), which are found vectorised, so the loop runs over turning points.
    The first frame is a boundary, not an extremum, and is never reported.
    """
    x = np.asarray(x, dtype=float)
    if x.ndim != 1:
        raise ValueError(f"find_extrema: need a 1-D curve, got shape {x.shape}")
    if not eps > 0:
        raise ValueError(f"find_extrema: eps must be positive, got {eps}")
    d = np.diff(x)
    nz = np.flatnonzero(d != 0)
    if nz.size == 0:
        return np.zeros(0, dtype=np.int64), np.zeros(0, dtype=bool)
    turns = nz[np.flatnonzero(np.sign(d[nz][1:]) != np.sign(d[nz][:-1]))] + 1
    cand = np.concatenate([[0], turns, [len(x) - 1]])
    idx, kind = [], []
    mx_i = mn_i = int(cand[0])
    state = 0  # 0: undecided, 1: looking for a maximum, -1: looking for a minimum
    for i in cand[1:]:
        v = x[i]
        if v > x[mx_i]:
            mx_i = int(i)
        if v < x[mn_i]:
            mn_i = int(i)
        if state != -1 and v < x[mx_i] - eps:  # fallen back from the maximum by eps
            idx.append(mx_i)
            kind.append(True)
            mn_i, state = int(i), -1
        elif state != 1 and v > x[mn_i] + eps:  # risen from the minimum by eps
            idx.append(mn_i)
            kind.append(False)
            mx_i, state = int(i), 1
    idx, kind = np.array(idx, dtype=np.int64), np.array(kind, dtype=bool)
    return idx[idx > 0], kind[idx > 0]


def extrema_pairs(x: np.ndarray, fps: float, eps: float) -> np.ndarray:
    """(n, 2) (distance in ms from the previous extremum, PC value) of every extremum of
    ``x`` but the first (Fig. 8)."""
    idx, _ = find_extrema(x, eps)
    if idx.size < 2:
        return np.zeros((0, 2))
    return np.stack([np.diff(idx) * 1000.0 / fps, np.asarray(x)[idx[1:]]], axis=1)


@dataclass(frozen=True)
class VariationModel:
    """Per-PC cluster models of (distance, value) pairs, padded to common sizes.

    Attributes:
        pcs: (P,) indices of the modelled principal components.
        points: (P, K, M, 2) the pairs of each cluster (distance ms, value), padded.
        counts: (P, K) pairs per cluster (0 for padding).
        transition: (P, K, K) probability transition matrices between clusters.
        n_clusters: (P,) clusters per PC (0 when a PC had too few extrema).
    """

    pcs: np.ndarray
    points: np.ndarray
    counts: np.ndarray
    transition: np.ndarray
    n_clusters: np.ndarray

    def generate(self, n_frames: int, fps: float, rng: np.random.Generator) -> np.ndarray:
        """(n_frames, P) variation curves by the seven steps of Sec. 6.2, one chain per PC
        (vectorised over PCs; the loop runs over generated key frames)."""
        P = len(self.pcs)
        out = np.zeros((n_frames, P))
        live = np.flatnonzero(self.n_clusters > 0)
        if n_frames < 2 or live.size == 0:
            return out
        end = (n_frames - 1) / fps
        cum = np.cumsum(self.transition[live], axis=-1)
        rows = np.arange(live.size)
        t = np.zeros(live.size)
        times, values = [t.copy()], [np.zeros(live.size)]  # 1. neutral position at t = 0
        c = np.floor(rng.random(live.size) * self.n_clusters[live]).astype(np.int64)  # 2. a random cluster
        while t.min() < end:
            m = np.floor(rng.random(live.size) * self.counts[live, c]).astype(np.int64)  # 3./6. a point in it
            pt = self.points[live, c, m]
            t = t + pt[:, 0] / 1000.0  # 4. key frame at t + distance with the point's value
            times.append(t.copy())
            values.append(pt[:, 1])
            u = rng.random(live.size)  # 5. next cluster from the transition matrix
            c = np.minimum((cum[rows, c] < u[:, None]).sum(axis=1), self.n_clusters[live] - 1)
        times, values = np.stack(times, axis=1), np.stack(values, axis=1)
        frame_t = np.arange(n_frames) / fps
        for j, p in enumerate(live):
            out[:, p] = PchipInterpolator(times[j], values[j])(frame_t)
        return out


def fit_variation_model(
    segments: Sequence[np.ndarray],
    pcs: Sequence[int],
    fps: float,
    eps_sd: float,
    n_clusters: int,
    seed: int,
) -> VariationModel:
    """Fit the Sec. 6 model on resting segments (each (T_i, D) PC values).

    ``eps_sd``: extremum error as a multiple of the PC's standard deviation after mean
    removal; ``n_clusters``: k of k-means per PC (fewer when a PC has fewer pairs).
    """
    from sklearn.cluster import KMeans  # only fitting needs scikit-learn (a slow import)

    pcs = np.asarray(pcs, dtype=np.int64)
    if n_clusters < 1:
        raise ValueError(f"n_clusters must be >= 1, got {n_clusters}")
    centred = [remove_segment_mean(np.asarray(s)[:, pcs]) for s in segments if len(s) > 1]
    if not centred:
        raise ValueError("fit_variation_model: no resting segment with two or more frames")
    sd = np.sqrt(np.mean(np.concatenate(centred) ** 2, axis=0))
    per_pc = []
    for j in range(pcs.size):
        flat = sd[j] <= 1e-9 * sd.max()  # a PC without variance in the rests gets no model
        pairs = [np.zeros((0, 2)) if flat else extrema_pairs(seg[:, j], fps, eps_sd * sd[j]) for seg in centred]
        n_pairs = [len(p) for p in pairs]
        allp = np.concatenate(pairs)
        k = min(n_clusters, len(allp))
        if k == 0:
            per_pc.append((allp, np.zeros(0, np.int64), np.zeros((0, 0)), 0))
            continue
        z = (allp - allp.mean(axis=0)) / np.where(allp.std(axis=0) > 0, allp.std(axis=0), 1.0)
        if k > 1:  # duplicate pairs may leave clusters empty: renumber the used ones
            with threadpool_limits(1):  # hundreds of 2-D points: threads only cost start-up
                labels = KMeans(n_clusters=k, n_init=10, random_state=seed).fit_predict(z)
            labels = np.unique(labels, return_inverse=True)[1]
            k = int(labels.max()) + 1
        else:
            labels = np.zeros(len(allp), np.int64)
        counts = np.zeros((k, k))
        for lab in np.split(labels, np.cumsum(n_pairs)[:-1]):
            np.add.at(counts, (lab[:-1], lab[1:]), 1)
        freq = np.bincount(labels, minlength=k) / len(labels)
        rows = counts.sum(axis=1, keepdims=True)
        trans = np.where(rows > 0, counts / np.maximum(rows, 1), freq)
        per_pc.append((allp, labels, trans, k))
    K = max(1, max(p[3] for p in per_pc))
    M = max(1, max((np.bincount(p[1]).max() if p[3] else 0) for p in per_pc))
    points = np.zeros((pcs.size, K, M, 2))
    counts = np.zeros((pcs.size, K), dtype=np.int64)
    transition = np.zeros((pcs.size, K, K))
    for j, (allp, labels, trans, k) in enumerate(per_pc):
        for c in range(k):
            members = allp[labels == c]
            points[j, c, : len(members)] = members
            counts[j, c] = len(members)
        transition[j, :k, :k] = trans
    return VariationModel(pcs, points, counts, transition, np.array([p[3] for p in per_pc], dtype=np.int64))
