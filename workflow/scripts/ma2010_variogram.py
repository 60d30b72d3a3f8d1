"""Rule ma2010_variogram (Ma 2010 Sec. 6.1-6.2): the empirical semivariograms of the Kriging
residuals per joint group and for Kriging on style alone, with the fitted variograms
(motionvar.ma2010.evaluations.variogram)."""


def main(snakemake) -> None:
    from _ma2010 import load_walks
    from _rule import write_evaluation

    from motionvar.ma2010.evaluations.variogram import variogram_fits
    from motionvar.ma2010.figures import draw_variogram

    o = snakemake.params.options
    walks = load_walks(snakemake)
    result = variogram_fits(walks, o["structure"], o["variogram_model"], o["variogram_scale"], o["seed"])
    write_evaluation(snakemake, result, draw_variogram)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
