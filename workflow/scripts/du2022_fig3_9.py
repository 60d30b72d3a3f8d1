"""Rule du2022_fig3_9 (Du 2022 Fig. 3.9, Sec. 3.3.3): B-spline RMSE against the number of
basis functions K (from du2022_fda_basis); motionvar.du2022.fda.evaluations.fig3_9."""


def main(snakemake) -> None:
    import pandas as pd
    from _rule import config_settings, write_evaluation

    from motionvar.du2022.fda.evaluations import evaluate_fig3_9
    from motionvar.du2022.fda.figures import draw_fig3_9

    settings = config_settings(snakemake, "fda")
    result = evaluate_fig3_9(pd.read_csv(snakemake.input.rmse), settings)
    write_evaluation(snakemake, result, draw_fig3_9, float_format="%.6g")


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
