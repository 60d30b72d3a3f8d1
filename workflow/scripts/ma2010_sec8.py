"""Rule ma2010_sec8 (Ma 2010 Sec. 8): seconds of computation per second of synthesized
walking, on one core (motionvar.ma2010.evaluations.sec8)."""


def main(snakemake) -> None:
    from _ma2010 import load_walks, settings
    from _rule import write_evaluation

    from motionvar.ma2010.evaluations.sec8 import sec8_timing
    from motionvar.ma2010.figures import draw_sec8

    s = settings(snakemake)
    walks = load_walks(snakemake, s)
    write_evaluation(snakemake, sec8_timing(walks, walks.fit_model(s), s), draw_sec8)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
