"""The realism figure of a dataset (rule dataset_realism): each statistic against its band
from captured data, and the spread of every joint's rotation channels."""

from __future__ import annotations

import numpy as np
import pandas as pd
from matplotlib.figure import Figure


def _position(value: float, lo: float, hi: float) -> float:
    """Where ``value`` lies in [lo, hi] (0 at lo, 1 at hi), on a log scale when both are positive."""
    if lo > 0 and value > 0:
        return float((np.log(value) - np.log(lo)) / (np.log(hi) - np.log(lo)))
    return float((value - lo) / (hi - lo)) if hi > lo else 0.5


def realism_figure(table: pd.DataFrame, joints: pd.DataFrame, title: str) -> Figure:
    """Left: one row per statistic with a band, its value placed in the band (shaded;
    log-scaled for positive bands), green inside, red outside, grey where the band does not
    gate (descriptive: the generator's clean data lies in it too), clipped at the panel's edges.
    Right: the largest SD of each joint's three rotation channels in the walks, or in the
    clips of the first other behaviour the data has (log scale)."""
    banded = table[np.isfinite(table["band_lo"].to_numpy(dtype=float))].reset_index(drop=True)
    present = [b for b in ("walk", "idle", "pick") if (joints["behaviour"] == b).any()]
    behaviour = present[0] if present else "walk"
    walk = joints[joints["behaviour"] == behaviour].reset_index(drop=True)
    height = max(len(banded), len(walk) * 0.55, 6) * 0.32 + 1.5
    fig = Figure(figsize=(15, height))
    ax, bx = fig.subplots(1, 2, gridspec_kw={"width_ratios": [1.25, 1]})
    ax.axvspan(0.0, 1.0, color="0.88")
    for k, row in banded.iterrows():
        y = len(banded) - 1 - k
        gates = bool(row["gates"])
        label = f"{row['statistic']} ({row['behaviour']}{'' if gates else ', descriptive'})"
        if not np.isfinite(row["value"]):
            ax.text(0.5, y, "no value (the data cannot give it)", ha="center", va="center", fontsize=8, color="0.4")
        else:
            x = _position(row["value"], row["band_lo"], row["band_hi"])
            color = ("tab:green" if bool(row["in_band"]) else "tab:red") if gates else "0.55"
            ax.plot(np.clip(x, -0.45, 1.45), y, "o", color=color, ms=7)
        value = f"{row['value']:.3g}" if np.isfinite(row["value"]) else "-"
        ax.text(1.52, y, f"{value}  [{row['band_lo']:.3g}, {row['band_hi']:.3g}]", va="center", fontsize=8)
        ax.text(-0.5, y, label + "  ", ha="right", va="center", fontsize=8)
    ax.set_xlim(-0.5, 1.5)
    ax.set_ylim(-0.7, len(banded) - 0.3)
    ax.set_yticks([])
    ax.set_xticks([0, 1], ["band low", "band high"])
    ax.set_title("statistic: value [band] from captured data", fontsize=10, loc="right")
    if len(walk):
        sd = np.maximum(walk["max_sd_deg"].to_numpy(dtype=float), 1e-4)
        y = np.arange(len(walk))[::-1]
        bx.barh(y, sd, color="tab:blue")
        bx.set_xscale("log")
        bx.set_yticks(y, walk["joint"], fontsize=7)
        bx.set_xlim(1e-4, max(100.0, sd.max() * 1.5))
        bx.set_xlabel(f"largest channel SD over the {behaviour} clips (degrees; 1e-4: constant)")
    else:
        bx.text(0.5, 0.5, "no walk, idle or pick clips", ha="center", va="center")
        bx.set_axis_off()
    fig.suptitle(title, fontsize=11)
    fig.subplots_adjust(left=0.22, right=0.98, top=1.0 - 0.6 / height, bottom=0.6 / height + 0.02, wspace=0.6)
    return fig
