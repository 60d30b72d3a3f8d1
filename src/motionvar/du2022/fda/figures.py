"""Figures of the Du 2022 ch. 3 evaluations (:mod:`motionvar.du2022.fda.evaluations`):
each ``draw_*`` takes the evaluation's :class:`motionvar.claims.EvaluationResult` and
returns a matplotlib Figure (B-spline RMSE curves, reconstruction error curves, t-SNE maps
of the latent spaces, latent dimensions per primitive).
"""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.figure import Figure
from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter

from ...claims import EvaluationResult

METHOD_LABELS = {
    "fpca": "FPCA",
    "normalized_fpca": "normalized FPCA",
    "sfpca": "SFPCA",
    "gplvm": "Bayesian GPLVM",
    "normalized_fpca_floored": "normalized FPCA, SD floored",
    "root_scaled_fpca": "root-scaled FPCA (author's code)",
}
METHOD_STYLES = {
    "fpca": dict(color="tab:blue", marker="o"),
    "normalized_fpca": dict(color="tab:orange", marker="s"),
    "sfpca": dict(color="tab:green", marker="^"),
    "gplvm": dict(color="tab:red", marker="D"),
    "normalized_fpca_floored": dict(color="tab:orange", marker="v", ls="--"),
    "root_scaled_fpca": dict(color="tab:purple", marker="x", ls=":"),
}


def plain_log_ticks(ax, axis: str = "y") -> None:
    """Ticks of a log axis at 1, 2, 5 x 10^k, labelled as plain numbers (0.2, 0.5, 1, 2)."""
    target = ax.yaxis if axis == "y" else ax.xaxis
    target.set_major_locator(LogLocator(base=10, subs=(1.0, 2.0, 5.0)))
    target.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}"))
    target.set_minor_formatter(NullFormatter())


