"""Rule du2022_fda_basis (Du 2022 Sec. 3.3.3, Fig. 3.9): joint-space RMSE of the B-spline
functions of every primitive for each candidate number of basis functions K, and the K
chosen per primitive (n_basis.csv, read by the other Du 2022 ch. 3 rules)."""


def main(snakemake) -> None:
    from _du2022_fda import canonical
    from _rule import config_settings

    from motionvar.du2022.fda import choose_basis_sizes

    settings = config_settings(snakemake, "du2022_fda")
    rmse, chosen = choose_basis_sizes(canonical(snakemake), settings.basis)
    rmse.to_csv(snakemake.output.rmse, index=False)
    chosen.to_csv(snakemake.output.n_basis, index=False)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
