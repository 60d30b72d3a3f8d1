"""Rule egges2004_identification (Egges 2004 Sec. 5.6, 8): does generated idle motion
identify its person? (motionvar.egges2004.evaluations.identification)"""


def main(snakemake) -> None:
    from _egges2004 import model, recordings, settings
    from _rule import joint_map, write_evaluation

    from motionvar.egges2004.evaluations.identification import identification
    from motionvar.egges2004.figures import draw_identification

    m = model(snakemake)
    train, held_out = recordings(snakemake, m)
    result = identification(m, train, held_out, joint_map(snakemake), settings(snakemake))
    write_evaluation(snakemake, result, draw_identification)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
