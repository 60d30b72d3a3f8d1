"""Figures of the Ma et al. 2010 evaluations (:mod:`.evaluations`): each ``draw_*`` takes
the evaluation's :class:`motionvar.claims.EvaluationResult` and returns a matplotlib
Figure (Fig. 3, 6, 7b, 8a, Sec. 7.4, Sec. 8)."""

from __future__ import annotations

from collections.abc import Sequence

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.axes import Axes
from matplotlib.collections import LineCollection
from matplotlib.figure import Figure

from ..claims import EvaluationResult
from ..core.motion import Motion
from ..plots import plot_key_frames
from ..plots.stick import bone_segments, project
from .comparison import LABELS, METHODS, NATURALNESS_SCORES

COLOURS = ("tab:blue", "tab:orange", "tab:green", "tab:red", "tab:purple", "tab:brown", "tab:pink", "tab:gray")


def draw_fig3(result: EvaluationResult) -> Figure:
    """Fig. 3: S_M(t) with its key frames and the foot strikes, and the first key frames
    as stick figures, for the walk and the run shown (``figure["shown"]``)."""
    shown = result.figure["shown"]
    fig, axes = plt.subplots(4, 1, figsize=(13, 11), gridspec_kw={"height_ratios": [1, 1.3, 1, 1.3]})
    for r, behaviour in enumerate(("walk", "run")):
        ax_s, ax_k = axes[2 * r], axes[2 * r + 1]
        if behaviour not in shown:
            ax_s.text(0.5, 0.5, f"no {behaviour} clips in this dataset", ha="center", transform=ax_s.transAxes)
            ax_s.axis("off")
            ax_k.axis("off")
            continue
        cid, m, ex, strikes = shown[behaviour]
        t = np.arange(m.n_frames) / m.fps
        s = ex.signal.signal
        ax_s.plot(t, s, color="k", lw=1.2, label=r"$S_\mathcal{M}(t)$" + f" ({ex.signal.part} body)")
        mx, mn = ex.frames[ex.kinds == 1], ex.frames[ex.kinds == -1]
        ax_s.plot(t[mx], s[mx], "v", color="tab:red", label="key frame (maximum)")
        ax_s.plot(t[mn], s[mn], "^", color="tab:blue", label="key frame (minimum)")
        for f in strikes:
            ax_s.axvline(f / m.fps, color="tab:green", lw=0.8, alpha=0.6)
        source = result.figure.get("strike_source", {}).get(behaviour, "detected")
        ax_s.plot([], [], color="tab:green", lw=0.8, label=f"foot strike ({source})")
        ax_s.set_xlabel("time (s)")
        ax_s.set_ylabel("S_M (cm)")
        ax_s.set_title(f"{behaviour} {cid}: D_l = {ex.signal.d_lower:.0f}, D_u = {ex.signal.d_upper:.0f}", fontsize=10)
        ax_s.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.0, 1.0))
        keys = ex.frames[: min(len(ex.frames), 7)]
        plot_key_frames(ax_k, m.positions(), m.skeleton.parents, keys, names=m.skeleton.names, fps=m.fps,
                        title=f"first {len(keys)} key frames of the {behaviour}")
    fig.suptitle("Ma 2010 Fig. 3: key frames at the local extrema of S_M(t)", fontsize=12)
    fig.tight_layout()
    return fig


