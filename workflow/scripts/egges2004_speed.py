"""Rule egges2004_speed (Egges 2004 Sec. 8): frames of idle motion generated per second
against the playback rate (motionvar.egges2004.evaluations.speed)."""


def main(snakemake) -> None:
    from _egges2004 import model, settings
    from _rule import write_evaluation

    from motionvar.egges2004.evaluations.speed import speed
    from motionvar.egges2004.figures import draw_speed

    write_evaluation(snakemake, speed(model(snakemake), settings(snakemake)), draw_speed)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
