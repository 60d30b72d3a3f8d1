"""Rule ma2010_fig7b (Ma 2010 Fig. 7b, Sec. 7.2): reliability over the 2-D style space
(stride of the left and of the right support phase). At every point of a grid around the
examples the model synthesizes a cycle (xi at the network's conditional mean) whose
strides are measured; the error against the requested strides is mapped in colour, and
its rank correlation with the distance to the nearest example is the claim."""


def main(snakemake) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    from scipy.stats import spearmanr

    from _ma2010 import PAPER, PROTOCOL, load_walks, model
    from motionvar.claims import Claim, verdict_from_bool, write_claims
    from motionvar.ma2010.evaluation import reliability_map

    data = load_walks(snakemake)
    o = data.options
    m = model(data)
    table = reliability_map(m, data.clips, data.solver, o["reliability_grid"], o["reliability_margin"])
    table.to_csv(snakemake.output.table, index=False)
    failed = table["stride_error_cm"].isna().to_numpy()
    ranked = np.where(failed, np.inf, table["stride_error_cm"].to_numpy())  # a failed synthesis ranks last
    rho, p = spearmanr(ranked, table["nearest_example_cm"])

    n = o["reliability_grid"]
    gl = table["left_cm"].to_numpy().reshape(n, n)
    gr = table["right_cm"].to_numpy().reshape(n, n)
    err = table["stride_error_cm"].to_numpy().reshape(n, n)
    fig, axes = plt.subplots(1, 2, figsize=(13, 5.2))
    cmap = plt.get_cmap("RdYlBu_r").copy()
    cmap.set_bad("0.35")
    mesh = axes[0].pcolormesh(gl, gr, np.ma.masked_invalid(err), shading="nearest", cmap=cmap)
    fig.colorbar(mesh, ax=axes[0], label="stride error of the synthesized cycle (cm)")
    axes[0].scatter(data.clips.style[:, 0], data.clips.style[:, 1], s=12, facecolor="white", edgecolor="k",
                    label="example cycles")
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
    axes[1].set_title(f"Spearman rho = {rho:.2f} (p = {p:.1g}), {len(table)} grid points")
    fig.suptitle("Ma 2010 Fig. 7b: reliability of the style parameters")
    fig.tight_layout()
    fig.savefig(snakemake.output.figure, dpi=110)
    plt.close(fig)

    write_claims(snakemake.output.claims, [Claim(
        claim_id=f"{PAPER}.fig7b.error_grows_with_distance", paper=PAPER, source="Fig. 7b, Sec. 7.2",
        statement="The distance between a requested style and the examples' styles correlates strongly with the "
                  "(un)reliability of the synthesized motion.",
        published="strong correlation (map, no number)",
        measured=f"Spearman rho = {rho:.2f} (p = {p:.1g}) between stride error and distance to the nearest example, "
                 f"{len(table)} grid points ({int(failed.sum())} failed syntheses ranked last)",
        verdict=verdict_from_bool(rho > 0 and p < 0.05),
        note="Reproduced when rho > 0 at p < 0.05. Reliability = stride error of the synthesized cycle (the paper "
             f"does not define its reliability level). Grid: the examples' range widened by {o['reliability_margin']:g} "
             f"of its extent on each side. {PROTOCOL}",
    )])


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
