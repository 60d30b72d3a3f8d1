"""Figures of the Egges et al. 2004 evaluations. One function per evaluation or figure
takes its :class:`~motionvar.claims.EvaluationResult` (or figure data) and returns a
matplotlib Figure: :func:`draw_categories` (Fig. 3), :func:`draw_fitting` (Fig. 4),
:func:`draw_repetition`, :func:`draw_pc_extrema` (Fig. 7-8), :func:`draw_identification`,
:func:`draw_speed`. The ``plot_*`` functions draw one panel into a given Axes.
"""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure
from matplotlib.patches import Circle, FancyArrowPatch

from ..claims import EvaluationResult
from .category_graph import CategoryGraph


def plot_pc_extrema(
    ax: Axes, x: np.ndarray, fps: float, idx: np.ndarray, is_max: np.ndarray, pc: int, n_labels: int = 4
) -> None:
    """Fig. 7-8: the values of one PC over a resting segment, its mean (the offset that
    Sec. 6.1 removes), the maxima and minima, and a few (distance ms, value) pairs."""
    t = np.arange(len(x)) / fps
    mean = float(np.mean(x))
    ax.plot(t, x, color="0.35", lw=1.0, label=f"PC {pc + 1}")
    ax.axhline(mean, color="tab:green", ls="--", lw=1.0, label=f"mean {mean:.3g} (offset, Sec. 6.1)")
    ax.plot(t[idx[is_max]], x[idx[is_max]], "v", color="tab:red", ms=6, label="maxima")
    ax.plot(t[idx[~is_max]], x[idx[~is_max]], "^", color="tab:blue", ms=6, label="minima")
    for k in range(1, min(len(idx), n_labels + 1)):
        d_ms = (idx[k] - idx[k - 1]) * 1000.0 / fps
        ax.annotate(
            f"({d_ms:.0f} ms, {x[idx[k]] - mean:+.2g})",
            (t[idx[k]], x[idx[k]]),
            textcoords="offset points",
            xytext=(4, 8 if is_max[k] else -14),
            fontsize=8,
        )
    ax.set_xlabel("time (s)")
    ax.set_ylabel("PC value")
    ax.legend(fontsize=8, loc="best")


def plot_category_graph(ax: Axes, graph: CategoryGraph, title: str = "") -> None:
    """Fig. 3: categories as nodes with T_min - T_max (ms), transitions as arrows with
    P(c1 => c2); arrows without observed transitions are left out."""
    k = graph.n
    angles = np.pi / 2 + 2 * np.pi * np.arange(k) / k
    pos = 1.6 * np.stack([np.cos(angles), np.sin(angles)], axis=1) if k > 1 else np.zeros((1, 2))
    r = 0.68
    for c in range(k):
        ax.add_patch(Circle(pos[c], r, facecolor="#dde8f5", edgecolor="0.2", lw=1.2))
        t = (
            f"{graph.t_min[c] * 1000:.0f} ms\n- {graph.t_max[c] * 1000:.0f} ms"
            if np.isfinite(graph.t_min[c])
            else "no stay"
        )
        ax.text(*pos[c], f"{graph.names[c]}\n{t}", ha="center", va="center", fontsize=8)
    for a in range(k):
        for b in range(k):
            p = graph.probabilities[a, b]
            if p <= 0:
                continue
            if a == b:
                out = pos[a] / (np.linalg.norm(pos[a]) or 1.0)
                ax.annotate(
                    "",
                    xy=pos[a] + out * r * 1.02 + [0.15, 0],
                    xytext=pos[a] + out * r * 1.02 - [0.15, 0],
                    arrowprops=dict(arrowstyle="->", connectionstyle="arc3,rad=-1.6", color="0.25"),
                )
                ax.text(*(pos[a] + out * (r + 0.45)), f"{p:.2f}", ha="center", va="center", fontsize=9, color="tab:red")
                continue
            u = (pos[b] - pos[a]) / np.linalg.norm(pos[b] - pos[a])
            start, end = pos[a] + u * r, pos[b] - u * r
            rad = 0.4
            ax.add_patch(
                FancyArrowPatch(
                    start,
                    end,
                    arrowstyle="-|>",
                    mutation_scale=14,
                    connectionstyle=f"arc3,rad={rad}",
                    color="0.25",
                    lw=1.2,
                )
            )
            d = end - start  # the label sits on the arc's midpoint (matplotlib's Arc3 control point)
            mid = 0.5 * (start + end) + 0.5 * rad * np.array([d[1], -d[0]])
            ax.text(
                *mid,
                f"{p:.2f}",
                ha="center",
                va="center",
                fontsize=9,
                color="tab:red",
                bbox=dict(boxstyle="round,pad=0.15", fc="white", ec="tab:red", lw=0.5),
            )
    ax.set_xlim(-2.6, 2.6)
    ax.set_ylim(-1.7, 2.4)
    ax.set_aspect("equal")
    ax.axis("off")
    if title:
        ax.set_title(title, fontsize=10)


