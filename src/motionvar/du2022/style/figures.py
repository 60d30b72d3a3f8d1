"""Figures of the Du 2022 ch. 5 evaluations: the style-distance heat map (Table 5.1),
the diversity bars (Tables 5.2-5.3), training curves, and random samples as stick
figures (Fig. 5.4-5.5: the last frame of each sample, characters started in a line) and
animations.

One function per evaluation takes its :class:`~motionvar.claims.EvaluationResult`:
:func:`draw_table5_1`, :func:`draw_table5_2`, :func:`draw_fig5_4` (a Figure) and
:func:`animate_fig5_4` (GIF frames); :func:`draw_training` draws the training histories.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import matplotlib.pyplot as plt
import numpy as np
import pandas as pd
from matplotlib.figure import Figure
from matplotlib.ticker import MaxNLocator

from ...claims import EvaluationResult
from ...plots.animation import render_frames
from ...plots.stick import draw_pose, project


def _heat(ax, table: pd.DataFrame, title: str) -> None:
    values = table.to_numpy(dtype=float)
    im = ax.imshow(values, cmap="viridis_r")
    ax.set_xticks(range(values.shape[1]), table.columns, rotation=45, ha="right", fontsize=8)
    ax.set_yticks(range(values.shape[0]), table.index, fontsize=8)
    ax.set_xlabel("style example s", fontsize=9)
    ax.set_ylabel("model m", fontsize=9)
    ax.set_title(title, fontsize=10)
    mid = np.nanmean(values)
    for i in range(values.shape[0]):
        j_min = int(np.nanargmin(values[i]))
        for j in range(values.shape[1]):
            txt = f"{values[i, j]:.3g}"
            ax.text(
                j,
                i,
                txt,
                ha="center",
                va="center",
                fontsize=6.5,
                color="white" if values[i, j] > mid else "black",
                fontweight="bold" if j == j_min else "normal",
            )
        ax.add_patch(plt.Rectangle((j_min - 0.5, i - 0.5), 1, 1, fill=False, ec="red", lw=1.5))
    plt.colorbar(im, ax=ax, fraction=0.046, pad=0.04)


def distance_heatmap(measured: pd.DataFrame, published: pd.DataFrame | None = None) -> Figure:
    """Table 5.1 as heat maps: ours (and the thesis'); each row's minimum is boxed red."""
    n = 2 if published is not None else 1
    fig, axes = plt.subplots(1, n, figsize=(5.6 * n, 5.0), squeeze=False)
    _heat(axes[0, 0], measured, "measured D(m, s) (Eq. 5.12)")
    if published is not None:
        _heat(axes[0, 1], published.loc[measured.index, measured.columns], "published (Du 2022, Table 5.1)")
    fig.tight_layout()
    return fig


def diversity_figure(table: pd.DataFrame, measures: Sequence[str] = ("pose_sd", "v_sd", "step_sd")) -> Figure:
    """Tables 5.2-5.3 as bars relative to the training data (so that our centimetres and
    the thesis' rig units compare): one panel per primitive and measure, measured and
    published bars per model. ``table`` has columns primitive, model, the measures and
    ``published_<measure>``; where it has them, ``training_<measure>`` (the clips of each
    model's own style: the neutral clips for the neutral VAE, the style's clips for a CVAE) and ``posterior_mean_<measure>`` are drawn as markers on the measured bars."""
    prims = list(dict.fromkeys(table["primitive"]))
    fig, axes = plt.subplots(len(prims), len(measures), figsize=(4.2 * len(measures), 3.0 * len(prims)), squeeze=False)
    for r, prim in enumerate(prims):
        t = table[table["primitive"] == prim].set_index("model")
        models = list(t.index)
        x = np.arange(len(models))
        for c, m in enumerate(measures):
            ax = axes[r, c]
            ours = t[m] / t.loc["training data", m]
            ax.bar(x - 0.2, ours, 0.4, label="measured", color="#1f77b4")
            pub = t.get(f"published_{m}")
            if pub is not None and pd.notna(pub.get("training data")):
                ok = pub.notna().to_numpy()  # the thesis has no row for our baselines
                ax.bar(x[ok] + 0.2, (pub / pub.loc["training data"])[ok], 0.4, label="published", color="#ff7f0e")
            for col, marker, label in (
                (f"training_{m}", "_", "own style's clips"),
                (f"posterior_mean_{m}", ".", "at the posterior means"),
            ):
                if col in t and t[col].notna().any():
                    ax.scatter(
                        x - 0.2,
                        t[col] / t.loc["training data", m],
                        marker=marker,
                        s=110,
                        color="k",
                        zorder=3,
                        label=label,
                    )
            ax.axhline(1.0, color="0.4", lw=0.8, ls="--")
            ax.set_xticks(x, models, rotation=45, ha="right", fontsize=7)
            ax.set_title(f"{prim}: {m.replace('_sd', '_SD')} / training", fontsize=9)
            ax.tick_params(axis="y", labelsize=7)
            if r == 0 and c == 0:
                fig.legend(*ax.get_legend_handles_labels(), loc="upper right", fontsize=8, ncol=4)
    fig.tight_layout(rect=(0, 0, 1, 0.95))
    return fig


def training_curves(histories: Mapping[str, pd.DataFrame], groups: Mapping[str, Sequence[str]]) -> Figure:
    """Loss per epoch (log scale), one panel per group of runs (e.g. autoencoder, VAEs,
    CVAEs of a primitive; a ring marks the epoch whose weights were kept when it is not
    the last, :func:`~.training.train_autoencoder`); when some histories have an ``active`` column (latent
    dimensions in use, :func:`~.training.train_vae`), a second row of panels draws it."""
    with_active = [any("active" in histories[n] for n in names) for names in groups.values()]
    n_rows = 2 if any(with_active) else 1
    fig, axes = plt.subplots(n_rows, len(groups), figsize=(4.4 * len(groups), 3.4 * n_rows), squeeze=False)
    for c, (title, names) in enumerate(groups.items()):
        ax = axes[0, c]
        for name in names:
            h = histories[name]
            (line,) = ax.plot(h["epoch"], h["loss"], label=name, lw=1.2)
            if "kept" in h and h["kept"].any() and not h["kept"].iloc[-1]:  # weights of an earlier epoch kept
                k = h.loc[h["kept"]].iloc[0]
                ax.plot(
                    [k["epoch"]],
                    [k["loss"]],
                    marker="o",
                    mfc="none",
                    color=line.get_color(),
                    ms=6,
                    label=f"{name}: kept epoch {int(k['epoch'])}",
                )
        ax.set_yscale("log")
        ax.set_xlabel("epoch", fontsize=8)
        ax.set_ylabel("training loss", fontsize=8)
        ax.set_title(title, fontsize=9)
        ax.tick_params(labelsize=7)
        ax.legend(fontsize=6)
        if n_rows == 2:
            ax = axes[1, c]
            if not with_active[c]:
                ax.set_axis_off()
                continue
            top = 1
            for name in names:
                h = histories[name]
                if "active" in h:
                    ax.plot(h["epoch"], h["active"], label=name, lw=1.2, marker=".", ms=3)
                    top = max(top, int(h["active"].max()))
            ax.set_ylim(-0.5, top + 1)
            ax.yaxis.set_major_locator(MaxNLocator(integer=True))
            ax.set_xlabel("epoch", fontsize=8)
            ax.set_ylabel("latent dimensions in use", fontsize=8)
            ax.set_title(f"{title}: active units", fontsize=9)
            ax.tick_params(labelsize=7)
    fig.tight_layout()
    return fig


def samples_figure(
    rows: Sequence[tuple[str, np.ndarray, np.ndarray | None]],
    parents: np.ndarray,
    names: Sequence[str],
    spacing_cm: float = 75.0,
    azimuth_deg: float = -35.0,
    elevation_deg: float = 8.0,
) -> Figure:
    """Fig. 5.4/5.5: per row a label, samples' positions (n, T, J, 3) (starting at the
    origin facing +x) and optionally a style example's positions (T, J, 3), drawn left of
    the samples in grey. Each character starts ``spacing_cm`` to the side of the one
    before; the last frame is drawn, seen from the front-side."""
    n_cols = max(len(p) for _, p, _ in rows)
    fig, axes = plt.subplots(
        len(rows), 1, figsize=(max(5.5, 1.0 + 0.9 * (n_cols + 1.5)), 1.9 * len(rows)), squeeze=False
    )
    screen = np.array([0.0, 0.0, 1.0])
    for ax, (label, samples, example) in zip(axes[:, 0], rows):
        lateral = np.array([0.0, 0.0, spacing_cm])
        xs = []
        for k, pos in enumerate(samples):
            last = pos[-1] + (k + 1.5) * lateral
            xy = project(last, screen, elevation_deg, azimuth_deg)
            draw_pose(ax, xy, parents, names, linewidth=1.6)
            xs.append(xy[:, 0])
        if example is not None:
            xy = project(example[-1], screen, elevation_deg, azimuth_deg)
            draw_pose(ax, xy, parents, None, linewidth=1.6).set_color("0.6")
            ax.text(
                float(xy[:, 0].mean()), float(xy[:, 1].max()) + 8, "style example", ha="center", fontsize=7, color="0.4"
            )
            xs.append(xy[:, 0])
        allx = np.concatenate(xs)
        ax.set_xlim(allx.min() - 20, allx.max() + 20)
        ax.set_ylim(-5, 195)
        ax.set_aspect("equal")
        ax.set_xticks([])
        ax.set_yticks([])
        for s in ax.spines.values():
            s.set_visible(False)
        ax.set_title(label, fontsize=8, loc="left")
    fig.tight_layout()
    return fig


def draw_table5_1(result: EvaluationResult) -> Figure:
    """Table 5.1 (:func:`~.evaluations.evaluate_table5_1`): measured and published heat maps."""
    return distance_heatmap(result.figure["measured"], result.figure["published"])


def draw_table5_2(result: EvaluationResult) -> Figure:
    """Tables 5.2-5.3 (:func:`~.evaluations.evaluate_table5_2`): diversity bars."""
    return diversity_figure(result.figure["table"])


def draw_fig5_4(result: EvaluationResult) -> Figure:
    """Fig. 5.4-5.5 (:func:`~.evaluations.evaluate_fig5_4`): the samples' last frames."""
    f = result.figure
    return samples_figure(f["rows"], f["parents"], f["names"])


def animate_fig5_4(result: EvaluationResult, group: str, panel_px: int, loops: int = 3) -> np.ndarray:
    """RGB frames (N, H, W, 3) of one sample per model of ``group`` ("neutral" or
    "styles") side by side, each clip played ``loops`` times in a row (moving on from
    where it ended, so that a half-second step can be watched)."""
    f = result.figure
    clips = f["animations"][group]
    if not clips:
        raise ValueError(f"du2022_fig5_4: no {group} models to animate")
    # loop i starts where the clip ended: shifted by i times its net root travel along x
    pos = [
        np.concatenate([p + np.array([i * (p[-1, 0, 0] - p[0, 0, 0]), 0, 0]) for i in range(loops)])
        for p, _, _ in clips
    ]
    return render_frames(
        pos,
        [f["parents"]] * len(clips),
        [fps for _, fps, _ in clips],
        names=[f["names"]] * len(clips),
        labels=[label for _, _, label in clips],
        panel_px=panel_px,
    )


def draw_training(
    autoencoder: pd.DataFrame,
    vaes: Mapping[str, pd.DataFrame],
    cvaes: Mapping[tuple[str, str], pd.DataFrame],
) -> Figure:
    """Training curves (:func:`training_curves`) of the autoencoder, the neutral VAEs (by
    primitive) and the CVAEs (by (primitive, style), one panel per primitive)."""
    histories = {"autoencoder": autoencoder, **vaes}
    groups = {"conv autoencoder (Eq. 5.1-5.2)": ["autoencoder"], "neutral VAEs (Eq. 5.6)": list(vaes)}
    for (primitive, style), h in cvaes.items():
        histories[f"{primitive}/{style}"] = h
        groups.setdefault(f"CVAEs {primitive} (Eq. 5.11)", []).append(f"{primitive}/{style}")
    return training_curves(histories, groups)
