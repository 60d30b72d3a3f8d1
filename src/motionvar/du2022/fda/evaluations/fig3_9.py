"""Du 2022 Fig. 3.9 (Sec. 3.3.3): joint-space RMSE between the B-spline functions and the
canonical frames for an increasing number of basis functions K, per behaviour and per
primitive with the K chosen by the cut-off rule."""

from __future__ import annotations

import numpy as np
import pandas as pd

from ....claims import Claim, EvaluationResult, verdict_from_fraction
from ..settings import FdaSettings


def evaluate_fig3_9(rmse: pd.DataFrame, settings: FdaSettings) -> EvaluationResult:
    """Fig. 3.9 from the RMSE table of :func:`motionvar.du2022.fda.choose_basis_sizes`
    (columns primitive, behaviour, n_clips, canonical_frames, n_basis, rmse_cm, chosen) made
    with ``settings.basis``.

    Table: the per-primitive rows, then per behaviour the RMSE pooled over its primitives'
    clips and frames (primitive "(all)"). Figure: ``pooled`` (behaviour, n_basis,
    rmse_cm), ``per_primitive`` (the input rows), ``min_relative_drop``. Claim: the RMSE
    falls strictly with K for every behaviour."""
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

    decreasing = {b: bool(np.all(np.diff(g["rmse_cm"].to_numpy()) < 0)) for b, g in pooled.groupby("behaviour")}
    n_ok = sum(decreasing.values())
    ks = sorted(pooled["n_basis"].unique())
    measured = "; ".join(
        f"{b}: {g['rmse_cm'].iloc[0]:.3g} cm (K={ks[0]}) -> {g['rmse_cm'].iloc[-1]:.3g} cm (K={g['n_basis'].iloc[-1]})"
        + ("" if decreasing[b] else " (not monotone)")
        for b, g in pooled.groupby("behaviour")
    )
    claim = Claim(
        claim_id="du2022.fig3_9.rmse_decreases_with_k",
        paper="du2022",
        source="Fig. 3.9",
        statement="The joint-space RMSE of the cubic B-spline representation decreases as the number of "
        "basis functions K grows, for every motion type.",
        published="RMSE falls with K for every motion type (curves in Fig. 3.9); chosen K: walk 10, "
        "two-hand pick 25, carry 15, transfer 20 (Table 3.1)",
        measured=f"{n_ok}/{len(decreasing)} behaviours strictly decreasing; {measured}; chosen K: "
        + ", ".join(f"{c['primitive']} {c['n_basis']}" for c in chosen),
        verdict=verdict_from_fraction(n_ok, len(decreasing)),
        value=n_ok / len(decreasing) if decreasing else float("nan"),
        bound=1.0,
        unit="share",
        direction=">=",
        note="RMSE of FK joint positions between the B-spline functions evaluated at the canonical "
        "frames and the canonical (time-warped) frames themselves.",
    )
    figure = {"pooled": pooled, "per_primitive": table, "min_relative_drop": settings.basis.min_relative_drop}
    return EvaluationResult(table=out, claims=[claim], figure=figure)
