"""Rule du2022_table3_1 (Du 2022 Table 3.1): per motion primitive the number of clips, of
basis functions (the Fig. 3.9 cut-off) and of latent dimensions: the smallest d whose
observation-space reconstruction error reaches a threshold, with SFPCA weights optimised
at a reference dimension (and, for comparison, with FPCA)."""

PUBLISHED = {  # Table 3.1: clips, basis functions, latent dimensions
    "walk_leftStance": (1366, 10, 42),
    "pick_reach": (374, 25, 45),
}


def smallest_dim(error_of, d_max: int, threshold: float):
    """Smallest d in [1, d_max] with error_of(d) <= threshold by bisection (the errors fall
    with d); None if even d_max misses it. Returns (d, {d: error} evaluated)."""
    seen = {}

    def err(d):
        if d not in seen:
            seen[d] = error_of(d)
        return seen[d]

    if err(d_max) > threshold:
        return None, seen
    lo, hi = 0, d_max  # err(hi) <= threshold; lo misses (or is 0)
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if err(mid) <= threshold:
            hi = mid
        else:
            lo = mid
    return hi, seen


def main(snakemake) -> None:
    import logging

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    import pandas as pd

    from _du2022_fda import canonical, plain_log_ticks, primitive_motions, save, setup_threads, sfpca
    from motionvar.claims import write_claims
    from motionvar.du2022.fda import FPCA, FunctionalMotions, WeightedFPCA, observation_error

    setup_threads(snakemake)
    o = snakemake.params.options
    t = o["table"]
    chosen = pd.read_csv(snakemake.input.n_basis)
    dataset = canonical(snakemake)
    rows, curves = [], {}
    for _, c in chosen.iterrows():
        motions, meta = primitive_motions(dataset, c["primitive"])
        fd = FunctionalMotions.from_motions(motions, int(c["n_basis"]))
        d_max = min(t["max_components"], fd.n_clips - 1)
        d_ref = min(t["reference_components"], d_max)
        weighted = sfpca(o, fd, d_ref).fit(fd)
        logging.info("%s: SFPCA(%d) %.1f s, init %s", c["primitive"], d_ref, weighted.fit_time_s_, weighted.init_)
        reference = fd.positions()
        models = {"sfpca": WeightedFPCA(d_max, weighted.function_weights_).fit(fd), "fpca": FPCA(d_max).fit(fd)}
        row = {"primitive": c["primitive"], "behaviour": c["behaviour"], "clips": fd.n_clips,
               "basis_functions": int(c["n_basis"]), "canonical_frames": fd.n_frames, "sfpca_reference_dims": d_ref}
        for name, model in models.items():
            def error(d, model=model):
                return observation_error(fd, model.reconstruct(fd, d), reference=reference)

            d, seen = smallest_dim(error, d_max, t["observation_error_cm"])
            row[f"latent_dims_{name}"] = d if d is not None else np.nan
            row[f"error_at_dims_{name}_cm"] = seen[d] if d is not None else np.nan
            grid = sorted(set(np.unique(np.geomspace(1, d_max, 8).round().astype(int))) | set(seen))
            curves[(c["primitive"], name)] = [(g, seen[g] if g in seen else error(g)) for g in grid]
        pub = PUBLISHED.get(c["primitive"])
        row.update({"published_clips": pub[0] if pub else np.nan, "published_basis": pub[1] if pub else np.nan,
                    "published_dims": pub[2] if pub else np.nan})
        rows.append(row)
    table = pd.DataFrame(rows)
    table.to_csv(snakemake.output.table, index=False, float_format="%.6g")

    fig, axes = plt.subplots(1, 2, figsize=(13, 4.8), sharey=True)
    for ax, name, title in ((axes[0], "sfpca", "SFPCA weights"), (axes[1], "fpca", "FPCA")):
        for primitive in table["primitive"]:
            xy = np.array(curves[(primitive, name)])
            ax.plot(xy[:, 0], xy[:, 1], marker=".", lw=1, label=primitive)
        ax.axhline(t["observation_error_cm"], color="k", ls="--", lw=1, label=f"{t['observation_error_cm']:g} cm")
        ax.set(title=f"{title}: observation-space error vs dimensions", xlabel="latent dimensions", yscale="log",
               xscale="log", ylim=(1e-2, None))  # d = clips - 1 reconstructs exactly: below the axis
        ax.grid(alpha=0.3, which="both")
        plain_log_ticks(ax, "y")
        plain_log_ticks(ax, "x")
    axes[0].set_ylabel("mean joint error (cm)")
    axes[1].legend(fontsize=7, ncol=2)
    fig.suptitle("Du 2022 Table 3.1: latent dimensions per motion primitive", fontsize=11)
    fig.tight_layout()
    save(fig, snakemake.output.figure)
    write_claims(snakemake.output.claims, [])


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
