"""Rule du2022_fda_curves (Du 2022 Fig. 3.10-3.11): the reconstruction errors per number of
latent dimensions and the latent coordinates of one primitive for some of the methods
(FPCA, normalized FPCA, SFPCA, Bayesian GPLVM), as one .npz of arrays (measurements, not a
fitted model: motionvar.du2022.fda.evaluations.curves). SFPCA at Table 3.1's reference
dimension is read from rule du2022_fda_sfpca's file instead of fitted again."""


def main(snakemake) -> None:
    import numpy as np
    import pandas as pd
    from _du2022_fda import canonical, load_sfpca, setup_threads
    from _rule import config_settings

    from motionvar.du2022.fda import functional_primitive, n_basis_of
    from motionvar.du2022.fda.evaluations import reconstruction_curves

    setup_threads(snakemake)
    settings = config_settings(snakemake, "du2022_fda")
    primitive = snakemake.wildcards.primitive
    n_basis = n_basis_of(pd.read_csv(snakemake.input.n_basis), primitive, snakemake.input.n_basis)
    fd, meta = functional_primitive(canonical(snakemake), primitive, n_basis)
    models = load_sfpca(getattr(snakemake.input, "sfpca", [])).values()
    curves = reconstruction_curves(fd, meta["variant"], primitive, snakemake.params.methods, settings, models)
    with open(snakemake.output.curves, "wb") as fh:
        np.savez(fh, **curves)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
