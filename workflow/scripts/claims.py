"""Rule claims: merge results/{dataset}/claims/*.json of all registered evaluations into
results/{dataset}/claims.csv (an empty table when none is registered)."""


def main(snakemake) -> None:
    import logging

    from motionvar.claims import merge_claims

    table = merge_claims(snakemake.input.claims)
    table.to_csv(snakemake.output[0], index=False)
    logging.info("%d claims from %d files", len(table), len(snakemake.input.claims))


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
