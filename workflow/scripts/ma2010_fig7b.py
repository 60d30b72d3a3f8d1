"""Rule ma2010_fig7b (Ma 2010 Fig. 7b, Sec. 7.2): reliability of the model over the 2-D
style space (motionvar.ma2010.evaluations.fig7b)."""


def main(snakemake) -> None:
    from _ma2010 import load_walks, settings
    from _rule import write_evaluation

    from motionvar.ma2010.evaluations.fig7b import fig7b_reliability
    from motionvar.ma2010.figures import draw_fig7b

    s = settings(snakemake)
    walks = load_walks(snakemake, s)
    write_evaluation(snakemake, fig7b_reliability(walks, walks.fit_model(s), s), draw_fig7b)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
