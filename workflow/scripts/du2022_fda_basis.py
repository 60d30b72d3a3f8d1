"""Rule du2022_fda_basis (Du 2022 Sec. 3.3.3, Fig. 3.9): joint-space RMSE between the B-spline
functions and the canonical frames of every primitive for each candidate number of basis
functions K, and the K chosen per primitive by the cut-off rule (n_basis.csv, read by the
other Du 2022 ch. 3 rules)."""


def main(snakemake) -> None:
    import numpy as np
    import pandas as pd

    from _du2022_fda import canonical, primitive_motions
    from motionvar.du2022.fda import bspline_fit_rmse, choose_n_basis

    o = snakemake.params.options["basis"]
    dataset = canonical(snakemake)
    rows, chosen = [], []
    for primitive in sorted(dataset.metadata["primitive"].unique()):
        motions, meta = primitive_motions(dataset, primitive)
        T = motions[0].n_frames
        ks = [k for k in sorted(o["n_basis"]) if k <= T]
        if not ks:
            raise ValueError(f"config fda.basis.n_basis: every K exceeds the {T} canonical frames of {primitive}")
        rmse = bspline_fit_rmse(motions, ks)
        K = choose_n_basis(np.array(ks), np.array(rmse), o["min_relative_drop"])
        behaviour = meta["behaviour"].iloc[0]
        chosen.append({"primitive": primitive, "behaviour": behaviour, "n_basis": K, "n_clips": len(motions),
                       "canonical_frames": T})
        rows += [{"primitive": primitive, "behaviour": behaviour, "n_clips": len(motions), "canonical_frames": T,
                  "n_basis": k, "rmse_cm": r, "chosen": k == K} for k, r in zip(ks, rmse)]
    pd.DataFrame(rows).to_csv(snakemake.output.rmse, index=False)
    pd.DataFrame(chosen).to_csv(snakemake.output.n_basis, index=False)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
