"""Figures of the Du 2022 ch. 4 evaluations: each ``draw_*`` takes the
:class:`~motionvar.claims.EvaluationResult` of the matching ``evaluate_*``
(:mod:`motionvar.du2022.graph.evaluations`) and returns a matplotlib Figure;
:func:`animate_fig4_10` writes the Fig. 4.10 animation (GIF)."""

from __future__ import annotations

import matplotlib.pyplot as plt
import matplotlib.ticker
import numpy as np

from ...claims import EvaluationResult
from ...plots import animate_motions, draw_pose, project
from .evaluations.fig4_12 import CONSTRAINT_KINDS, METHODS

METHOD_COLOURS = {
    "kmeans": "tab:blue",
    "gmm": "tab:orange",
    "median": "tab:green",
    "median_budget": "tab:cyan",
    "median_means": "tab:olive",
    "random": "tab:red",
    "brute_force": "0.5",
}
UNITS = {"position": "cm", "orientation": "deg", "pose": "cm per joint"}
AXIS = "xyz"


def draw_fig4_9(result: EvaluationResult) -> plt.Figure:
    """Fig. 4.9: per case and projection, the samples' density (colour), its ``level``
    region (white line), the training clips (red) and their ``level`` region (red dashes)."""
    f = result.figure
    panels = f["panels"]
    n_views = len({p["view"] for p in panels})
    n_cases = len(panels) // n_views
    fig, axes = plt.subplots(n_cases, n_views, figsize=(4.2 * n_views, 3.6 * n_cases), squeeze=False)
    for n, p in enumerate(panels):
        ax = axes[n // n_views, n % n_views]
        a, b = p["axes"]
        dens = p["density"].T
        (x0, x1), (y0, y1) = p["bounds"]
        ax.imshow(
            dens, origin="lower", extent=(x0, x1, y0, y1), cmap="viridis", aspect="equal", interpolation="bilinear"
        )
        ax.contour(p["x"], p["y"], dens, levels=[p["threshold"]], colors="white", linewidths=1.2)
        if "training_density" in p:
            ax.contour(
                p["x"],
                p["y"],
                p["training_density"].T,
                levels=[p["training_threshold"]],
                colors="red",
                linewidths=0.9,
                linestyles="dashed",
            )
        ax.scatter(p["training"][:, a], p["training"][:, b], s=6, c="red", edgecolors="none", label="training clips")
        ax.set_xlabel(f"{AXIS[a]} (cm)", fontsize=8)
        ax.set_ylabel(f"{AXIS[b]} (cm)", fontsize=8)
        ax.tick_params(labelsize=7)
        both = f", samples inside {p['samples_inside']:.2f}" if "samples_inside" in p else ""
        ax.set_title(f"{p['primitive']}, {p['joint']}, {p['view']}\ncoverage {p['coverage']:.2f}{both}", fontsize=9)
        if n == 0:
            ax.legend(fontsize=7, loc="upper right")
    fig.suptitle(
        f"Last-frame end effectors: density of {f['n_samples']} sampled motions (colour, white line: "
        f"{f['level']:.0%} region) and training clips (red dots; dashed: their {f['level']:.0%} region)",
        fontsize=10,
    )
    fig.tight_layout()
    return fig


def draw_fig4_10(result: EvaluationResult) -> plt.Figure:
    """Fig. 4.10: left, the path and the generated walk (hips, feet, step ends) from
    above; right, the last frame of each reaching motion beside its target."""
    f = result.figure
    walk, steps, path, hips = f["walk"], f["steps"], f["path"], f["hips"]
    fig, (ax0, ax1) = plt.subplots(1, 2, figsize=(12, 5), gridspec_kw=dict(width_ratios=[1.1, 1]))
    pos = walk.positions()
    ax0.plot(path[:, 0], path[:, 1], color="0.6", linewidth=6, alpha=0.5, label="path constraint")
    ax0.plot(pos[:, hips, 0], pos[:, hips, 2], color="tab:blue", linewidth=1.5, label="hips of the generated walk")
    for (name, v), style in zip(f.get("variants", {}).items(), ("--", ":")):
        vp = v["walk"].positions()[:, hips]
        ax0.plot(
            vp[:, 0],
            vp[:, 2],
            style,
            color="0.35",
            linewidth=1.0,
            label=f"hips, {v.get('label', name)}: {v['mean_step_cm']:.1f} cm/step, max {v['max_deviation_cm']:.0f} cm off",
        )
    for (foot, j), colour in zip(f["feet"].items(), ("tab:cyan", "tab:red")):
        ax0.plot(pos[::4, j, 0], pos[::4, j, 2], ".", color=colour, markersize=2, label=foot.replace("_", " "))
    for st in steps:
        e = st.motion.positions()[-1, hips]
        ax0.plot(e[0], e[2], "k|", markersize=8)
    ax0.set_aspect("equal")
    ax0.set_xlabel("x (cm)")
    ax0.set_ylabel("z (cm)")
    ax0.set_title(
        f"Path following: {len(steps)} primitives "
        f"({', '.join(s.primitive.replace('walk_', '') for s in steps[:3])}, ...)"
        + (f"\n{f['mode']}" if f.get("mode") else ""),
        fontsize=8,
    )
    ax0.legend(fontsize=7, loc="best")
    spacing = 90.0
    rows, natural = f.get("reach_rows", []), f.get("natural_log_prob")
    for k, (m, t) in enumerate(zip(f["reaches"], f["targets"])):
        p = m.positions()
        xy = project(p[-1], (1.0, 0.0, 0.0), azimuth_deg=30.0)  # from the side, turned to part the arms
        txy = project(t, (1.0, 0.0, 0.0), azimuth_deg=30.0)
        shift = k * spacing - xy[0, 0]
        xy[:, 0] += shift
        draw_pose(ax1, xy, m.skeleton.parents, m.skeleton.names)
        ax1.plot(txy[0] + shift, txy[1], "o", color="red", markersize=6)
        if k < len(rows):  # the reach's remaining error and log-likelihood under the pose (red: below natural)
            r = rows[k]
            low = natural is not None and r["log_prob"] < natural
            ax1.annotate(
                f"{r['position_error_cm']:.1f} cm\nlog p {r['log_prob']:.1f}",
                (xy[0, 0], xy[:, 1].min()),
                xytext=(0, -4),
                textcoords="offset points",
                ha="center",
                va="top",
                fontsize=6,
                color="red" if low else "0.3",
            )
    ax1.set_aspect("equal")
    ax1.autoscale_view()
    ax1.set_xlabel("poses side by side (cm)")
    ax1.set_ylabel("height (cm)")
    natural_text = "" if natural is None else f"\nunder each: hand error, log p (red: below natural, {natural:.1f})"
    ax1.set_title(
        f"Reaching with {f['reach_primitive']}: last frame, right-hand targets (red){natural_text}", fontsize=9
    )
    fig.tight_layout()
    return fig


def animate_fig4_10(result: EvaluationResult, path: str, max_seconds: float = 8.0, panel_px: int = 220) -> None:
    """Fig. 4.10 as a GIF at ``path``: the generated walk and the first two reaches."""
    reaches = result.figure["reaches"][:2]
    animate_motions(
        path,
        [result.figure["walk"]] + reaches,
        labels=["path following"] + [f"reach {k + 1}" for k in range(len(reaches))],
        max_seconds=max_seconds,
        panel_px=panel_px,
    )


def _fig4_12_boxes(queries) -> list[tuple[str, object, str]]:
    """(method, beam or None, label) of the boxes of one Fig. 4.12 panel: the k-means tree
    at every beam measured (the verdict beam starred, the budget beam marked +), then the
    other methods."""
    out = []
    km = queries[queries["method"] == "kmeans"]
    beams = sorted(set(km["beam"])) if "beam" in km.columns else [None]
    chosen = set(km.loc[km["selected"], "beam"]) if "selected" in km.columns else set()
    budget = set(km.loc[km["budget_beam"], "beam"]) if "budget_beam" in km.columns else set()
    for b in beams:
        mark = ("*" if b in chosen else "") + ("+" if b in budget else "")
        out.append(("kmeans", b, "k-means" if b is None else f"k-means\nb={b}{mark}"))
    kd = queries.loc[queries["method"] == "median_budget", "beam"] if "beam" in queries.columns else []
    labels = {
        "median": "median\n(kd)",
        "median_budget": f"median\n(kd, b={int(kd.iloc[0]) if len(kd) else '?'})",
        "median_means": "median\n(means)",
        "brute_force": "brute",
    }
    out += [(m, None, labels.get(m, m)) for m in METHODS if m != "kmeans" and m in set(queries["method"])]
    return out


def draw_fig4_12(result: EvaluationResult) -> plt.Figure:
    """Fig. 4.12: box plots of the search errors per primitive (rows) and constraint kind
    (columns), one box per method (the k-means tree at every beam measured; * marks the
    beam of the verdicts), with its mean objective evaluations."""
    queries = result.figure["queries"]
    prims = list(dict.fromkeys(queries["primitive"]))
    kinds = [k for k in CONSTRAINT_KINDS if k in set(queries["kind"])]
    fig, axes = plt.subplots(len(prims), len(kinds), figsize=(4.6 * len(kinds), 2.9 * len(prims)), squeeze=False)
    for i, p in enumerate(prims):
        sub_p = queries[queries["primitive"] == p]
        boxes = _fig4_12_boxes(sub_p)
        for j, k in enumerate(kinds):
            ax = axes[i, j]
            sub = sub_p[sub_p["kind"] == k]
            picked = [sub[(sub["method"] == m) & ((sub["beam"] == b) if b is not None else True)] for m, b, _ in boxes]
            data = [np.maximum(x["error"].to_numpy(), 1e-3) for x in picked]
            bp = ax.boxplot(
                data, whis=(5, 95), showfliers=False, patch_artist=True, medianprops=dict(color="black", linewidth=2)
            )
            for box, (m, _, _) in zip(bp["boxes"], boxes):
                box.set_facecolor(METHOD_COLOURS[m])
                box.set_alpha(0.6)
            ax.set_xticks(range(1, len(boxes) + 1))
            ax.set_xticklabels(
                [f"{lab}\n{x['n_evals'].mean():.0f} ev." for (_, _, lab), x in zip(boxes, picked)], fontsize=6
            )
            ax.set_yscale("log")
            ax.yaxis.set_major_formatter(matplotlib.ticker.FormatStrFormatter("%g"))
            ax.yaxis.set_minor_locator(matplotlib.ticker.LogLocator(subs=(2.0, 5.0)))
            ax.yaxis.set_minor_formatter(matplotlib.ticker.FormatStrFormatter("%g"))
            ax.tick_params(axis="y", labelsize=7)
            ax.grid(axis="y", alpha=0.3)
            ax.set_title(f"{p} - {k}", fontsize=9)
            ax.set_ylabel(f"error ({UNITS[k]})", fontsize=8)
    n = int(len(queries[(queries["method"] == "random")]) / max(1, len(prims) * len(kinds)))
    fig.suptitle(
        f"Search outcome over {queries['n_evals'].max():.0f} latent samples, {n} random constraints per "
        "panel (boxes: quartiles, whiskers 5-95 %, bar: median; ev. = mean objective evaluations)\n"
        "b = beam, * = beam of the verdicts (fixed in advance), + = the largest under the evaluation budget; "
        "median (kd) = the median tree as a kd-tree, greedy and at the k-means tree's evaluations; median (means) = "
        "our variant",
        fontsize=8,
    )
    fig.tight_layout()
    return fig


def draw_sec4_6_1(result: EvaluationResult) -> plt.Figure:
    """Sec. 4.6.1: clip bytes and model bytes per primitive (log scale) with their ratio."""
    t = result.table[result.table["primitive"] != "all"]
    total = result.figure["total"]
    fig, ax = plt.subplots(figsize=(8, 4))
    x = np.arange(len(t))
    ax.bar(x - 0.2, t["data_bytes"] / 1e6, 0.4, label="clips (float64 arrays)", color="tab:gray")
    ax.bar(x + 0.2, t["model_bytes"] / 1e6, 0.4, label="model (npz + json)", color="tab:blue")
    if "half_model_bytes" in t.columns:
        ax.plot(x - 0.2, t["half_data_bytes"] / 1e6, "_", color="black", markersize=14, label="half of the clips")
        ax.plot(x + 0.2, t["half_model_bytes"] / 1e6, "_", color="black", markersize=14, label="model of that half")
    for i, r in enumerate(t["ratio"]):
        ax.text(
            i, max(t["data_bytes"].iloc[i], t["model_bytes"].iloc[i]) / 1e6 * 1.15, f"{r:.0f}x", ha="center", fontsize=8
        )
    ax.set_yscale("log")
    ax.set_xticks(x)
    ax.set_xticklabels(t["primitive"], rotation=30, ha="right", fontsize=8)
    ax.set_ylabel("MB (log scale)")
    growth = (
        f"\nfrom half to all of the clips: models x{total['model_growth']:.2f}, data x{total['data_growth']:.2f}"
        if "model_growth" in total
        else ""
    )
    ax.set_title(
        f"Model vs data size: {total['model_bytes'] / 1e6:.2f} MB of models for "
        f"{total['data_bytes'] / 1e6:.1f} MB of clips ({total['ratio']:.0f}x; thesis: 41 MB vs 4.2 GB){growth}",
        fontsize=9,
    )
    ax.legend(fontsize=8)
    fig.tight_layout()
    return fig
