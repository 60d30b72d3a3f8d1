"""Rule claims_summary: the merged claims as an HTML page, one table per paper with the
verdicts coloured (results/{dataset}/claims_summary.html), each marked stable or not
where a stability run has the dataset among its seeds: this config's, or the earlier run's
that config key stability.marks names."""


def main(snakemake) -> None:
    import logging
    from pathlib import Path

    import pandas as pd

    from motionvar.report.counts import seed_names
    from motionvar.report.summary import claims_html, read_claims_table

    table = read_claims_table(snakemake.input.claims)
    stability = pd.read_csv(snakemake.params.stability) if snakemake.params.stability else None
    if stability is not None and snakemake.wildcards.dataset not in seed_names(stability):
        logging.info("%s has no seed %s: no stability marks", snakemake.params.stability, snakemake.wildcards.dataset)
        stability = None
    html = claims_html(
        table,
        paper_titles=snakemake.params.categories,
        title=f"Claims checked on dataset '{snakemake.wildcards.dataset}'",
        stability=stability,
        dataset=snakemake.wildcards.dataset,
    )
    Path(snakemake.output[0]).write_text(html, encoding="utf-8")


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
