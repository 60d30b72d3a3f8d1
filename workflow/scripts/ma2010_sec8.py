"""Rule ma2010_sec8 (Ma 2010 Sec. 8): seconds of computation per second of synthesized
walking, on one core (motionvar.ma2010.evaluations.sec8)."""


def main(snakemake) -> None:
    from _ma2010 import load_walks
    from _rule import write_evaluation

    from motionvar.ma2010.evaluations.sec8 import sec8_timing
    from motionvar.ma2010.figures import draw_sec8

    o = snakemake.params.options
    walks = load_walks(snakemake)
    model = walks.fit_model(o["structure"], o["variogram_model"])
    write_evaluation(
        snakemake, sec8_timing(walks, model, o["timing_seconds"], o["timing_repeats"], o["seed"]), draw_sec8
    )


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
