"""Measures of Du 2022 Sec. 4.6: search comparison (Fig. 4.12), sample coverage of the
training data (Fig. 4.9) and compactness (Sec. 4.6.1).
"""

from __future__ import annotations

import time
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import pandas as pd
from scipy.ndimage import gaussian_filter

from .constraints import Objective, random_constraints
from .primitive import MotionPrimitive
from .trees import KeyFramePositionIndex, SpacePartitioningTree, random_search

CONSTRAINT_KINDS = ("position", "orientation", "pose")
METHODS = ("kmeans", "gmm", "median", "random", "brute_force")


@dataclass(frozen=True)
class SearchSettings:
    """Fig. 4.12 settings: tree samples, queries per constraint kind, beam, leaf size,
    random-sampling size, seed."""

    n_samples: int = 10000
    n_queries: int = 1000
    beam: int = 2
    leaf_size: int = 16
    n_random: int = 100
    seed: int = 0


def search_comparison(primitive: MotionPrimitive, position_joint: int, pose_joints: Sequence[int],
                      settings: SearchSettings | None = None,
                      kinds: Sequence[str] = CONSTRAINT_KINDS) -> tuple[pd.DataFrame, pd.DataFrame]:
    """Fig. 4.12 for one primitive: random constraints of each kind at the last canonical
    frame (Eq. 4.2), met by fresh GMM samples; the best sample found by each tree, by
    random sampling and by brute force over the tree's samples.

    Returns (per-query table: kind, query, method, error, n_evals, time_s;
    per-tree table: method, n_nodes, depth, build_s).
    """
    st = settings or SearchSettings()
    rng = np.random.default_rng(st.seed)
    samples = primitive.sample(st.n_samples, rng)
    trees, tree_rows = {}, []
    for kind in ("kmeans", "gmm", "median"):
        t0 = time.perf_counter()
        trees[kind] = SpacePartitioningTree(samples, kind, leaf_size=st.leaf_size, seed=st.seed)
        tree_rows.append(dict(method=kind, n_nodes=trees[kind].n_nodes, depth=trees[kind].depth,
                              build_s=time.perf_counter() - t0))
    last = primitive.n_frames - 1
    joints = [int(position_joint)] + [int(j) for j in pose_joints if int(j) != int(position_joint)]
    t0 = time.perf_counter()
    exact = KeyFramePositionIndex(primitive, samples, [last], joints)
    tree_rows.append(dict(method="brute_force", n_nodes=len(samples), depth=0, build_s=time.perf_counter() - t0))
    rows = []
    for kind in kinds:
        cons_joints = [int(position_joint)] if kind != "pose" else [int(j) for j in pose_joints]
        queries = random_constraints(primitive, kind, st.n_queries, cons_joints, last, rng)
        for q, c in enumerate(queries):
            for name, tree in trees.items():
                t0 = time.perf_counter()
                r = tree.search(Objective(primitive, [c]), st.beam)
                rows.append((kind, q, name, r.error, r.n_evals, time.perf_counter() - t0))
            t0 = time.perf_counter()
            r = random_search(primitive, Objective(primitive, [c]), st.n_random, rng)
            rows.append((kind, q, "random", r.error, r.n_evals, time.perf_counter() - t0))
            t0 = time.perf_counter()
            r = exact.search([c])  # exact: the same best sample as evaluating all of them
            rows.append((kind, q, "brute_force", r.error, len(samples), time.perf_counter() - t0))
    table = pd.DataFrame(rows, columns=["kind", "query", "method", "error", "n_evals", "time_s"])
    return table, pd.DataFrame(tree_rows)


