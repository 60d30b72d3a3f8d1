"""Du 2022 Fig. 3.9 (Sec. 3.3.3): joint-space RMSE between the B-spline functions and the
canonical frames for an increasing number of basis functions K, per behaviour and per
primitive with the K chosen by the cut-off rule."""

from __future__ import annotations

from typing import Any

import numpy as np
import pandas as pd

from ....claims import EvaluationResult, judge_claims
from ...claims import CLAIMS
from ..settings import FdaSettings


def evaluate_fig3_9(rmse: pd.DataFrame, settings: FdaSettings) -> EvaluationResult:
    """Fig. 3.9 from the RMSE table of :func:`motionvar.du2022.fda.choose_basis_sizes`
    (columns primitive, behaviour, n_clips, canonical_frames, n_basis, rmse_cm, chosen) made
    with ``settings.basis``.

    Table: the per-primitive rows, then per behaviour the RMSE pooled over its primitives'
    clips and frames (primitive "(all)"). Figure: ``pooled`` (behaviour, n_basis,
    rmse_cm), ``per_primitive`` (the input rows), ``min_relative_drop``. Measurements
    (:func:`fig3_9_measurements`): the pooled RMSE per behaviour, judged in
    :mod:`motionvar.du2022.claims`."""
    table = rmse.copy()
    chosen = table[table["chosen"]].to_dict("records")

    # per behaviour: RMSE pooled over its primitives' clips and frames
    table["weight"] = table["n_clips"] * table["canonical_frames"]
    table["sq"] = table["rmse_cm"] ** 2 * table["weight"]
    pooled = table.groupby(["behaviour", "n_basis"])[["sq", "weight"]].sum()
    pooled = np.sqrt(pooled["sq"] / pooled["weight"]).rename("rmse_cm").reset_index()
    table = table.drop(columns=["weight", "sq"])
    behaviour_rows = pooled.assign(primitive="(all)", chosen=False)
    out = pd.concat([table, behaviour_rows], ignore_index=True)

    figure = {"pooled": pooled, "per_primitive": table, "min_relative_drop": settings.basis.min_relative_drop}
    measurements = fig3_9_measurements(pooled, chosen)
    return EvaluationResult(out, judge_claims(CLAIMS, "du2022_fig3_9", measurements), figure, measurements)


def fig3_9_measurements(pooled: pd.DataFrame, chosen: list[dict[str, Any]]) -> dict[str, Any]:
    """What the Fig. 3.9 claim is judged on: per behaviour its pooled RMSE (cm) at each K
    (ascending), every K measured, and the K chosen per primitive."""
    return {
        "behaviours": {
            str(b): {"n_basis": [int(k) for k in g["n_basis"]], "rmse_cm": [float(r) for r in g["rmse_cm"]]}
            for b, g in pooled.groupby("behaviour")
        },
        "n_basis": [int(k) for k in sorted(pooled["n_basis"].unique())],
        "chosen": {str(c["primitive"]): int(c["n_basis"]) for c in chosen},
    }