def draw_fig3_9(result: EvaluationResult) -> Figure:
    """Fig. 3.9: RMSE against K, pooled per behaviour (left) and per primitive with the
    chosen K circled and the equal-error RMSEs of the complex-motion claim dashed (right)."""
    pooled, table = result.figure["pooled"], result.figure["per_primitive"]
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.6))
    for behaviour, g in pooled.groupby("behaviour"):
        axes[0].plot(g["n_basis"], g["rmse_cm"], marker="o", label=behaviour)
    axes[0].set(
        title="Per behaviour (pooled over its primitives)",
        xlabel="number of basis functions K",
        ylabel="joint-space RMSE (cm)",
        yscale="log",
    )
    axes[0].legend(fontsize=8)
    palette = plt.cm.tab20.colors  # dark tones first, then the light ones: 20 distinct colours
    for i, (primitive, g) in enumerate(table.groupby("primitive")):
        color = palette[(2 * i) % 20 + (2 * i // 20) % 2]
        axes[1].plot(g["n_basis"], g["rmse_cm"], marker=".", lw=1, label=primitive, color=color)
        c = g[g["chosen"]]
        axes[1].plot(c["n_basis"], c["rmse_cm"], "o", ms=9, mfc="none", color=color)
    for t in result.figure["equal_error_cm"]:  # the complex-motion claim's RMSEs
        axes[1].axhline(t, color="0.5", ls="--", lw=0.8)
    drop = result.figure["min_relative_drop"]
    axes[1].set(
        title=f"Per primitive (circle: chosen K, cut-off {drop:.0%} per added function;\n"
        "dashed: the RMSEs of the equal-error claim)",
        xlabel="number of basis functions K",
        ylabel="joint-space RMSE (cm)",
        yscale="log",
    )
    axes[1].legend(fontsize=7, ncol=2)
    for ax in axes:
        ax.grid(alpha=0.3, which="both")
        plain_log_ticks(ax)
    fig.suptitle("Du 2022 Fig. 3.9: cubic B-spline representation of canonical clips", fontsize=11)
    fig.tight_layout()
    return fig


def draw_fig3_10(result: EvaluationResult) -> Figure:
    """Fig. 3.10: per primitive (rows) the feature-space and observation-space error
    against the number of latent dimensions, one curve per method."""
    table, methods, primitives = (result.figure[k] for k in ("table", "methods", "primitives"))
    fig, axes = plt.subplots(len(primitives), 2, figsize=(12, 4.2 * len(primitives)), squeeze=False)
    for r, primitive in enumerate(primitives):
        sub = table[table["primitive"] == primitive]
        for c, (col, label) in enumerate(
            [
                ("feature_error", "feature space (functional norm)"),
                ("observation_error_cm", "observation space: mean joint error (cm)"),
            ]
        ):
            ax = axes[r, c]
            for method in methods:
                g = sub[sub["method"] == method].sort_values("dims")
                ax.plot(g["dims"], g[col], label=METHOD_LABELS[method], ms=5, **METHOD_STYLES[method])
            n = int(sub["n_clips"].iloc[0])
            ax.set(
                title=f"{primitive} ({n} clips, K={int(sub['n_basis'].iloc[0])}): {label.split(':')[0]}",
                xlabel="number of latent dimensions",
                ylabel=label,
                yscale="log",
            )
            ax.grid(alpha=0.3, which="both")
            plain_log_ticks(ax)
            ax.legend(fontsize=8)
    fig.suptitle("Du 2022 Fig. 3.10: average reconstruction error vs latent dimensions", fontsize=11)
    fig.tight_layout()
    return fig


def draw_fig3_11(result: EvaluationResult) -> Figure:
    """Fig. 3.11: the t-SNE map of every (primitive, method) latent space, coloured by label."""
    panels, k = result.figure["panels"], result.figure["knn"]
    n_rows, n_cols = len(panels), max((len(r) for r in panels), default=0)
    fig, axes = plt.subplots(n_rows, n_cols, figsize=(3.6 * n_cols, 3.6 * n_rows), squeeze=False)
    markers = ["x", "o", "^", "s", "v", "D"]
    colors = ["tab:red", "tab:blue", "tab:green", "tab:purple", "tab:orange", "tab:brown"]
    for r, row in enumerate(panels):
        for c, p in enumerate(row):
            labels, xy = p["labels"], p["xy"]
            ax = axes[r, c]
            for i, lab in enumerate(sorted(np.unique(labels))):
                m = labels == lab
                ax.scatter(
                    xy[m, 0],
                    xy[m, 1],
                    s=10 if len(labels) > 200 else 22,
                    marker=markers[i % 6],
                    color=colors[i % 6],
                    alpha=0.7,
                    label=f"{lab} ({m.sum()})",
                    facecolors="none" if markers[i % 6] in "o^sD" else None,
                )
            ax.set_title(
                f"{p['primitive']}\n{METHOD_LABELS[p['method']]} ({p['dim']}-D): silh. {p['silhouette']:.2f}, "
                f"{k}-NN {p['knn_accuracy']:.0%}",
                fontsize=9,
            )
            ax.set_xticks([])
            ax.set_yticks([])
            if c == 0:
                ax.legend(fontsize=7, loc="best")
    fig.suptitle("Du 2022 Fig. 3.11: t-SNE of the latent spaces, coloured by label", fontsize=11)
    fig.tight_layout()
    return fig


def draw_table3_1(result: EvaluationResult) -> Figure:
    """Table 3.1's figure: observation-space error against the latent dimension per
    primitive, with the SFPCA weights (left) and plain FPCA (right), and the threshold."""
    curves, threshold = result.figure["curves"], result.figure["threshold"]
    fig, axes = plt.subplots(1, 2, figsize=(13, 4.8), sharey=True)
    for ax, name, title in ((axes[0], "sfpca", "SFPCA weights"), (axes[1], "fpca", "FPCA")):
        for primitive in result.figure["primitives"]:
            xy = np.array(curves[(primitive, name)])
            ax.plot(xy[:, 0], xy[:, 1], marker=".", lw=1, label=primitive)
        ax.axhline(threshold, color="k", ls="--", lw=1, label=f"{threshold:g} cm")
        ax.set(
            title=f"{title}: observation-space error vs dimensions",
            xlabel="latent dimensions",
            yscale="log",
            xscale="log",
            ylim=(1e-2, None),
        )  # d = clips - 1 reconstructs exactly: below the axis
        ax.grid(alpha=0.3, which="both")
        plain_log_ticks(ax, "y")
        plain_log_ticks(ax, "x")
    axes[0].set_ylabel("mean joint error (cm)")
    axes[1].legend(fontsize=7, ncol=2)
    fig.suptitle("Du 2022 Table 3.1: latent dimensions per motion primitive", fontsize=11)
    fig.tight_layout()
    return fig
