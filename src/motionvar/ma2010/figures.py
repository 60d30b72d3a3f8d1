"""Figures of the Ma et al. 2010 evaluations (:mod:`.evaluations`): each ``draw_*`` takes
the evaluation's :class:`motionvar.claims.EvaluationResult` and returns a matplotlib
Figure (Fig. 3, 6, 7b, 8a, Sec. 7.4, Sec. 8)."""

from __future__ import annotations

from collections.abc import Sequence

import matplotlib.pyplot as plt
import numpy as np
import pandas as pd
from matplotlib.axes import Axes
from matplotlib.collections import LineCollection
from matplotlib.figure import Figure

from ..claims import EvaluationResult
from ..core.motion import Motion
from ..plots import plot_key_frames
from ..plots.stick import bone_segments, project
from .comparison import METHODS, NATURALNESS_SCORES, family

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
        plot_key_frames(
            ax_k,
            m.positions(),
            m.skeleton.parents,
            keys,
            names=m.skeleton.names,
            fps=m.fps,
            title=f"first {len(keys)} key frames of the {behaviour}",
        )
    fig.suptitle("Ma 2010 Fig. 3: key frames at the local extrema of S_M(t)", fontsize=12)
    fig.tight_layout()
    return fig


def _fig6_strides(axes, folds: pd.DataFrame, closing: np.ndarray) -> None:
    """Fig. 6, left panels: per support phase, the requested stride (the held-out cycle's style)
    against the synthesized one of ours (own, mean and sampled xi) and Kriging; closing cycles ringed."""
    kinds = [
        ("ours_own_xi", "ours, held-out cycle's own xi", "o", "tab:blue"),
        ("ours_mean_xi", "ours, xi at the network's conditional mean", "s", "tab:purple"),
        ("ours_sampled_xi", "ours, xi sampled from the network", "+", "tab:green"),
        ("kriging", "Kriging, style only", "x", "tab:orange"),
    ]
    for ax, side in zip(axes, ("left", "right")):
        t = folds[f"true_{side}_cm"].to_numpy()
        for name, label, marker, colour in kinds:
            ax.scatter(t, folds[f"{name}_{side}_cm"], s=14, marker=marker, color=colour, label=label)
        ax.scatter(
            t[closing],
            folds.loc[closing, f"ours_own_xi_{side}_cm"],
            s=90,
            facecolors="none",
            edgecolors="k",
            lw=0.8,
            label="closing cycle (last of its walk)",
        )
        lo, hi = t.min() - 3, t.max() + 3
        ax.plot([lo, hi], [lo, hi], color="0.5", lw=1)
        ax.set_xlim(lo, hi)
        ax.set_ylim(lo, hi)
        ax.set_xlabel(f"requested stride (the held-out cycle's), {side} support (cm)")
        ax.set_ylabel("stride of the synthesized cycle (cm)")
        ax.set_title(f"{side} support phase (points beyond the frame not shown)", fontsize=9)
        ax.legend(fontsize=7, loc="upper left")


def _fig6_errors(ax: Axes, folds: pd.DataFrame, closing: np.ndarray, f: dict) -> None:
    """Fig. 6, third panel: the stride error per held-out cycle (ours, and the ablation with
    the root rotation in the other group), closing cycles shaded."""
    bound, root, abl = f["published_max_stride_error_cm"], f["root_group"], f.get("ablation")
    x = np.arange(len(folds))
    bars = [
        ("ours_own_xi", f"ours, own xi, root in {root}", "tab:blue"),
        ("ours_mean_xi", f"ours, conditional-mean xi, root in {root}", "tab:purple"),
    ]
    if abl:
        bars.append((f"ours_own_xi_{abl}", f"ours, own xi, root in {f['alt_root_group']} (ablation)", "tab:red"))
    width = 0.8 / len(bars)
    for k, (name, label, colour) in enumerate(bars):
        ax.bar(
            x + (k - (len(bars) - 1) / 2) * width, folds[f"{name}_stride_error_cm"], width, color=colour, label=label
        )
    for i in np.flatnonzero(closing):
        ax.axvspan(i - 0.45, i + 0.45, color="0.88", zorder=0)
    ax.axhline(bound, color="tab:red", ls="--", lw=1, label=f"paper: max error {bound:g} cm")
    ax.set_xticks(x)
    ax.set_xticklabels([f"{i + 1}{'c' if c else ''}" for i, c in enumerate(closing)], fontsize=6)
    ax.set_xlabel("held-out cycle, in walk order (c, shaded: closing cycle)")
    ax.set_ylabel("stride error: max |error| of the two phases (cm)")
    xi = f["loo_xi"]
    err = folds[f"ours_{xi}_xi_stride_error_cm"].to_numpy()
    unit = "whole walk left out per fold" if f["loo_unit"] == "walk" else "one cycle left out per fold"
    ax.set_title(
        f"{len(folds)} held-out cycles ({unit}): ours ({xi} xi, the verdict's) max {err.max():.2f} cm, "
        f"mean {err.mean():.2f} cm",
        fontsize=9,
    )
    ax.legend(fontsize=7)


