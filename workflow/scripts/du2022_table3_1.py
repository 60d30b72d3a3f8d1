"""Rule du2022_table3_1 (Du 2022 Table 3.1): clips, basis functions and latent dimensions
per motion primitive (SFPCA weights at a reference dimension: rule du2022_fda_sfpca's for the
Fig. 3.10 primitives, fitted here for the others; and FPCA); motionvar.du2022.fda.evaluations.table3_1."""


def main(snakemake) -> None:
    import pandas as pd
    from _du2022_fda import canonical, load_sfpca
    from _rule import config_settings, write_evaluation

    from motionvar.du2022.fda.evaluations import evaluate_table3_1
    from motionvar.du2022.fda.figures import draw_table3_1

    settings = config_settings(snakemake, "fda")
    chosen = pd.read_csv(snakemake.input.n_basis)
    result = evaluate_table3_1(canonical(snakemake), chosen, settings, sfpca_models=load_sfpca(snakemake.input.sfpca))
    write_evaluation(snakemake, result, draw_table3_1, float_format="%.6g")


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
