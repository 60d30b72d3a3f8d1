"""Rules not_applicable_<paper>: the table, figure and claims of an evaluation the dataset
cannot support, with the reason from checkpoint applicability."""


def main(snakemake) -> None:
    import pandas as pd
    from _rule import write_evaluation

    from motionvar.claim_catalog import specs_of
    from motionvar.claims import not_applicable_result
    from motionvar.plots.notice import draw_notice

    ev = snakemake.wildcards.ev
    table = pd.read_csv(snakemake.input[0], dtype=str, keep_default_na=False).set_index("evaluation")
    if ev not in table.index or table.loc[ev, "applicable"] == "True":
        raise ValueError(f"{snakemake.input[0]}: {ev} is not a not-applicable evaluation of this dataset")
    row = table.loc[ev]
    result = not_applicable_result(
        ev,
        f"Not applicable to dataset {snakemake.wildcards.dataset}: {row.reason}",
        specs_of(ev),
        checks=row.checks,
        source=row.source,
    )
    write_evaluation(snakemake, result, lambda r: draw_notice(f"{row.source} ({ev}): not applicable", row.reason))


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
