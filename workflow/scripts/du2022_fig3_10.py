"""Rule du2022_fig3_10 (Du 2022 Fig. 3.10, Sec. 3.3.5-3.3.6): reconstruction error against
the number of latent dimensions in feature and observation space, four methods, from the
du2022_fda_curves files; motionvar.du2022.fda.evaluations.fig3_10."""


def main(snakemake) -> None:
    from _du2022_fda import load_curves
    from _rule import config_settings, write_evaluation

    from motionvar.du2022.fda.evaluations import evaluate_fig3_10
    from motionvar.du2022.fda.figures import draw_fig3_10

    settings = config_settings(snakemake, "fda")
    result = evaluate_fig3_10(load_curves(snakemake.input.curves), settings)
    write_evaluation(snakemake, result, draw_fig3_10, float_format="%.6g")


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
