"""Rule egges2004_repetition (Egges 2004 Sec. 6): repetition of generated small variations
and idle motion vs recorded motion and loops (motionvar.egges2004.evaluations.repetition),
and a PC curve with its extrema (Fig. 7-8, evaluations.fig7_8_extrema)."""


def main(snakemake) -> None:
    from _egges2004 import save_figure
    from _evaluation import evaluate

    from motionvar.egges2004.evaluations import pc_extrema
    from motionvar.egges2004.figures import draw_pc_extrema

    done = evaluate(snakemake)
    extrema = pc_extrema(done.inputs["model"], done.inputs["recordings"], done.settings)
    save_figure(draw_pc_extrema(extrema), snakemake.output.extrema)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