def draw_fig6(result: EvaluationResult) -> Figure:
    """Fig. 6: true vs synthesized strides per support phase (ours with the held-out xi,
    ours with xi sampled, Kriging) and the stride error per held-out cycle."""
    table = result.table
    bound = result.figure["published_max_stride_error_cm"]
    err = table["ours_stride_error_cm"].to_numpy()
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.6))
    for ax, side in zip(axes[:2], ("left", "right")):
        t, p = table[f"true_{side}_cm"], table[f"ours_{side}_cm"]
        ax.scatter(t, p, s=14, color="tab:blue", label="ours (held-out clip's xi)")
        ax.scatter(t, table[f"ours_sampled_xi_{side}_cm"], s=10, marker="+", color="tab:green",
                   label="ours (xi sampled from the network)")
        ax.scatter(t, table[f"kriging_{side}_cm"], s=10, marker="x", color="tab:orange", label="Kriging, style only")
        lo, hi = min(t.min(), p.min()) - 2, max(t.max(), p.max()) + 2
        ax.plot([lo, hi], [lo, hi], color="0.5", lw=1)
        ax.set_xlabel(f"true stride, {side} support (cm)")
        ax.set_ylabel("stride of the synthesized cycle (cm)")
        ax.set_title(f"{side} support phase")
        ax.legend(fontsize=8)
    x = np.arange(len(table))
    axes[2].bar(x, err, color="tab:blue", label="ours: max |error| of the two phases")
    axes[2].axhline(bound, color="tab:red", ls="--", label=f"paper: max error {bound:g} cm")
    axes[2].set_xlabel("held-out cycle")
    axes[2].set_ylabel("stride error (cm)")
    axes[2].set_title(f"LOO over {len(table)} cycles: max {err.max():.2f} cm, mean {err.mean():.2f} cm")
    axes[2].legend(fontsize=8)
    fig.suptitle("Ma 2010 Fig. 6: stride of held-out walking cycles vs the synthesized ones (leave-one-out)")
    fig.tight_layout()
    return fig


def draw_fig7b(result: EvaluationResult) -> Figure:
    """Fig. 7b: the reliability map over the style grid with the examples, and the stride
    error against the distance to the nearest example."""
    table, f = result.table, result.figure
    n, failed, style = f["n_grid"], f["failed"], f["example_style"]
    gl = table["left_cm"].to_numpy().reshape(n, n)
    gr = table["right_cm"].to_numpy().reshape(n, n)
    err = table["stride_error_cm"].to_numpy().reshape(n, n)
    fig, axes = plt.subplots(1, 2, figsize=(13, 5.2))
    cmap = plt.get_cmap("RdYlBu_r").with_extremes(bad="0.35")
    mesh = axes[0].pcolormesh(gl, gr, np.ma.masked_invalid(err), shading="nearest", cmap=cmap)
    fig.colorbar(mesh, ax=axes[0], label="stride error of the synthesized cycle (cm)")
    axes[0].scatter(style[:, 0], style[:, 1], s=12, facecolor="white", edgecolor="k", label="example cycles")
    axes[0].set_xlabel("stride, left support (cm)")
    axes[0].set_ylabel("stride, right support (cm)")
    axes[0].set_title("reliability map: blue = reliable, red = unreliable, grey = synthesis failed", fontsize=9)
    axes[0].legend(fontsize=8, loc="upper left")
    axes[1].scatter(table["nearest_example_cm"], table["stride_error_cm"], s=12)
    if failed.any():
        axes[1].scatter(table["nearest_example_cm"][failed], np.full(failed.sum(), np.nanmax(err) * 1.05), marker="x",
                        color="0.35", s=14, label="synthesis failed (ranked last)")
        axes[1].legend(fontsize=8)
    axes[1].set_xlabel("distance to the nearest example (cm)")
    axes[1].set_ylabel("stride error (cm)")
    axes[1].set_title(f"Spearman rho = {f['rho']:.2f} (p = {f['p']:.1g}), {len(table)} grid points")
    fig.suptitle("Ma 2010 Fig. 7b: reliability of the style parameters")
    fig.tight_layout()
    return fig


def draw_overlay(ax: Axes, motions: Sequence[Motion], key_frames: Sequence[np.ndarray], colours: Sequence[str]) -> None:
    """Key frames of several cycles, one column per key frame, cycles overlaid in colours."""
    spacing = 110.0
    for m, keys, colour in zip(motions, key_frames, colours):
        xy = project(m.positions(), (1.0, 0.0, 0.0), azimuth_deg=20.0)
        for k, f in enumerate(keys):
            pose = xy[f].copy()
            pose[:, 0] += k * spacing - pose[0, 0]
            ax.add_collection(LineCollection(bone_segments(pose, m.skeleton.parents), colors=colour, linewidths=1.4,
                                             alpha=0.8))
    ax.set_xlim(-0.5 * spacing, (len(key_frames[0]) - 0.5) * spacing)
    ax.autoscale(axis="y")
    ax.set_aspect("equal")
    ax.set_xticks([k * spacing for k in range(len(key_frames[0]))])
    ax.set_xticklabels([f"key {k + 1}" for k in range(len(key_frames[0]))])