def _fig6_methods(ax: Axes, summary: pd.DataFrame, bound: float) -> None:
    """Fig. 6, right panel: the largest stride error of every method on steady and on closing cycles."""
    methods = list(dict.fromkeys(summary["method"]))
    y = np.arange(len(methods))
    for k, (cycles, colour) in enumerate([("steady", "tab:cyan"), ("closing", "0.45")]):
        rows = summary[summary["cycles"] == cycles].set_index("method")
        vals = [rows.loc[m, "max_stride_error_cm"] if m in rows.index else np.nan for m in methods]
        ax.barh(y + (k - 0.5) * 0.4, vals, 0.4, color=colour, label=f"{cycles} cycles")
        for yy, m, v in zip(y, methods, vals):
            if m in rows.index and np.isfinite(v):
                ax.text(
                    v,
                    yy + (k - 0.5) * 0.4,
                    f" {int(rows.loc[m, 'n_within_bound'])}/{int(rows.loc[m, 'n'])}",
                    va="center",
                    fontsize=6,
                )
    ax.axvline(bound, color="tab:red", ls="--", lw=1)
    style_only = {
        "kriging": "Kriging (style only)",
        "rbf": "RBF (style only, one kernel per walk)",
        "rbf_cycles": "RBF (style only, one kernel per cycle)",
        "least_squares": "least squares (style only)",
        "validation": "held-out cycle's own clip, retimed (diagnostic)",
    }
    labels = {
        m: style_only.get(m, f"ours, {r['xi']} xi, root in {r['root_group']}")
        for m, r in summary.drop_duplicates("method").set_index("method").iterrows()
    }
    ax.set_yticks(y)
    ax.set_yticklabels([labels[m] for m in methods], fontsize=7)
    ax.invert_yaxis()
    ax.set_xlabel("max stride error (cm); n within 1.2 cm / n")
    ax.set_title("steady vs closing cycles, per method", fontsize=9)
    ax.legend(fontsize=7, loc="lower right")


def draw_fig6(result: EvaluationResult) -> Figure:
    """Fig. 6: true vs synthesized strides per support phase (ours with the held-out
    cycle's own xi, at the network's conditional mean and sampled; Kriging), closing cycles
    (the last of each walk) ringed; the stride error per held-out cycle (ours, and the
    ablation with the root rotation in the other group), closing cycles shaded; and the
    largest error of every method on steady and on closing cycles."""
    table, f = result.table, result.figure
    folds = table[table["kind"] == "fold"].reset_index(drop=True)
    summary = table[table["kind"] == "summary"].reset_index(drop=True)
    closing = folds["closing"].astype(bool).to_numpy()
    fig, axes = plt.subplots(1, 4, figsize=(22, 5), gridspec_kw={"width_ratios": [1, 1, 1.5, 1.3]})
    _fig6_strides(axes[:2], folds, closing)
    _fig6_errors(axes[2], folds, closing, f)
    _fig6_methods(axes[3], summary, f["published_max_stride_error_cm"])
    fig.suptitle("Ma 2010 Fig. 6: stride of held-out walking cycles vs the synthesized ones (leave-one-out)")
    fig.tight_layout()
    return fig


