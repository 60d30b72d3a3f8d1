"""Rule egges2004_repetition (Egges 2004 Sec. 6): repetition of generated small variations
and idle motion vs recorded motion and loops (motionvar.egges2004.evaluations.sec6_repetition),
and a PC curve with its extrema (Fig. 7-8, evaluations.fig7_8_extrema)."""


def main(snakemake) -> None:
    from _egges2004 import model, recordings, save_figure
    from _rule import write_evaluation

    from motionvar.egges2004.evaluations import RepetitionParams, pc_extrema, repetition
    from motionvar.egges2004.figures import draw_pc_extrema, draw_repetition

    p = snakemake.params.options
    m = model(snakemake)
    train, _ = recordings(snakemake, m)
    params = RepetitionParams(**p["repetition"], perlin_frequency_hz=p["perlin_frequency_hz"])
    write_evaluation(snakemake, repetition(m, train, params, p["seed"]), draw_repetition)
    extrema = pc_extrema(m, train, p["extrema_pc"], p["extrema_eps_sd"], p["figure_subjects"])
    save_figure(draw_pc_extrema(extrema), snakemake.output.extrema)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
