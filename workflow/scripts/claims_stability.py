"""Rule claims_stability: per claim, the verdict of every seed's dataset, how many agree,
and the claim's value across seeds (motionvar.report.stability); table, figure and page."""


def main(snakemake) -> None:
    from pathlib import Path

    import matplotlib.pyplot as plt

    from motionvar.plots.stability import stability_figure
    from motionvar.report.stability import claims_stability, stability_html
    from motionvar.report.summary import read_claims_table

    tables = {name: read_claims_table(path) for name, path in zip(snakemake.params.datasets, snakemake.input.claims)}
    table = claims_stability(tables, snakemake.params.stable_share)
    table.to_csv(snakemake.output.table, index=False)
    fig = stability_figure(table)
    fig.savefig(snakemake.output.figure, dpi=110)
    plt.close(fig)
    Path(snakemake.output.page).write_text(stability_html(table), encoding="utf-8")


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
