"""Rule du2022_fig3_11 (Du 2022 Fig. 3.11): t-SNE maps of each method's latent space,
coloured by label, with silhouette and k-NN accuracy measured in the latent space, from
the du2022_fda_curves files; motionvar.du2022.fda.evaluations.fig3_11."""


def main(snakemake) -> None:
    from _du2022_fda import load_curves
    from _rule import config_settings, write_evaluation

    from motionvar.du2022.fda.evaluations import evaluate_fig3_11
    from motionvar.du2022.fda.figures import draw_fig3_11

    settings = config_settings(snakemake, "fda")
    result = evaluate_fig3_11(load_curves(snakemake.input.curves), settings)
    write_evaluation(snakemake, result, draw_fig3_11, float_format="%.6g")


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
