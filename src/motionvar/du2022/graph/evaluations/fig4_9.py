"""Du 2022 Fig. 4.9: do random motions sampled from the primitives cover the variation
of the training data? End-effector positions at the last frame of sampled motions of
walk leftStance (left foot) and pick reach (both hands) against the training clips, as
2-D kernel densities in three projections, with a coverage number per projection both
ways: the training points inside the samples' ``level`` region (the samples reach the
training's variation) and the samples inside the training points' ``level`` region (they do
not spread beyond it). A region is the highest-density region holding ``level`` of a binned
kernel density's mass, as a probability contour of a kde2d plot.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np
import pandas as pd
from scipy.ndimage import gaussian_filter

from ....claims import EvaluationResult, judge_claims
from ....core.joint_map import JointMap
from ....io.dataset import MotionDataset
from ...claims import CLAIMS
from ..primitive import MotionPrimitive, primitive_clips
from ..settings import GraphSettings
from .common import semantic_index

VIEWS = (("top (x, z)", 0, 2), ("side (x, y)", 0, 1), ("front (z, y)", 2, 1))
CASES = (("walk_leftStance", "left_ankle"), ("pick_reach", "left_hand"), ("pick_reach", "right_hand"))
SAMPLE_CHUNK = 10000  # latent vectors per key-frame pose evaluation (memory)


def binned_kde(
    points: np.ndarray, bounds: np.ndarray, n_grid: int, bandwidth: np.ndarray | None = None
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
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


def hdr_threshold(density: np.ndarray, x: np.ndarray, y: np.ndarray, level: float) -> float:
    """The density value whose superlevel set holds ``level`` of the mass of a gridded density
    (cell centres ``x``, ``y``): the boundary of its ``level`` highest-density region."""
    d = np.sort(np.asarray(density, float).ravel())[::-1]
    mass = np.cumsum(d) * (x[1] - x[0]) * (y[1] - y[0])
    return float(d[min(int(np.searchsorted(mass, level * mass[-1])), len(d) - 1)])


def _grid_bounds(a: np.ndarray, b: np.ndarray, margin: float) -> np.ndarray:
    both = np.concatenate([a, b])
    lo, hi = both.min(axis=0), both.max(axis=0)
    pad = margin * np.maximum(hi - lo, 1e-6)
    return np.stack([lo - pad, hi + pad], axis=1)


def _share_inside(region_points: np.ndarray, points: np.ndarray, bounds: np.ndarray, level: float, n_grid: int):
    """Share of ``points`` inside the ``level`` highest-density region of ``region_points``'
    binned KDE; with the region's density threshold and the density grid."""
    dens, xc, yc = binned_kde(region_points, bounds, n_grid)
    threshold = hdr_threshold(dens, xc, yc, level)
    return float(np.mean(_lookup(dens, xc, yc, points) >= threshold)), threshold, (dens, xc, yc)


def coverage(
    samples_2d: np.ndarray, training_2d: np.ndarray, level: float, n_grid: int, margin: float = 0.25
) -> tuple[float, float, dict]:
    """Share of training points inside the samples' ``level`` highest-density region (by
    the binned KDE, :func:`hdr_threshold`). Returns (coverage, density threshold, plotting
    data: density, centres, bounds)."""
    s, t = np.asarray(samples_2d, float), np.asarray(training_2d, float)
    bounds = _grid_bounds(s, t, margin)
    cov, threshold, (dens, xc, yc) = _share_inside(s, t, bounds, level, n_grid)
    return cov, threshold, dict(density=dens, x=xc, y=yc, bounds=bounds)


def coverage_both_ways(
    samples_2d: np.ndarray, training_2d: np.ndarray, level: float, n_grid: int, margin: float = 0.25
) -> tuple[float, float, dict]:
    """:func:`coverage` and the share of the samples inside the training points' ``level``
    highest-density region (on the same grid). Returns (coverage, samples inside, plotting
    data: :func:`coverage`'s with ``threshold``, ``training_density`` and
    ``training_threshold``)."""
    s, t = np.asarray(samples_2d, float), np.asarray(training_2d, float)
    cov, threshold, data = coverage(s, t, level, n_grid, margin)
    inside, t_threshold, (t_dens, _, _) = _share_inside(t, s, data["bounds"], level, n_grid)
    return cov, inside, dict(data, threshold=threshold, training_density=t_dens, training_threshold=t_threshold)


def fig4_9_measurements(table: pd.DataFrame, level: float, threshold: float, n_samples: int) -> dict[str, Any]:
    """What the Fig. 4.9 claim is judged on: the coverage both ways per primitive, joint and
    projection (rows of ``table``: ``coverage``, ``samples_inside``), the density ``level``, the
    coverage ``threshold`` (``diversity.coverage_threshold``) and the number of sampled motions."""
    return {
        "coverage": [
            {
                "primitive": r.primitive,
                "joint": r.joint,
                "view": r.view,
                "coverage": float(r.coverage),
                "samples_inside": float(r.samples_inside),
            }
            for r in table.itertuples()
        ],
        "level": level,
        "coverage_threshold": threshold,
        "n_samples": int(n_samples),
    }


def evaluate_fig4_9(
    models: Mapping[str, MotionPrimitive],
    dataset: MotionDataset,
    joint_map: JointMap,
    settings: GraphSettings,
    source: str = "dataset",
) -> EvaluationResult:
    """Fig. 4.9 with ``settings.diversity`` (``d``) and ``settings.seed``: for each case of
    :data:`CASES` (primitive, semantic joint), the joint's last-frame position in
    ``d.n_samples`` motions sampled from ``models[primitive]`` against the training clips
    of that primitive in ``dataset`` (``source`` names its file in errors), in each
    projection of :data:`VIEWS`: coverage both ways (:func:`coverage_both_ways`, binned
    KDE on a ``d.grid`` x ``d.grid`` grid); the claim (motionvar.du2022.claims) is judged
    from :func:`fig4_9_measurements`."""
    d, seed = settings.diversity, settings.seed
    n_samples, level, grid = d.n_samples, d.level, d.grid
    rows, panels = [], []
    for prim, sem in CASES:
        model = models[prim]
        j = semantic_index(joint_map, model.skeleton, sem, "graph diversity joints")
        S = model.sample(n_samples, np.random.default_rng([seed, 49]))
        pos = np.concatenate(
            [
                model.key_frame_pose(S[i : i + SAMPLE_CHUNK], [model.n_frames - 1], [j])[0][:, 0, 0]
                for i in range(0, len(S), SAMPLE_CHUNK)
            ]
        )
        motions, _ = primitive_clips(dataset, prim, source)
        train = np.stack([m.positions()[-1, j] for m in motions])
        for view, a, b in VIEWS:
            cov, inside, data = coverage_both_ways(pos[:, [a, b]], train[:, [a, b]], level, grid)
            rows.append(
                dict(
                    primitive=prim,
                    joint=sem,
                    view=view,
                    coverage=cov,
                    samples_inside=inside,
                    n_training=len(train),
                    n_samples=len(pos),
                )
            )
            panels.append(
                dict(
                    primitive=prim,
                    joint=sem,
                    view=view,
                    axes=(a, b),
                    training=train,
                    coverage=cov,
                    samples_inside=inside,
                    **data,
                )
            )
    table = pd.DataFrame(rows)
    measurements = fig4_9_measurements(table, level, d.coverage_threshold, n_samples)
    figure = dict(panels=panels, n_samples=n_samples, level=level)
    return EvaluationResult(table, judge_claims(CLAIMS, "du2022_fig4_9", measurements), figure, measurements)
