"""Figure of a claims-stability table (:mod:`motionvar.report.stability`): one row per claim
with a value, its value in every seed (coloured by that seed's verdict) against the bound."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
import pandas as pd
from matplotlib.figure import Figure
from matplotlib.lines import Line2D

from ..report.counts import seed_bounds, seed_names
from ..report.summary import VERDICT_COLOURS

_EDGE = {
    "reproduced": "tab:green",
    "partial": "tab:orange",
    "not reproduced": "tab:red",
    "not testable": "0.4",
    "not applicable": "0.6",
    "missing": "k",
}


def stability_figure(table: pd.DataFrame) -> Figure:
    """One small panel per claim that carries a value (each on its own scale: units
    differ): the seeds' values as dots coloured by their verdict, the mean with its 95 %
    interval as a bar, the bound as a red dashed line (a red tick beside each seed's dot where
    the bound is measured on the data and differs between seeds); the claim id and whether it is
    stable at the left. Claims without values are listed in the title count."""
    seeds = seed_names(table)
    rows = table[np.isfinite(table["value_mean"].astype(float))].reset_index(drop=True)
    n = max(len(rows), 1)
    fig, axes = plt.subplots(n, 1, figsize=(11, 0.42 * n + 1.2), squeeze=False)
    for ax, r in zip(axes[:, 0], rows.to_dict("records")):
        vals = np.array([r[f"value_{s}"] for s in seeds], dtype=float)
        verdicts = [r[f"verdict_{s}"] for s in seeds]
        jitter = (np.arange(len(vals)) - (len(vals) - 1) / 2) * 0.09  # seeds with equal values stay visible
        ax.scatter(
            vals,
            jitter,
            s=28,
            c=[VERDICT_COLOURS.get(v, "#ddd") for v in verdicts],
            edgecolors=[_EDGE.get(v, "k") for v in verdicts],
            linewidths=1.0,
            zorder=3,
        )
        if np.isfinite(r["value_ci_low"]):
            ax.plot([r["value_ci_low"], r["value_ci_high"]], [0.45, 0.45], color="0.3", lw=2)
        ax.plot([r["value_mean"]], [0.45], marker="|", color="0.1", ms=8)
        per_seed = seed_bounds(r, seeds)
        if per_seed is not None:  # each seed's own bound, beside its dot
            for b, y in zip(per_seed, jitter):
                ax.plot([b, b], [y - 0.12, y + 0.12], color="tab:red", lw=1.2)
        elif np.isfinite(r["bound"]):
            ax.axvline(r["bound"], color="tab:red", ls="--", lw=1)
        bounds = per_seed if per_seed is not None else [r["bound"]]
        extent = np.concatenate([vals, bounds, [r["value_ci_low"], r["value_ci_high"]]])
        lo, hi = np.nanmin(extent), np.nanmax(extent)
        pad = 0.08 * (hi - lo) if hi > lo else max(abs(hi), 1.0) * 0.1
        ax.set_xlim(lo - pad, hi + pad)
        ax.set_ylim(-0.6, 0.8)
        ax.set_yticks([])
        ax.tick_params(axis="x", labelsize=6, pad=1)
        for side in ("top", "right", "left"):
            ax.spines[side].set_visible(False)
        mark = "" if r["stable"] else "  (not stable)"
        ax.text(
            -0.01,
            0.5,
            f"{r['claim_id']}{mark}",
            transform=ax.transAxes,
            ha="right",
            va="center",
            fontsize=6.5,
            color="k" if r["stable"] else "tab:red",
        )
        unit = r["unit"] if isinstance(r["unit"], str) else ""  # a CSV read back gives NaN for ""
        ax.text(1.01, 0.5, unit, transform=ax.transAxes, ha="left", va="center", fontsize=6)
    if rows.empty:
        axes[0, 0].set_axis_off()
        axes[0, 0].text(0.5, 0.5, "no claim carries a value", ha="center", va="center")
    handles = [
        Line2D([], [], marker="o", ls="", color=VERDICT_COLOURS.get(v, "#ddd"), markeredgecolor=_EDGE[v], label=v)
        for v in ("reproduced", "partial", "not reproduced", "not testable")
    ]
    handles += [
        Line2D([], [], color="tab:red", ls="--", label="bound"),
        Line2D([], [], color="tab:red", marker="|", ls="", ms=8, label="bound of that seed (measured)"),
        Line2D([], [], color="0.3", lw=2, label="mean, 95 % interval"),
    ]
    fig.legend(handles=handles, loc="upper center", ncol=7, fontsize=7, frameon=False, bbox_to_anchor=(0.5, 1.0))
    fig.suptitle(
        f"Claim values across {len(seeds)} seeds ({len(rows)} of {len(table)} claims carry a value)",
        fontsize=9,
        y=1.0 - 0.35 / (0.42 * n + 1.2),
    )
    fig.subplots_adjust(
        left=0.36, right=0.95, top=1.0 - 0.75 / (0.42 * n + 1.2), bottom=0.4 / (0.42 * n + 1.2), hspace=0.9
    )
    return fig
