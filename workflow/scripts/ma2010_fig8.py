"""Rule ma2010_fig8 (Ma 2010 Fig. 8a, Sec. 7.3-7.4): cycles synthesized at one stride with
xi sampled, their spread per joint group against the data's, RBF's and Kriging's
(motionvar.ma2010.evaluations.fig8)."""


def main(snakemake) -> None:
    from _ma2010 import load_walks, settings
    from _rule import write_evaluation

    from motionvar.ma2010.evaluations.fig8 import fig8_fixed_style
    from motionvar.ma2010.figures import draw_fig8

    s = settings(snakemake)
    walks = load_walks(snakemake, s)
    write_evaluation(snakemake, fig8_fixed_style(walks, walks.fit_model(s), s), draw_fig8)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