def plot_fitted_animation(
    ax: Axes, original: np.ndarray, fitted: dict[str, np.ndarray], p: float, q: float, fps: float, pc: int = 0
) -> None:
    """Fig. 4: one PC of an animation before and after fitting it to start at p and end
    at q (one curve per ramp)."""
    t = np.arange(len(original)) / fps
    ax.plot(t, original, color="0.5", lw=1.5, label="animation a from the database")
    for (name, curve), style in zip(fitted.items(), ("-", "--")):
        ax.plot(t, curve, style, lw=1.5, label=f"fitted ({name} offset)")
    ax.plot([t[0]], [p], "o", color="tab:green", ms=8, label="p (start posture)")
    ax.plot([t[-1]], [q], "s", color="tab:purple", ms=8, label="q (end posture)")
    ax.set_xlabel("time (s)")
    ax.set_ylabel(f"PC {pc + 1}")
    ax.legend(fontsize=8)


def plot_identification(ax_bar: Axes, ax_conf: Axes, table, confusion: dict) -> None:
    """Accuracy per source and feature set with the chance level; confusion matrix of the
    generated windows (rows: true subject, columns: named subject)."""
    sources = list(dict.fromkeys(table["source"]))
    sets = list(dict.fromkeys(table["features"]))
    width = 0.8 / len(sets)
    x = np.arange(len(sources))
    for k, fs in enumerate(sets):
        acc = [float(table.loc[(table.source == s) & (table.features == fs), "accuracy"].iloc[0]) for s in sources]
        bars = ax_bar.bar(x + (k - (len(sets) - 1) / 2) * width, acc, width, label=f"features: {fs}")
        ax_bar.bar_label(bars, fmt="%.2f", fontsize=8)
    ax_bar.axhline(float(table["chance"].iloc[0]), color="k", ls="--", lw=1, label="chance (1/N)")
    ax_bar.set_xticks(x, [s.replace(" (", "\n(") for s in sources], fontsize=8)
    ax_bar.set_ylim(0, 1.22)
    ax_bar.set_ylabel("subject named correctly (share of windows)")
    ax_bar.legend(fontsize=8, loc="upper center", ncol=len(sets) + 1)
    m = confusion["confusion"]
    ax_conf.imshow(m, cmap="Blues")
    labels = confusion["labels"]
    ticks = np.arange(len(labels))
    step = max(1, len(labels) // 12)
    ax_conf.set_xticks(ticks[::step], labels[::step], fontsize=7)
    ax_conf.set_yticks(ticks[::step], labels[::step], fontsize=7)
    ax_conf.set_xlabel("subject named by the classifier")
    ax_conf.set_ylabel("subject of the generated motion")
    ax_conf.set_title("generated windows, all features", fontsize=9)


def plot_repetition(ax: Axes, pooled: dict[str, np.ndarray]) -> None:
    """Best-match normalised cross-correlation of every window, per source (box plots)."""
    names = list(pooled)
    ax.boxplot([pooled[k] for k in names], orientation="horizontal", widths=0.6, showfliers=False)
    for k, name in enumerate(names):
        v = pooled[name]
        jitter = np.random.default_rng(k).uniform(-0.15, 0.15, len(v))
        ax.plot(v, k + 1 + jitter, ".", ms=2, alpha=0.4, color="tab:blue")
    ax.set_yticks(np.arange(1, len(names) + 1), names, fontsize=8)
    ax.invert_yaxis()
    ax.set_xlim(0, 1.02)
    ax.set_xlabel("highest normalised cross-correlation with another window (1 = exact repeat)")


def plot_spectra(ax: Axes, spectra: dict) -> None:
    """Power spectra of PC 1 of one subject's variation sequences, one curve per source (log-log)."""
    styles = {"recorded": dict(color="k", lw=2.0), "white": dict(color="0.6", ls=":")}
    for name, psd in spectra["psd"].items():
        style = next((v for k, v in styles.items() if name.startswith(k)), {})
        ax.loglog(spectra["freqs"], psd, label=name, **{"lw": 1.2, **style})
    ax.set_xlabel("frequency (Hz)")
    ax.set_ylabel("power spectral density of PC 1")
    ax.legend(fontsize=7)


def plot_speed(ax: Axes, table) -> None:
    """Frames generated per second per subject against the playback rate (log scale)."""
    x = np.arange(len(table))
    bars = ax.bar(
        x, table["frames_per_second"], color="tab:blue", label="generated (balance + variations + PC -> rotations)"
    )
    ax.bar_label(bars, labels=[f"{r:.0f}x" for r in table["realtime_ratio"]], fontsize=8)
    ax.axhline(float(table["playback_fps"].iloc[0]), color="tab:red", ls="--", label="playback rate")
    ax.set_yscale("log")
    ax.set_ylim(float(table["playback_fps"].min()) / 5, float(table["frames_per_second"].max()) * 30)
    ax.set_xticks(x, [f"subject {s}" for s in table["subject"]], fontsize=8)
    ax.set_ylabel("frames per second")
    ax.legend(fontsize=8, loc="upper center")


def draw_categories(result: EvaluationResult) -> Figure:
    """Fig. 3: the category transition graphs of the subjects in ``figure["graphs"]``
    (:func:`~motionvar.egges2004.evaluations.fig3_categories.category_check`)."""
    graphs = result.figure["graphs"]
    fig, axes = plt.subplots(1, len(graphs), figsize=(4.2 * len(graphs), 4.4), squeeze=False)
    for ax, (s, graph) in zip(axes[0], graphs.items()):
        plot_category_graph(ax, graph, f"subject {s}")
    fig.suptitle(
        "Category transition graphs: P(c1 => c2) on the arrows, T_min - T_max in the nodes (Fig. 3)", fontsize=10
    )
    fig.tight_layout()
    return fig


def draw_fitting(result: EvaluationResult) -> Figure:
    """Fig. 4 (a database shift fitted to new ends), a stretch of balance shifting with
    its fitted shifts, and the largest junction step per subject and ramp
    (:func:`~motionvar.egges2004.evaluations.fitting.fitting`)."""
    f, table = result.figure, result.table
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.2), gridspec_kw={"width_ratios": [1, 1.6, 1]})
    plot_fitted_animation(axes[0], f["original"], f["fitted"], f["p"], f["q"], f["fps"])
    axes[0].set_title(f"Fig. 4: a database shift fitted to new ends (subject {f['subject']})", fontsize=9)
    t = np.arange(len(f["balance"])) / f["fps"]
    axes[1].plot(t, f["balance"], color="0.2", lw=1)
    for start, stop in f["shifts_s"]:
        axes[1].axvspan(start, stop, color="tab:orange", alpha=0.3, lw=0)
    axes[1].set_xlabel("time (s)")
    axes[1].set_ylabel("PC 1")
    axes[1].set_title(
        f"{f['balance_s']:g} s of balance shifting: rests and fitted shifts (shaded) join without jumps", fontsize=9
    )
    sub = table[table.test.str.startswith("fitAnim")]
    for ramp, off in (("linear", -0.2), ("smoothstep", 0.2)):
        rows = sub[sub.ramp == ramp]
        axes[2].bar(np.arange(len(rows)) + off, rows["max_junction_step_ratio"], 0.4, label=f"{ramp} offset")
    quantile = f"{100 * f['quantile']:g} % quantile inside recorded shifts"
    axes[2].axhline(1.0, color="tab:red", ls="--", lw=1, label=quantile)
    axes[2].set_xticks(np.arange(len(sub.subject.unique())), sub.subject.unique(), fontsize=7)
    axes[2].set_xlabel("subject")
    axes[2].set_ylabel("largest junction step / recorded step")
    axes[2].legend(fontsize=8)
    axes[2].set_title("continuity at the junctions", fontsize=9)
    fig.tight_layout()
    return fig


