"""Rule egges2004_fitting (Egges 2004 Sec. 5.4.4, 7.1, Fig. 4-5): fitted animations start
at p and end at q exactly, and the pieces of a generated sequence join smoothly
(motionvar.egges2004.evaluations.fitting)."""


def main(snakemake) -> None:
    from _egges2004 import model, settings
    from _rule import write_evaluation

    from motionvar.egges2004.evaluations.fitting import fitting
    from motionvar.egges2004.figures import draw_fitting

    write_evaluation(snakemake, fitting(model(snakemake), settings(snakemake)), draw_fitting)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
