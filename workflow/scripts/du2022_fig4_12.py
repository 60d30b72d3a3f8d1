"""Rule du2022_fig4_12 (Du 2022 Fig. 4.12): search errors of the k-means, GMM and median
trees, random sampling and brute force per primitive and constraint type; box plots,
mean evaluations, and the claims of Sec. 4.6.2."""

METHOD_COLOURS = {"kmeans": "tab:blue", "gmm": "tab:orange", "median": "tab:green", "random": "tab:red",
                  "brute_force": "0.5"}
UNITS = {"position": "cm", "orientation": "deg", "pose": "cm per joint"}


def main(snakemake) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import matplotlib.ticker
    import numpy as np
    import pandas as pd

    from _graph import save
    from motionvar.claims import write_claims
    from motionvar.du2022.graph.evaluation import CONSTRAINT_KINDS, METHODS, summarize_search
    from motionvar.du2022.graph.verdicts import fig4_12_claims

    queries = pd.concat([pd.read_csv(p) for p in snakemake.input.queries], ignore_index=True)
    summary = summarize_search(queries).drop(columns="mean_time_ms")
    summary.to_csv(snakemake.output.table, index=False, float_format="%.6g")
    write_claims(snakemake.output.claims, fig4_12_claims(summary, queries))

    prims = list(dict.fromkeys(queries["primitive"]))
    kinds = [k for k in CONSTRAINT_KINDS if k in set(queries["kind"])]
    fig, axes = plt.subplots(len(prims), len(kinds), figsize=(3.6 * len(kinds), 2.7 * len(prims)), squeeze=False)
    for i, p in enumerate(prims):
        for j, k in enumerate(kinds):
            ax = axes[i, j]
            sub = queries[(queries["primitive"] == p) & (queries["kind"] == k)]
            data = [np.maximum(sub.loc[sub["method"] == m, "error"].to_numpy(), 1e-3) for m in METHODS]
            bp = ax.boxplot(data, whis=(5, 95), showfliers=False, patch_artist=True,
                            medianprops=dict(color="black", linewidth=2))
            for box, m in zip(bp["boxes"], METHODS):
                box.set_facecolor(METHOD_COLOURS[m])
                box.set_alpha(0.6)
            evals = [sub.loc[sub["method"] == m, "n_evals"].mean() for m in METHODS]
            ax.set_xticks(range(1, len(METHODS) + 1))
            ax.set_xticklabels([f"{m.replace('brute_force', 'brute')}\n{e:.0f} ev." for m, e in zip(METHODS, evals)],
                               fontsize=7)
            ax.set_yscale("log")
            ax.yaxis.set_major_formatter(matplotlib.ticker.FormatStrFormatter("%g"))
            ax.yaxis.set_minor_locator(matplotlib.ticker.LogLocator(subs=(2.0, 5.0)))
            ax.yaxis.set_minor_formatter(matplotlib.ticker.FormatStrFormatter("%g"))
            ax.tick_params(axis="y", labelsize=7)
            ax.grid(axis="y", alpha=0.3)
            ax.set_title(f"{p} - {k}", fontsize=9)
            ax.set_ylabel(f"error ({UNITS[k]})", fontsize=8)
    n = int(queries.groupby(["primitive", "kind"]).size().iloc[0] / len(METHODS))
    fig.suptitle(f"Search outcome over {queries['n_evals'].max():.0f} latent samples, {n} random constraints per "
                 "panel (boxes: quartiles, whiskers 5-95 %, bar: median; ev. = mean objective evaluations)",
                 fontsize=9)
    fig.tight_layout()
    save(fig, snakemake.output.figure)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
