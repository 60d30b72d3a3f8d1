"""Entry point of the ``motionvar`` command (``[project.scripts]`` in pyproject.toml; also
``python -m motionvar.cli.main``)::

    motionvar models  --dataset synthetic
    motionvar ma2010  --dataset synthetic --style 135 --seconds 20 --variants 3 --out walks/
    motionvar egges2004 --dataset synthetic --subject 01 --seconds 60 --out idle.bvh
    motionvar du2022 walk  --dataset synthetic --path "0,0 300,0 400,100" --out walk.bvh
    motionvar du2022 style --dataset synthetic --style old --n 5 --out styles/

Every subcommand reads the model files of ``--results`` (default ``results``) and never
fits anything. Errors a user can fix (a model not built yet or unreadable, an argument
outside what the model covers, a request above the command's size limit: its module's
``MAX_*``, checked before anything is loaded, an output file that exists without
``--force``) are one line on stderr and exit status 2. A command's files appear together
when all are written, or none does (motionvar.io.atomic.AtomicFiles): after an error,
Ctrl-C, SIGTERM or SIGHUP every output path is as it was (exit status 128 + the signal's
number for a signal). Without ``--quiet`` a progress bar and the library's progress lines
(e.g. each step of a graph walk) come on stderr. ``motionvar --version`` names the
installed version.
"""

from __future__ import annotations

import argparse
import contextlib
import logging
import signal
import sys
import threading
from collections.abc import Sequence

from ..io.units import UNIT_CM_MAX, UNIT_CM_MIN
from . import du2022, egges2004, ma2010, models
from .common import MAX_SEED, CLIError, check_output_options

# Signals that stop a command as Ctrl-C does: the output transaction is rolled back.
STOP_SIGNALS = tuple(getattr(signal, n) for n in ("SIGINT", "SIGTERM", "SIGHUP") if hasattr(signal, n))


class Stopped(BaseException):
    """A stop signal (SIGTERM, SIGHUP) raised in the command, as KeyboardInterrupt is for
    SIGINT, so that its clean-up runs."""

    def __init__(self, signum: int) -> None:
        self.signum = signum
        super().__init__(signal.Signals(signum).name)


EXAMPLES = """examples:
  motionvar models
  motionvar ma2010 --style 135 --seconds 20 --variants 3 --out walks/

`motionvar <command> --help` lists a command's options."""


def version() -> str:
    """The installed package's version (importlib.metadata), or "unknown" when motionvar
    runs from a source tree that is not installed."""
    from importlib.metadata import PackageNotFoundError
    from importlib.metadata import version as installed

    try:
        return installed("motionvar")
    except PackageNotFoundError:
        return "unknown (not installed)"


def _location(every_dataset: bool = False) -> argparse.ArgumentParser:
    """--dataset and --results: where a run's models lie (every subcommand)."""
    c = argparse.ArgumentParser(add_help=False)
    g = c.add_argument_group("where the models lie")
    g.add_argument(
        "--dataset",
        default=None if every_dataset else "synthetic",
        help="dataset name under --results (default "
        + ("every dataset there with models)" if every_dataset else "synthetic)"),
    )
    g.add_argument("--results", default="results", help="results folder of a pipeline run (default results)")
    return c


def _common() -> argparse.ArgumentParser:
    """The options of the commands that write BVH files: --dataset, --results, --seed,
    --unit-cm, --force, --quiet."""
    c = argparse.ArgumentParser(add_help=False, parents=[_location()])
    g = c.add_argument_group("output options")
    g.add_argument(
        "--seed",
        type=int,
        default=0,
        help=f"random seed, 0 to {MAX_SEED}: the same seed gives the same output (default 0)",
    )
    g.add_argument(
        "--unit-cm",
        type=float,
        default=1.0,
        help=f"centimetres per BVH length unit of the output, {UNIT_CM_MIN:g} to {UNIT_CM_MAX:g} (default 1: cm; "
        "100: metres, 0.1: mm)",
    )
    g.add_argument(
        "--force",
        action="store_true",
        help="overwrite output files that exist (regular files only; without it an existing one stops the command)",
    )
    g.add_argument("--quiet", action="store_true", help="no progress bar")
    return c


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="motionvar",
        description="Generate BVH motion with the models a motionvar pipeline run saved under "
        "results/<dataset>/models/ (Ma et al. 2010, Egges et al. 2004, Du 2022).",
        epilog=EXAMPLES,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("--version", action="version", version=f"motionvar {version()}")
    sub = p.add_subparsers(dest="command", metavar="{models,ma2010,egges2004,du2022}", required=True)
    models.add_parser(sub, lambda: _location(every_dataset=True))
    for part in (ma2010, egges2004, du2022):  # each its own copy of the common options (set_defaults
        part.add_parser(sub, _common)  # on a subparser changes the default of a shared action)
    return p


@contextlib.contextmanager
def progress_lines(enabled: bool):
    """While the command runs, the progress lines of the library's long loops
    (motionvar.core.progress, e.g. each step of a graph walk) on stderr as ``motionvar:
    <line>``; nothing with ``enabled`` False (--quiet)."""
    if not enabled:
        yield
        return

    class StderrHandler(logging.StreamHandler):
        """Writes to the sys.stderr of the moment (which tests and callers may swap)."""

        stream = property(lambda self: sys.stderr, lambda self, value: None)

    logger = logging.getLogger("motionvar.progress")
    handler, level = StderrHandler(), logger.level
    handler.setFormatter(logging.Formatter("motionvar: %(message)s"))
    logger.addHandler(handler)
    logger.setLevel(logging.INFO)
    try:
        yield
    finally:
        logger.removeHandler(handler)
        logger.setLevel(level)


@contextlib.contextmanager
def stop_signals():
    """While the command runs, SIGTERM and SIGHUP raise Stopped and SIGINT raises
    KeyboardInterrupt; once one came, the others are ignored while the command cleans up.
    A signal the caller ignores (``nohup``) stays ignored; outside the main thread (where
    Python cannot set handlers) nothing changes."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return

    def stop(signum: int, frame) -> None:
        for s in STOP_SIGNALS:
            signal.signal(s, signal.SIG_IGN)
        raise KeyboardInterrupt if signum == signal.SIGINT else Stopped(signum)

    previous = {s: signal.getsignal(s) for s in STOP_SIGNALS}
    for s, handler in previous.items():
        if handler is not signal.SIG_IGN:
            signal.signal(s, stop)
    try:
        yield
    finally:
        for s, handler in previous.items():
            signal.signal(s, handler if handler is not None else signal.SIG_DFL)


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line ``argv`` (default ``sys.argv[1:]``); returns the exit status
    (argparse's own usage errors exit with 2 through SystemExit; a stop signal 128 + its
    number)."""
    args = build_parser().parse_args(argv)
    try:
        with stop_signals():
            check_output_options(args)
            with progress_lines(not getattr(args, "quiet", True)):
                return int(args.run(args) or 0)
    except CLIError as exc:
        print(f"motionvar {args.command}: error: {exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print(f"motionvar {args.command}: interrupted", file=sys.stderr)
        return 128 + signal.SIGINT
    except Stopped as exc:
        print(f"motionvar {args.command}: stopped by {exc}", file=sys.stderr)
        return 128 + exc.signum


if __name__ == "__main__":
    sys.exit(main())
