"""Rule ma2010_variogram (Ma 2010 Sec. 6.1-6.2): the empirical semivariograms of the Kriging
residuals per joint group and for Kriging on style alone, with the fitted variograms
(motionvar.ma2010.evaluations.variogram)."""


def main(snakemake) -> None:
    from _ma2010 import load_walks, settings
    from _rule import write_evaluation

    from motionvar.ma2010.evaluations.variogram import variogram_fits
    from motionvar.ma2010.figures import draw_variogram

    s = settings(snakemake)
    write_evaluation(snakemake, variogram_fits(load_walks(snakemake, s), s), draw_variogram)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
