"""Shared by the rule scripts: log to the rule's ``log:`` file, and report bad input as
one clear line instead of a traceback.

Usage at the end of a rule script (``main`` takes the ``snakemake`` object)::

    if "snakemake" in globals():
        from _rule import run
        run(snakemake, main)

Errors that mean bad input (ValueError and its subclasses such as DatasetError,
OSError, KeyError) print ``ERROR rule <name>: <message>`` on the console and in the
log (with the traceback in the log only) and exit with status 1; Snakemake then removes
the rule's outputs. :class:`motionvar.claims.NotApplicable` from an evaluation (the data
lacks what it needs) writes the evaluation's not-applicable outputs instead. Any other
exception is a bug and propagates with its traceback.
It also selects matplotlib's file backend (Agg) for the script.
"""

from __future__ import annotations

import logging
import sys
import traceback
import warnings

from motionvar.claims import NotApplicable

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
        except NotApplicable as exc:
            if not all(hasattr(snakemake.output, k) for k in ("table", "figure", "claims")):
                _fail(snakemake, log, f"not applicable to this dataset: {exc.reason}")
            logging.info("not applicable: %s", exc.reason)
            write_not_applicable(snakemake, exc.reason)
        except BAD_INPUT as exc:
            _fail(snakemake, log, str(exc))
        logging.info("done")


def _fail(snakemake, log, message: str) -> None:
    message = f"ERROR rule {snakemake.rule}: {message}"
    log.write(traceback.format_exc() + message + "\n")
    print(message, file=sys.stderr)
    sys.exit(1)


def write_not_applicable(snakemake, reason: str) -> None:
    """The evaluation's outputs when its input turns out insufficient (NotApplicable):
    the not-applicable claim with ``reason``, a table and a figure saying so; further
    outputs of the rule (figures, GIFs, tables) say the same."""
    import matplotlib.pyplot as plt
    import numpy as np

    from motionvar.claims import evaluation_source, not_applicable_result
    from motionvar.plots import write_gif
    from motionvar.plots.notice import draw_notice

    ev = snakemake.rule
    result = not_applicable_result(ev, f"Not applicable to dataset {snakemake.wildcards.dataset}: {reason}")
    title = f"{evaluation_source(ev)} ({ev}): not applicable"
    write_evaluation(snakemake, result, lambda r: draw_notice(title, reason))
    written = {str(snakemake.output.table), str(snakemake.output.figure), str(snakemake.output.claims)}
    for path in (str(p) for p in snakemake.output if str(p) not in written):
        if path.endswith(".csv"):
            result.table.to_csv(path, index=False)
            continue
        fig = draw_notice(title, reason)
        if path.endswith(".gif"):
            fig.canvas.draw()
            write_gif(path, np.asarray(fig.canvas.buffer_rgba())[None, ..., :3], fps=1.0)
        else:
            fig.savefig(path)
        plt.close(fig)


def write_evaluation(snakemake, result, draw, dpi: int = 110, **to_csv) -> None:
    """Write an evaluation's outputs: ``result.table`` to ``output.table`` (CSV, no index,
    ``to_csv`` keyword arguments passed on), ``draw(result)`` (a matplotlib Figure) to
    ``output.figure`` (a notice with the reason for a not-applicable result), ``result.claims``
    to ``output.claims``."""
    import matplotlib.pyplot as plt

    from motionvar.claims import write_claims

    result.table.to_csv(snakemake.output.table, index=False, **to_csv)
    if result.figure.get("not_applicable"):  # an evaluation that found its input insufficient
        from motionvar.plots.notice import draw_notice

        fig = draw_notice(result.figure["title"], result.figure["reason"])
    else:
        fig = draw(result)
    fig.savefig(snakemake.output.figure, dpi=dpi)
    plt.close(fig)
    write_claims(snakemake.output.claims, result.claims)