def draw_identification(result: EvaluationResult) -> Figure:
    """Accuracy per source and feature set, and the confusion matrix of the generated
    windows (:func:`~motionvar.egges2004.evaluations.identification.identification`)."""
    f = result.figure
    fig, (a, b) = plt.subplots(1, 2, figsize=(12, 4.6), gridspec_kw={"width_ratios": [1.5, 1]})
    plot_identification(a, b, result.table, f)
    a.set_title(f"Who is it? {len(f['labels'])} subjects, {f['window_s']:g}-s windows", fontsize=10)
    fig.tight_layout()
    return fig


def draw_repetition(result: EvaluationResult) -> Figure:
    """Best-match normalised cross-correlation per source
    (:func:`~motionvar.egges2004.evaluations.repetition.repetition`)."""
    f = result.figure
    spectra = f.get("spectra")
    fig, axes = plt.subplots(1, 2 if spectra else 1, figsize=(16 if spectra else 10, 4.6), squeeze=False)
    plot_repetition(axes[0, 0], f["pooled"])
    axes[0, 0].set_title(
        f"Repetition within {f['sequence_s']:g}-s sequences ({f['window_s']:g}-s windows, first {f['n_pcs']} PCs)",
        fontsize=10,
    )
    if spectra:
        plot_spectra(axes[0, 1], spectra)
        axes[0, 1].set_title(f"Structure: spectra of the variations, subject {spectra['subject']}", fontsize=10)
    fig.tight_layout()
    return fig


def draw_pc_extrema(data: dict) -> Figure:
    """Fig. 7-8, one panel per subject
    (:func:`~motionvar.egges2004.evaluations.fig7_8_extrema.pc_extrema`)."""
    panels = data["panels"]
    fig, axes = plt.subplots(len(panels), 1, figsize=(10, 3.2 * len(panels)), squeeze=False)
    for ax, p in zip(axes[:, 0], panels):
        plot_pc_extrema(ax, p["x"], p["fps"], p["extrema"], p["is_max"], data["pc"])
        ax.set_title(
            f"subject {p['subject']}, clip {p['clip']}: longest resting segment, epsilon = {data['eps_sd']:g} SD",
            fontsize=9,
        )
    fig.tight_layout()
    return fig


def draw_speed(result: EvaluationResult) -> Figure:
    """Frames generated per second per subject against the playback rate
    (:func:`~motionvar.egges2004.evaluations.speed.speed`)."""
    fig, ax = plt.subplots(figsize=(7, 4))
    plot_speed(ax, result.table)
    f = result.figure
    ax.set_title(f"Idle motion generation, {f['sequence_s']:g}-s sequences, on {f.get('cpu', 'this CPU')}", fontsize=10)
    fig.tight_layout()
    return fig
