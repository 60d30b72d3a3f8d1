"""Ma et al. 2010 Fig. 7b, Sec. 7.2: reliability over the 2-D style space (stride of the
left and of the right support phase). At every point of a grid around the examples the
model synthesizes a cycle (xi at the network's conditional mean) whose strides are
measured; the error against the requested strides is the map, and its rank correlation
with the distance to the nearest example is the claim ("a strong correlation"). A synthesis
that fails is the least reliable of all: it ranks as the largest error, never left out. The
verdict is the correlation over every grid point; two diagnostics stand beside it: the grid
points along the line the examples lie on (a symmetric gait: left = right stride), and those
off it with the error less half the asymmetry asked for, the least that a model which learnt
only symmetric walks errs there (a floor that grows with the distance by itself)."""

from __future__ import annotations

import numpy as np
import pandas as pd
from scipy.spatial import cKDTree
from scipy.stats import spearmanr

from ...claims import EvaluationResult, judge_claims
from ..claims import CLAIMS
from ..examples import WalkCycles
from ..representation import ClipSet
from ..settings import Ma2010Settings
from ..svi import StyleVariationModel
from ..synthesis import RootSolver
from .common import predicted_strides


def examples_line(style: np.ndarray) -> tuple[np.ndarray, np.ndarray, float]:
    """The line the example styles (N, 2) lie along: their mean, the unit direction of their
    first principal axis, and the largest distance of an example from it (cm)."""
    mean = style.mean(axis=0)
    _, _, vt = np.linalg.svd(style - mean, full_matrices=False)
    direction = vt[0]
    off = (style - mean) @ np.array([-direction[1], direction[0]])
    return mean, direction, float(np.abs(off).max(initial=0.0))


def reliability_map(
    model: StyleVariationModel, clips: ClipSet, solver: RootSolver, n_grid: int, margin: float
) -> pd.DataFrame:
    """Fig. 7b: over a grid of the 2-D style space (the examples' range widened by
    ``margin`` times its extent on each side), the stride error of the synthesized clip
    (xi at the network's conditional mean; NaN where the synthesis fails: ``failed``), the
    distance to the nearest example (cm), the distance from the examples' line
    (:func:`examples_line`) and whether the point lies along it (``on_examples_line``: within
    the band the examples occupy about the line, at least half a grid step wide, so that the
    grid cells the line crosses count), and ``asymmetry_floor_cm`` = |left - right| / 2, the
    smallest stride error of a cycle whose two strides are equal."""
    lo, hi = clips.style.min(axis=0), clips.style.max(axis=0)
    ext = np.maximum(hi - lo, 1.0)
    axes = [np.linspace(lo[k] - margin * ext[k], hi[k] + margin * ext[k], n_grid) for k in range(2)]
    gl, gr = np.meshgrid(*axes, indexing="ij")
    grid = np.stack([gl.ravel(), gr.ravel()], axis=1)
    pred, _ = model.synthesize_clips(grid, noise=False)
    measured = predicted_strides(pred, model.reference_keys_, solver, clips.fps)
    dist, _ = cKDTree(clips.style).query(grid)
    mean, direction, band = examples_line(clips.style)
    off_line = np.abs((grid - mean) @ np.array([-direction[1], direction[0]]))
    step = 0.5 * np.mean([np.ptp(a) / max(n_grid - 1, 1) for a in axes])
    return pd.DataFrame(
        {
            "left_cm": grid[:, 0],
            "right_cm": grid[:, 1],
            "measured_left_cm": measured[:, 0],
            "measured_right_cm": measured[:, 1],
            "stride_error_cm": np.max(np.abs(measured - grid), axis=1),
            "asymmetry_floor_cm": np.abs(grid[:, 0] - grid[:, 1]) / 2,
            "failed": np.isnan(measured).any(axis=1),
            "nearest_example_cm": dist,
            "examples_line_cm": off_line,
            "on_examples_line": off_line <= max(band, step),
        }
    )


def rank_correlation(table: pd.DataFrame, error: str = "stride_error_cm") -> dict:
    """Spearman's rho and its p-value between the ``error`` column and the distance to the nearest
    example over the points of (a part of) a reliability map, a failed synthesis ranked as the
    largest error (ties among failures share their rank), with the number of points and of
    failures among them (rho and p NaN with fewer than 3 points, or with no spread)."""
    failed = table["failed"].to_numpy(bool)
    err = np.where(failed, np.inf, table[error].to_numpy(float))
    out = {"n": len(table), "failed": int(failed.sum())}
    if len(table) < 3 or np.ptp(table["nearest_example_cm"].to_numpy(float)) == 0 or len(np.unique(err)) < 2:
        return {"rho": float("nan"), "p": float("nan")} | out
    rho, p = spearmanr(err, table["nearest_example_cm"])
    return {"rho": float(rho), "p": float(p)} | out


def reliability_correlation(table: pd.DataFrame) -> dict:
    """Fig. 7b's measurements from a reliability map (:func:`reliability_map`): the rank
    correlation (:func:`rank_correlation`, failures ranked worst) over every grid point (``all``:
    the verdict's), along the examples' line (``on_line``), off it (``off_line``) and off it with
    the asymmetry floor taken from the error (``off_line_excess``); over the syntheses that
    succeeded only (``succeeded``, a diagnostic); the numbers of grid points and of failed
    syntheses (all, along the line)."""
    on = table["on_examples_line"].to_numpy(bool)
    failed = table["failed"].to_numpy(bool)
    off = table[~on]
    if "asymmetry_floor_cm" in off:
        off = off.assign(excess_error_cm=off["stride_error_cm"] - off["asymmetry_floor_cm"])
    return {
        "all": rank_correlation(table),
        "on_line": rank_correlation(table[on]),
        "off_line": rank_correlation(off),
        "off_line_excess": rank_correlation(off, "excess_error_cm") if "excess_error_cm" in off else None,
        "succeeded": rank_correlation(table[~failed]),
        "grid_points": len(table),
        "on_line_points": int(on.sum()),
        "failed": int(failed.sum()),
        "failed_on_line": int((failed & on).sum()),
    }


def fig7b_reliability(walks: WalkCycles, model: StyleVariationModel, settings: Ma2010Settings) -> EvaluationResult:
    """Fig. 7b for ``model`` fitted to ``walks``: the reliability map on an ``n_grid`` x
    ``n_grid`` grid (``settings.fig7b.grid``; the examples' range widened by
    ``settings.fig7b.margin``) and the claim that the stride error grows strongly with the
    distance to the nearest example (:func:`reliability_correlation`, with ``margin``). Figure:
    ``n_grid``, ``example_style`` (N, 2), ``line`` (the examples' mean and direction), the
    correlations."""
    n_grid, margin = settings.fig7b.grid, settings.fig7b.margin
    table = reliability_map(model, walks.clips, walks.solver, n_grid, margin)
    measurements = reliability_correlation(table) | {"margin": margin}
    mean, direction, _ = examples_line(walks.clips.style)
    figure = {
        "n_grid": n_grid,
        "example_style": walks.clips.style,
        "line": (mean, direction),
        "correlation": {k: measurements[k] for k in ("all", "on_line", "off_line", "off_line_excess")},
    }
    return EvaluationResult(table, judge_claims(CLAIMS, "ma2010_fig7b", measurements), figure, measurements)