def draw_fig7b(result: EvaluationResult) -> Figure:
    """Fig. 7b: the reliability map over the style grid with the examples and their line, and
    the stride error against the distance to the nearest example, grid points along the
    examples' line apart from those off it (failed syntheses only on the map)."""
    table, f = result.table, result.figure
    n, style = f["n_grid"], f["example_style"]
    gl = table["left_cm"].to_numpy().reshape(n, n)
    gr = table["right_cm"].to_numpy().reshape(n, n)
    err = table["stride_error_cm"].to_numpy().reshape(n, n)
    fig, axes = plt.subplots(1, 2, figsize=(13, 5.2))
    cmap = plt.get_cmap("RdYlBu_r").with_extremes(bad="0.35")
    mesh = axes[0].pcolormesh(gl, gr, np.ma.masked_invalid(err), shading="nearest", cmap=cmap)
    fig.colorbar(mesh, ax=axes[0], label="stride error of the synthesized cycle (cm)")
    axes[0].scatter(style[:, 0], style[:, 1], s=12, facecolor="white", edgecolor="k", label="example cycles")
    mean, direction = f["line"]
    reach = np.ptp(gl) + np.ptp(gr)
    ends = mean[None, :] + np.array([-reach, reach])[:, None] * direction[None, :]
    axes[0].plot(ends[:, 0], ends[:, 1], color="k", lw=0.8, ls=":", label="the examples' line")
    axes[0].set_xlim(gl.min(), gl.max())
    axes[0].set_ylim(gr.min(), gr.max())
    axes[0].set_xlabel("stride, left support (cm)")
    axes[0].set_ylabel("stride, right support (cm)")
    axes[0].set_title("reliability map: blue = reliable, red = unreliable, grey = synthesis failed", fontsize=9)
    axes[0].legend(fontsize=8, loc="upper left")
    on = table["on_examples_line"].to_numpy(bool)
    failed = table["failed"].to_numpy(bool)
    corr = f["correlation"]
    # a failed synthesis ranks as the largest error: drawn in a row above every measured one
    top = 1.15 * max(float(np.nanmax(table["stride_error_cm"], initial=0.0)), 1e-6)
    shown = np.where(failed, top, table["stride_error_cm"].to_numpy(float))
    excess = corr.get("off_line_excess")
    for mask, label, key, marker in (
        (on, "along the examples' line", "on_line", "o"),
        (~on, "off it", "off_line", "x"),
    ):
        c = corr[key]
        text = f"rho = {c['rho']:.2f}" if np.isfinite(c["rho"]) else "too few"
        if key == "off_line" and excess is not None and np.isfinite(excess["rho"]):
            text += f"; less the asymmetry floor {excess['rho']:.2f}"
        axes[1].scatter(
            table["nearest_example_cm"][mask],
            shown[mask],
            s=14,
            marker=marker,
            label=f"{label}: {c['n']} points, {c['failed']} failed, {text}",
        )
    if failed.any():
        axes[1].axhline(top, color="0.6", lw=0.6, ls="--")
        axes[1].annotate("failed", (0.01, top), xycoords=("axes fraction", "data"), va="bottom", fontsize=8)
    axes[1].legend(fontsize=8)
    axes[1].set_xlabel("distance to the nearest example (cm)")
    axes[1].set_ylabel("stride error (cm)")
    c = corr["all"]
    axes[1].set_title(
        f"Spearman rho = {c['rho']:.2f} (p = {c['p']:.1g}) over all {c['n']} grid points; "
        + (f"{c['failed']} failed syntheses, ranked worst" if c["failed"] else "no synthesis failed"),
        fontsize=9,
    )
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
            ax.add_collection(
                LineCollection(bone_segments(pose, m.skeleton.parents), colors=colour, linewidths=1.4, alpha=0.8)
            )
    ax.set_xlim(-0.5 * spacing, (len(key_frames[0]) - 0.5) * spacing)
    ax.autoscale(axis="y")
    ax.set_aspect("equal")
    ax.set_xticks([k * spacing for k in range(len(key_frames[0]))])
    ax.set_xticklabels([f"key {k + 1}" for k in range(len(key_frames[0]))])


