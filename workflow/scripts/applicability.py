"""Checkpoint applicability: which registered evaluations the dataset supports, with the
reason for each one it does not (results/{dataset}/applicability.csv)."""


def main(snakemake) -> None:
    import logging

    import pandas as pd

    from motionvar.applicability import applicability_table
    from motionvar.config_sections import section_settings
    from motionvar.du2022.requirements import fda_requirements, graph_requirements, style_requirements
    from motionvar.egges2004.requirements import requirements as egges2004
    from motionvar.io.joint_map_file import rig_joint_map
    from motionvar.ma2010.requirements import requirements as ma2010

    p = snakemake.params
    papers = {  # config section -> its requirements, in the order of the table's rows
        "ma2010": ma2010,
        "du2022_fda": fda_requirements,
        "du2022_style": style_requirements,
        "egges2004": egges2004,
        "du2022_graph": graph_requirements,
    }
    reqs = [r for section, of in papers.items() for r in of(section_settings(section, getattr(p, section)))]
    meta = {stage: pd.read_csv(snakemake.input[stage], dtype=str, keep_default_na=False) for stage in ("data", "prep")}
    table = applicability_table([r for r in reqs if r.evaluation in p.evaluations], meta, rig_joint_map(p.joint_map))
    missing = sorted(set(p.evaluations) - set(table["evaluation"]))
    if missing:
        raise ValueError(
            f"evaluations without declared requirements: {missing} (add them to the paper's requirements.py)"
        )
    table.to_csv(snakemake.output[0], index=False)
    for row in table[~table["applicable"]].itertuples():
        logging.info("not applicable: %s (%s): %s", row.evaluation, row.source, row.reason)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
