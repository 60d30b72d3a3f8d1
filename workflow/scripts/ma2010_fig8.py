"""Rule ma2010_fig8 (Ma 2010 Fig. 8a, Sec. 7.3-7.4): cycles synthesized at one stride with
xi sampled, their spread per joint group against the data's, RBF's and Kriging's
(motionvar.ma2010.evaluations.fig8)."""


def main(snakemake) -> None:
    from _ma2010 import load_walks
    from _rule import write_evaluation

    from motionvar.ma2010.evaluations.fig8 import fig8_fixed_style
    from motionvar.ma2010.figures import draw_fig8

    o = snakemake.params.options
    walks = load_walks(snakemake)
    model = walks.fit_model(o["structure"], o["variogram_model"])
    result = fig8_fixed_style(
        walks, model, o["fig8_variants"], o["seed"], o["variogram_model"], o["spread_ratio_bounds"]
    )
    write_evaluation(snakemake, result, draw_fig8)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
