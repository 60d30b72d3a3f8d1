"""Rule du2022_fda_sfpca (Du 2022 Eq. 3.8, Table 3.1): the SFPCA of one Fig. 3.10 primitive at
Table 3.1's reference dimension, fitted once and saved (.npz + .json, motionvar.io.model_file);
read by du2022_fda_curves and du2022_table3_1 (the same fit, at the same dimension)."""


def main(snakemake) -> None:
    import pandas as pd
    from _du2022_fda import canonical, setup_threads
    from _rule import config_settings

    from motionvar.du2022.fda import functional_primitive, n_basis_of
    from motionvar.du2022.fda.models import fit_reference_sfpca

    setup_threads(snakemake)
    settings = config_settings(snakemake, "du2022_fda")
    primitive = snakemake.wildcards.primitive
    n_basis = n_basis_of(pd.read_csv(snakemake.input.n_basis), primitive, snakemake.input.n_basis)
    fd, _ = functional_primitive(canonical(snakemake), primitive, n_basis)
    model = fit_reference_sfpca(fd, settings)
    model.save(snakemake.output.model)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
