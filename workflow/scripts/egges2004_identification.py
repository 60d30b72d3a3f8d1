"""Rule egges2004_identification (Egges 2004 Sec. 5.6, 8): does generated idle motion
identify its person? (motionvar.egges2004.evaluations.sec8_identification)"""


def main(snakemake) -> None:
    from _egges2004 import joint_map, model, recordings
    from _rule import write_evaluation

    from motionvar.egges2004.evaluations import IdentificationParams, identification
    from motionvar.egges2004.figures import draw_identification

    p = snakemake.params.options
    m = model(snakemake)
    train, held_out = recordings(snakemake, m)
    params = IdentificationParams(**p["identification"], perlin_frequency_hz=p["perlin_frequency_hz"])
    result = identification(m, train, held_out, joint_map(snakemake), params, p["support_margin"], p["seed"])
    write_evaluation(snakemake, result, draw_identification)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
