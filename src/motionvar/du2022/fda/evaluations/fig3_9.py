"""Du 2022 Fig. 3.9 (Sec. 3.3.3): joint-space RMSE between the B-spline functions and the
canonical frames for an increasing number of basis functions K, per behaviour and per
primitive with the K chosen by the cut-off rule."""

from __future__ import annotations

from collections.abc import Sequence
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

    Table: the per-primitive rows (``chosen``: the cut-off rule's K; ``first_within_<t>_cm``: the
    first K within each of ``settings.basis.equal_error_cm``), then per behaviour the RMSE pooled
    over its primitives' clips and frames (primitive "(all)"). Figure: ``pooled`` (behaviour, n_basis,
    rmse_cm), ``per_primitive`` (the input rows), ``min_relative_drop``, ``equal_error_cm``. Measurements
    (:func:`fig3_9_measurements`): the pooled RMSE per behaviour and the per-primitive curves
    with their chosen K, judged in :mod:`motionvar.du2022.claims`; the complex-motion claim
    compares ``settings.reconstruction.pick_primitive`` with the other Fig. 3.10 primitives
    (``settings.reconstruction.primitives``; Table 3.1: walk leftStance and two-hand picking reach)
    by ``settings.basis.claim_rule``."""
    table = rmse.sort_values(["primitive", "n_basis"]).copy()
    # the equal-error rule beside the cut-off rule's chosen K: the first K within each RMSE
    for t in settings.basis.equal_error_cm:
        within = table["rmse_cm"] <= t
        table[f"first_within_{t:g}_cm"] = within & (within.groupby(table["primitive"]).cumsum() == 1)

    # per behaviour: RMSE pooled over its primitives' clips and frames
    table["weight"] = table["n_clips"] * table["canonical_frames"]
    table["sq"] = table["rmse_cm"] ** 2 * table["weight"]
    pooled = table.groupby(["behaviour", "n_basis"])[["sq", "weight"]].sum()
    pooled = np.sqrt(pooled["sq"] / pooled["weight"]).rename("rmse_cm").reset_index()
    table = table.drop(columns=["weight", "sq"])
    behaviour_rows = pooled.assign(primitive="(all)", chosen=False).assign(
        **{c: False for c in table.columns if c.startswith("first_within_")}
    )
    out = pd.concat([table, behaviour_rows], ignore_index=True)

    figure = {
        "pooled": pooled,
        "per_primitive": table,
        "min_relative_drop": settings.basis.min_relative_drop,
        "equal_error_cm": list(settings.basis.equal_error_cm),
    }
    rec = settings.reconstruction
    simple = [p for p in rec.primitives if p != rec.pick_primitive]
    measurements = fig3_9_measurements(pooled, table, simple, rec.pick_primitive) | {
        "claim_rule": settings.basis.claim_rule,
        "equal_error_cm": [float(t) for t in settings.basis.equal_error_cm],
    }
    return EvaluationResult(out, judge_claims(CLAIMS, "du2022_fig3_9", measurements), figure, measurements)


def fig3_9_measurements(
    pooled: pd.DataFrame, per_primitive: pd.DataFrame, simple: Sequence[str], complex_primitive: str
) -> dict[str, Any]:
    """What the Fig. 3.9 claims are judged on: per behaviour its pooled RMSE (cm) at each K
    (ascending), every K measured, the K chosen per primitive, per primitive its RMSE curve,
    canonical frames and behaviour (rows of :func:`motionvar.du2022.fda.choose_basis_sizes`),
    the complex (manipulation) primitive and the simple ones it is compared with."""
    chosen = per_primitive[per_primitive["chosen"]]
    return {
        "behaviours": {
            str(b): {"n_basis": [int(k) for k in g["n_basis"]], "rmse_cm": [float(r) for r in g["rmse_cm"]]}
            for b, g in pooled.groupby("behaviour")
        },
        "n_basis": [int(k) for k in sorted(pooled["n_basis"].unique())],
        "chosen": {str(p): int(k) for p, k in zip(chosen["primitive"], chosen["n_basis"])},
        "primitives": {
            str(p): {
                "behaviour": str(g["behaviour"].iloc[0]),
                "canonical_frames": int(g["canonical_frames"].iloc[0]),
                "n_basis": [int(k) for k in g["n_basis"]],
                "rmse_cm": [float(r) for r in g["rmse_cm"]],
            }
            for p, g in per_primitive.sort_values("n_basis").groupby("primitive")
        },
        "complex": str(complex_primitive),
        "simple": [str(p) for p in simple],
    }
