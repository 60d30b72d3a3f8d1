"""Shared by the rule scripts: log to the rule's ``log:`` file, and report bad input as
one clear line instead of a traceback.

Usage at the end of a rule script (``main`` takes the ``snakemake`` object)::

    if "snakemake" in globals():
        from _rule import run
        run(snakemake, main)

Errors that mean bad input (ValueError and its subclasses such as DatasetError,
OSError, KeyError) print ``ERROR rule <name>: <message>`` on the console and in the
log (with the traceback in the log only) and exit with status 1; Snakemake then removes
the rule's outputs. Any other exception is a bug and propagates with its traceback.
It also selects matplotlib's file backend (Agg) for the script.
"""

from __future__ import annotations

import logging
import sys
import traceback
import warnings

BAD_INPUT = (ValueError, OSError, KeyError)


def run(snakemake, main) -> None:
    import matplotlib

    matplotlib.use("Agg")  # figures are files; the library never chooses a backend
    with open(snakemake.log[0], "w") as log:
        logging.basicConfig(
            level=logging.INFO, format="%(asctime)s %(levelname)s %(message)s",
            handlers=[logging.StreamHandler(log)], force=True,
        )
        logging.captureWarnings(True)
        warnings.simplefilter("default")
        logging.info("rule %s, wildcards %s", snakemake.rule, dict(snakemake.wildcards.items()))
        try:
            main(snakemake)
        except BAD_INPUT as exc:
            message = f"ERROR rule {snakemake.rule}: {exc}"
            log.write(traceback.format_exc() + message + "\n")
            print(message, file=sys.stderr)
            sys.exit(1)
        logging.info("done")


def write_evaluation(snakemake, result, draw, dpi: int = 110, **to_csv) -> None:
    """Write an evaluation's outputs: ``result.table`` to ``output.table`` (CSV, no index,
    ``to_csv`` keyword arguments passed on), ``draw(result)`` (a matplotlib Figure) to
    ``output.figure``, ``result.claims`` to ``output.claims``."""
    import matplotlib.pyplot as plt

    from motionvar.claims import write_claims

    result.table.to_csv(snakemake.output.table, index=False, **to_csv)
    fig = draw(result)
    fig.savefig(snakemake.output.figure, dpi=dpi)
    plt.close(fig)
    write_claims(snakemake.output.claims, result.claims)