def draw_fig8(result: EvaluationResult) -> Figure:
    """Fig. 8a: the key frames of the variants overlaid, and the spread per joint group of
    ours, the ceiling (the nearest examples' own xi at the same style), the nearest
    examples (also with each clip's mean posture removed), RBF and Kriging."""
    f = result.figure
    style, errors, spreads, groups = f["style"], f["errors"], f["spreads"], f["groups"]
    fig, axes = plt.subplots(1, 2, figsize=(16, 5), gridspec_kw={"width_ratios": [2.0, 1.2]})
    draw_overlay(axes[0], f["motions"], f["key_frames"], COLOURS)
    ceiling = f.get("ceiling_errors")
    extra = f"; ceiling (own xi) max {np.max(ceiling):.2f} cm" if ceiling is not None else ""
    axes[0].set_title(
        f"{len(f['motions'])} synthesized cycles at stride {style[0]:.1f} / {style[1]:.1f} cm (one "
        f"colour each); stride errors {', '.join(f'{e:.2f}' for e in errors)} cm{extra}",
        fontsize=9,
    )
    names = list(spreads)
    width = 0.8 / len(names)
    interval = f.get("data_interval")
    for i, name in enumerate(names):
        heights = [spreads[name][g] for g in groups]
        yerr = None
        if name == f.get("data_name") and interval is not None:  # the nearest examples' 95 % bootstrap interval
            lo, hi = (np.array([interval[g][k] for g in groups]) for k in (0, 1))
            yerr = np.clip([np.array(heights) - lo, hi - np.array(heights)], 0.0, None)
        axes[1].bar(
            np.arange(len(groups)) + i * width,
            heights,
            width,
            yerr=yerr,
            capsize=3,
            label=name + (" (95 % bootstrap interval)" if yerr is not None else ""),
            hatch="//" if "posture removed" in name else None,
            color=COLOURS[i % len(COLOURS)],
        )
    axes[1].set_xticks(np.arange(len(groups)) + 0.4 - width / 2)
    axes[1].set_xticklabels(["legs (A)", "left arm (B)", "right arm (C)", "upper body (D)"], fontsize=8)
    axes[1].set_ylabel("SD across clips of joint positions (cm)")
    axes[1].set_title("spread at one style, per joint group (ceiling: the examples' own xi)", fontsize=9)
    axes[1].legend(fontsize=7, loc="upper left")
    tallest = max(max(v.values()) for v in spreads.values())
    if interval is not None:
        tallest = max(tallest, max(hi for _, hi in interval.values()))
    axes[1].set_ylim(0, 1.45 * tallest)
    fig.suptitle("Ma 2010 Fig. 8a: variation at a fixed style")
    fig.tight_layout()
    return fig


def draw_sec7_4(result: EvaluationResult) -> Figure:
    """Sec. 7.4: the naturalness scores and the variation between sequences per method and
    setting (Perlin noise and the DBN at each setting of their sweeps; examples as reference;
    a diverged method drawn at the top, marked)."""
    f = result.figure
    means, labels = f["means"], f["labels"]
    n_panels = len(NATURALNESS_SCORES) + 1
    fig, axes = plt.subplots(1, n_panels, figsize=(3.8 * n_panels, 4.8))
    palette = dict(zip(METHODS, plt.get_cmap("tab10").colors))
    shown = [*labels, "examples"]
    colours = [palette[family(m)] for m in labels] + ["0.75"]
    for ax, key in zip(axes, [*NATURALNESS_SCORES, "variation_between_sequences_cm"]):
        raw = [float(means.loc[m, key]) for m in shown]
        finite = [v for v in raw if np.isfinite(v)]
        top = 1.5 * max(finite) if finite and max(finite) > 0 else 1.0
        vals = [v if np.isfinite(v) else (top if v > 0 else 0.0) for v in raw]
        ax.bar(range(len(shown)), vals, color=colours, hatch=[""] * len(labels) + ["//"])
        ax.set_xticks(range(len(shown)))
        ax.set_xticklabels([labels.get(m, "examples (reference)") for m in shown], rotation=50, ha="right", fontsize=7)
        for i, v in enumerate(raw):
            if np.isinf(v):
                ax.text(i, top, "diverged", rotation=90, ha="center", va="top", fontsize=7, color="white")
        ax.set_title(
            NATURALNESS_SCORES.get(key, f"variation between the {f['n_sequences']} sequences (cm)"), fontsize=8
        )
        positive = sorted(v for v in vals if v > 0)
        if positive and positive[-1] > 20 * positive[0]:  # a method far off the others: log axis
            ax.set_yscale("symlog", linthresh=positive[0])
    fig.suptitle(
        f"Ma 2010 Sec. 7.4: {f['seconds']:g}-s sequences from {f['n_examples']} example cycles; {f['sweeps']} "
        "(naturalness: lower is better; variation: 0 = identical sequences)",
        fontsize=10,
    )
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
    ax.set_title(
        f"{f['motion_seconds']:.0f} s of walking from {f['n_cycles']} cycles: {1 / sps:.0f}x faster than real time",
        fontsize=9,
    )
    ax.legend(fontsize=8)
    fig.tight_layout()
    return fig


