"""Rule claims: merge results/{dataset}/claims/*.json of all registered evaluations into
results/{dataset}/claims.csv (an empty table when none is registered)."""


def main(snakemake) -> None:
    import logging
    from pathlib import Path

    from motionvar.claims import merge_claims, read_claims

    table = merge_claims(snakemake.input.claims)
    table.to_csv(snakemake.output[0], index=False)
    logging.info("%d claims from %d files", len(table), len(snakemake.input.claims))
    silent = [Path(p).stem for p in snakemake.input.claims if not read_claims(p)]
    if silent:  # evaluations that only draw or tabulate (e.g. Table 3.1, Fig. 5.4) make no claim
        logging.info("evaluations without claims (figures and tables only): %s", ", ".join(silent))


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