def summarize_search(table: pd.DataFrame) -> pd.DataFrame:
    """Median, quartiles, SD of the error and mean evaluations per (primitive, kind, method)."""
    keys = [k for k in ("primitive", "kind", "method") if k in table.columns]
    g = table.groupby(keys, sort=False)
    out = g["error"].agg(median="median", q25=lambda x: x.quantile(0.25), q75=lambda x: x.quantile(0.75),
                         sd="std", mean="mean")
    out["mean_evals"] = g["n_evals"].mean()
    out["share_under_120_evals"] = g["n_evals"].apply(lambda x: float(np.mean(x < 120)))
    out["mean_time_ms"] = 1e3 * g["time_s"].mean()
    return out.reset_index()


# ---- Fig. 4.9: coverage of the training data by the samples -----------------------------
def binned_kde(points: np.ndarray, bounds: np.ndarray, n_grid: int = 128,
               bandwidth: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """2-D kernel density on a grid (as R's MASS::kde2d, used for Fig. 4.9), by binning
    the points and smoothing with a Gaussian of Scott's bandwidth (per axis, in grid
    cells). Returns (density (n_grid, n_grid) indexed [x, y], x centres, y centres)."""
    p = np.asarray(points, dtype=float)
    if p.ndim != 2 or p.shape[1] != 2 or len(p) < 2:
        raise ValueError(f"binned_kde: points must be (N >= 2, 2); got {p.shape}")
    (x0, x1), (y0, y1) = bounds
    H, xe, ye = np.histogram2d(p[:, 0], p[:, 1], bins=n_grid, range=[[x0, x1], [y0, y1]])
    if bandwidth is None:
        bandwidth = p.std(axis=0, ddof=1) * len(p) ** (-1.0 / 6.0)  # Scott's rule, d = 2
    cell = np.array([(x1 - x0) / n_grid, (y1 - y0) / n_grid])
    sigma = np.maximum(np.asarray(bandwidth) / cell, 0.5)
    dens = gaussian_filter(H, sigma=sigma, mode="constant")
    dens /= max(dens.sum() * cell.prod(), 1e-300)
    return dens, 0.5 * (xe[1:] + xe[:-1]), 0.5 * (ye[1:] + ye[:-1])


def _lookup(dens: np.ndarray, xc: np.ndarray, yc: np.ndarray, pts: np.ndarray) -> np.ndarray:
    dx, dy = xc[1] - xc[0], yc[1] - yc[0]
    i = np.floor((pts[:, 0] - (xc[0] - dx / 2)) / dx).astype(int)
    j = np.floor((pts[:, 1] - (yc[0] - dy / 2)) / dy).astype(int)
    inside = (i >= 0) & (i < len(xc)) & (j >= 0) & (j < len(yc))
    out = np.zeros(len(pts))
    out[inside] = dens[i[inside], j[inside]]
    return out


def coverage(samples_2d: np.ndarray, training_2d: np.ndarray, level: float = 0.95, n_grid: int = 128,
             margin: float = 0.25) -> tuple[float, float, dict]:
    """Share of training points inside the samples' ``level`` highest-density region
    (the region holding ``level`` of the samples, by the binned KDE). Returns
    (coverage, density threshold, plotting data: density, centres, bounds)."""
    s, t = np.asarray(samples_2d, float), np.asarray(training_2d, float)
    both = np.concatenate([s, t])
    lo, hi = both.min(axis=0), both.max(axis=0)
    pad = margin * np.maximum(hi - lo, 1e-6)
    bounds = np.stack([lo - pad, hi + pad], axis=1)
    dens, xc, yc = binned_kde(s, bounds, n_grid)
    threshold = float(np.quantile(_lookup(dens, xc, yc, s), 1.0 - level))
    cov = float(np.mean(_lookup(dens, xc, yc, t) >= threshold))
    return cov, threshold, dict(density=dens, x=xc, y=yc, bounds=bounds)


# ---- Sec. 4.6.1: compactness ----------------------------------------------------------------
def motion_bytes(n_frames: int, n_joints: int, itemsize: int = 8) -> int:
    """Bytes of a clip as raw arrays: root position (3) + one quaternion per joint per frame."""
    return int(n_frames) * (3 + 4 * int(n_joints)) * int(itemsize)
