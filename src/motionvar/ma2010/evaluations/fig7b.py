"""Ma et al. 2010 Fig. 7b, Sec. 7.2: reliability over the 2-D style space (stride of the
left and of the right support phase). At every point of a grid around the examples the
model synthesizes a cycle (xi at the network's conditional mean) whose strides are
measured; the error against the requested strides is the map, and its rank correlation
with the distance to the nearest example is the claim."""

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


def reliability_map(
    model: StyleVariationModel, clips: ClipSet, solver: RootSolver, n_grid: int, margin: float
) -> pd.DataFrame:
    """Fig. 7b: over a grid of the 2-D style space (the examples' range widened by
    ``margin`` times its extent on each side), the stride error of the synthesized clip
    (xi at the network's conditional mean; NaN where the synthesis fails) and the distance
    to the nearest example (cm)."""
    lo, hi = clips.style.min(axis=0), clips.style.max(axis=0)
    ext = np.maximum(hi - lo, 1.0)
    axes = [np.linspace(lo[k] - margin * ext[k], hi[k] + margin * ext[k], n_grid) for k in range(2)]
    gl, gr = np.meshgrid(*axes, indexing="ij")
    grid = np.stack([gl.ravel(), gr.ravel()], axis=1)
    pred, _ = model.synthesize_clips(grid, noise=False)
    measured = predicted_strides(pred, model.reference_keys_, solver, clips.fps)
    dist, _ = cKDTree(clips.style).query(grid)
    return pd.DataFrame(
        {
            "left_cm": grid[:, 0],
            "right_cm": grid[:, 1],
            "measured_left_cm": measured[:, 0],
            "measured_right_cm": measured[:, 1],
            "stride_error_cm": np.max(np.abs(measured - grid), axis=1),
            "nearest_example_cm": dist,
        }
    )


def reliability_correlation(table: pd.DataFrame) -> tuple[float, float, np.ndarray]:
    """Spearman's rho and its p-value between the stride error and the distance to the nearest
    example over the points of a reliability map (:func:`reliability_map`), a failed synthesis
    (NaN error) ranking last; and the mask of failed points."""
    failed = table["stride_error_cm"].isna().to_numpy()
    ranked = np.where(failed, np.inf, table["stride_error_cm"].to_numpy())  # a failed synthesis ranks last
    rho, p = spearmanr(ranked, table["nearest_example_cm"])
    return float(rho), float(p), failed


def fig7b_reliability(walks: WalkCycles, model: StyleVariationModel, settings: Ma2010Settings) -> EvaluationResult:
    """Fig. 7b for ``model`` fitted to ``walks``: the reliability map on an ``n_grid`` x
    ``n_grid`` grid (``settings.reliability_grid``; the examples' range widened by
    ``settings.reliability_margin``) and the claim that the stride error grows with the distance to the
    nearest example (:func:`reliability_correlation`; measurements ``rho``, ``p``, ``grid_points``,
    ``failed``, ``margin``). Figure: ``n_grid``, ``example_style`` (N, 2), ``rho``, ``p``, ``failed``
    (mask over the table)."""
    n_grid, margin = settings.reliability_grid, settings.reliability_margin
    table = reliability_map(model, walks.clips, walks.solver, n_grid, margin)
    rho, p, failed = reliability_correlation(table)
    measurements = {"rho": rho, "p": p, "grid_points": len(table), "failed": int(failed.sum()), "margin": margin}
    figure = {"n_grid": n_grid, "example_style": walks.clips.style, "rho": rho, "p": p, "failed": failed}
    return EvaluationResult(table, judge_claims(CLAIMS, "ma2010_fig7b", measurements), figure, measurements)