def draw_variogram(result: EvaluationResult) -> Figure:
    """Sec. 6 (variogram): per Kriging interpolator (four joint groups, style-only MK05) the
    variogram cloud (same-walk pairs marked), the binned semivariogram over all pairs and
    between walks, the fitted variogram and the other candidate models."""
    table, f = result.table, result.figure
    names = list(dict.fromkeys(table["group"]))
    fig, axes = plt.subplots(1, len(names), figsize=(4.2 * len(names), 4.9), squeeze=False)
    scaled = f["scale"] == "sd"
    for ax, name in zip(axes[0], names):
        cloud, fits = f["clouds"][name], f["fits"][name]
        sw = cloud["same_walk"]
        ax.scatter(
            cloud["lag"][~sw],
            cloud["gamma"][~sw],
            s=4,
            color="0.7",
            alpha=0.5,
            lw=0,
            label="one pair of cycles, different walks",
        )
        ax.scatter(
            cloud["lag"][sw],
            cloud["gamma"][sw],
            s=7,
            color="tab:orange",
            alpha=0.8,
            lw=0,
            label="one pair of cycles, same walk",
        )
        ax.axvline(cloud["max_lag"], color="0.5", ls=":", lw=1, label="cutoff of the fit (half the largest lag)")
        rows = table[(table["group"] == name) & (table["series"] == "all pairs")]
        ax.scatter(
            rows["lag"],
            rows["gamma"],
            s=12 + 50 * rows["pairs"] / max(rows["pairs"].max(), 1),
            color="k",
            zorder=3,
            label="binned, all pairs (size: pairs)",
        )
        between = table[(table["group"] == name) & (table["series"] == "between walks")]
        ax.plot(
            between["lag"],
            between["gamma"],
            "s",
            mfc="none",
            mec="tab:blue",
            ms=5,
            zorder=3,
            label="binned, pairs from different walks",
        )
        h = np.linspace(0.0, cloud["max_lag"], 300)[1:]
        for m, ls in zip(("linear", "exponential", "gaussian", "spherical"), (":", "--", "-.", (0, (1, 3)))):
            if m in fits["candidates"]:
                ax.plot(h, fits["candidates"][m].curve(h), ls=ls, color="0.25", lw=0.9, label=f"{m} fit")
        v = fits["chosen"]
        ax.plot(h, v.curve(h), color="tab:red", lw=2.2, zorder=4, label="fitted variogram (used)")
        if scaled:
            ax.axhline(1.0, color="tab:green", lw=0.8, ls="--", label="semivariance of unrelated cycles (1)")
        top = max(np.nanpercentile(cloud["gamma"], 98) if len(cloud["gamma"]) else 0.0, 1.3 * np.nanmax(rows["gamma"]))
        ax.set_ylim(0, top)
        ax.set_xlim(0, 1.2 * cloud["max_lag"])
        d = v.describe()
        shape = f"range {d['range']:.2g}" if np.isfinite(d["range"]) else f"slope {d['slope']:.2g}"
        sill = d["partial_sill"] if np.isfinite(d["partial_sill"]) else 0.0
        ax.set_title(f"{name}\n{d['model']}: nugget {d['nugget']:.2g}, partial sill {sill:.2g}, {shape}", fontsize=9)
        ax.set_xlabel("lag: distance of standardized [c, xi] (MK05: c)", fontsize=8)
    axes[0][0].set_ylabel("semivariance" + (" (in variances of each dimension)" if scaled else " (raw units)"))
    handles, labels = axes[0][0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=5, fontsize=7, frameon=False)
    fig.suptitle(
        f"Ma 2010 Sec. 6: semivariograms of the Kriging residuals, {f['n_clips']} cycles "
        f"(variogram {f['model']}, output scale {f['scale']})",
        fontsize=11,
    )
    fig.tight_layout(rect=(0, 0.1, 1, 1))
    return fig
