"""Rule egges2004_repetition (Egges 2004 Sec. 6): repetition of generated small variations
and idle motion vs recorded motion and loops (motionvar.egges2004.evaluations.repetition),
and a PC curve with its extrema (Fig. 7-8, evaluations.fig7_8_extrema)."""


def main(snakemake) -> None:
    from _egges2004 import model, recordings, save_figure, settings
    from _rule import write_evaluation

    from motionvar.egges2004.evaluations import pc_extrema
    from motionvar.egges2004.evaluations.repetition import repetition
    from motionvar.egges2004.figures import draw_pc_extrema, draw_repetition

    s = settings(snakemake)
    m = model(snakemake)
    train, _ = recordings(snakemake, m)
    write_evaluation(snakemake, repetition(m, train, s), draw_repetition)
    save_figure(draw_pc_extrema(pc_extrema(m, train, s)), snakemake.output.extrema)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
