"""Rule ma2010_fig7b (Ma 2010 Fig. 7b, Sec. 7.2): reliability of the model over the 2-D
style space (motionvar.ma2010.evaluations.fig7b)."""


def main(snakemake) -> None:
    from _ma2010 import load_walks
    from _rule import write_evaluation

    from motionvar.ma2010.evaluations.fig7b import fig7b_reliability
    from motionvar.ma2010.figures import draw_fig7b

    o = snakemake.params.options
    walks = load_walks(snakemake)
    model = walks.fit_model(o["structure"], o["variogram_model"])
    write_evaluation(
        snakemake, fig7b_reliability(walks, model, o["reliability_grid"], o["reliability_margin"]), draw_fig7b
    )


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