def draw_fig8(result: EvaluationResult) -> Figure:
    """Fig. 8a: the key frames of the variants overlaid, and the spread per joint group of
    ours, the nearest examples, RBF and Kriging."""
    f = result.figure
    style, errors, spreads, groups = f["style"], f["errors"], f["spreads"], f["groups"]
    fig, axes = plt.subplots(1, 2, figsize=(15, 5), gridspec_kw={"width_ratios": [2.2, 1]})
    draw_overlay(axes[0], f["motions"], f["key_frames"], COLOURS)
    axes[0].set_title(f"{len(f['motions'])} synthesized cycles at stride {style[0]:.1f} / {style[1]:.1f} cm (one "
                      f"colour each); stride errors {', '.join(f'{e:.2f}' for e in errors)} cm", fontsize=9)
    names = list(spreads)
    width = 0.8 / len(names)
    for i, name in enumerate(names):
        axes[1].bar(np.arange(len(groups)) + i * width, [spreads[name][g] for g in groups], width, label=name)
    axes[1].set_xticks(np.arange(len(groups)) + 0.4 - width / 2)
    axes[1].set_xticklabels(["legs (A)", "left arm (B)", "right arm (C)", "upper body (D)"], fontsize=8)
    axes[1].set_ylabel("SD across clips of joint positions (cm)")
    axes[1].set_title("spread at one style, per joint group")
    axes[1].legend(fontsize=8, loc="upper left")
    axes[1].set_ylim(0, 1.3 * max(max(v.values()) for v in spreads.values()))
    fig.suptitle("Ma 2010 Fig. 8a: variation at a fixed style")
    fig.tight_layout()
    return fig


def draw_sec7_4(result: EvaluationResult) -> Figure:
    """Sec. 7.4: the four naturalness scores and the variation between sequences per
    method (examples as reference; a diverged method drawn at the top, marked)."""
    f = result.figure
    means = f["means"]
    fig, axes = plt.subplots(1, 5, figsize=(18, 4.2))
    colours = plt.get_cmap("tab10").colors
    shown = [*METHODS, "examples"]
    for ax, key in zip(axes, [*NATURALNESS_SCORES, "variation_between_sequences_cm"]):
        raw = [float(means.loc[m, key]) for m in shown]
        finite = [v for v in raw if np.isfinite(v)]
        top = 1.5 * max(finite) if finite else 1.0
        vals = [v if np.isfinite(v) else (top if v > 0 else 0.0) for v in raw]
        ax.bar(range(len(shown)), vals, color=[*colours[: len(METHODS)], "0.75"], hatch=[""] * len(METHODS) + ["//"])
        ax.set_xticks(range(len(shown)))
        ax.set_xticklabels([LABELS.get(m, "examples (reference)") for m in shown], rotation=40, ha="right", fontsize=8)
        for i, v in enumerate(raw):
            if np.isinf(v):
                ax.text(i, top, "diverged", rotation=90, ha="center", va="top", fontsize=7, color="white")
        ax.set_title(NATURALNESS_SCORES.get(key, f"variation between the {f['n_sequences']} sequences (cm)"), fontsize=9)
        positive = sorted(v for v in vals if v > 0)
        if positive and positive[-1] > 20 * positive[0]:  # a method far off the others: log axis
            ax.set_yscale("symlog", linthresh=positive[0])
    fig.suptitle(f"Ma 2010 Sec. 7.4: {f['seconds']:g}-s sequences from {f['n_examples']} example cycles "
                 "(naturalness: lower is better; variation: 0 = identical sequences)", fontsize=11)
    fig.tight_layout()
    return fig


def draw_sec8(result: EvaluationResult) -> Figure:
    """Sec. 8: seconds of computation per second of motion, the paper's and ours."""
    f = result.figure
    sps, paper = f["seconds_per_second"], f["published_seconds_per_second"]
    fig, ax = plt.subplots(figsize=(6, 3.6))
    ax.bar(["paper (Sec. 8)", "ours"], [paper, sps], color=["0.6", "tab:blue"])
    ax.axhline(1.0, color="tab:red", ls="--", lw=1, label="real time (1 s per s)")
    ax.set_yscale("log")
    ax.set_ylabel("computation s per s of motion")
    ax.set_title(f"{f['motion_seconds']:.0f} s of walking from {f['n_cycles']} cycles: {1 / sps:.0f}x faster than "
                 "real time", fontsize=9)
    ax.legend(fontsize=8)
    fig.tight_layout()
    return fig
