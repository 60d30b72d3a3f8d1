"""Checkpoint applicability: which registered evaluations the dataset supports, with the
reason for each one it does not (results/{dataset}/applicability.csv)."""


def main(snakemake) -> None:
    import logging

    import pandas as pd

    from motionvar.applicability import applicability_table
    from motionvar.du2022.requirements import fda_requirements, graph_requirements, style_requirements
    from motionvar.egges2004.requirements import requirements as egges2004_requirements
    from motionvar.ma2010.requirements import requirements as ma2010

    p, g = snakemake.params, snakemake.params.graph
    walks = [q for q in g["primitives"] if q.startswith("walk_")]  # Fig. 4.10's walking primitives
    reqs = [
        *ma2010(**p.ma2010),
        *fda_requirements(**p.fda),
        *style_requirements(**p.style),
        *egges2004_requirements(**p.egges2004),
        *graph_requirements(g["primitives"], p.graph_search["primitives"], walks, g["reach_primitive"]),
    ]
    meta = {stage: pd.read_csv(snakemake.input[stage], dtype=str, keep_default_na=False) for stage in ("data", "prep")}
    table = applicability_table([r for r in reqs if r.evaluation in p.evaluations], meta)
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
