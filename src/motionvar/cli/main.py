"""Entry point of the ``motionvar`` command (``[project.scripts]`` in pyproject.toml; also
``python -m motionvar.cli.main``)::

    motionvar models  --dataset synthetic
    motionvar ma2010  --dataset synthetic --style 135 --seconds 20 --variants 3 --out walks/
    motionvar egges2004 --dataset synthetic --subject 01 --seconds 60 --out idle.bvh
    motionvar du2022 walk  --dataset synthetic --path "0,0 300,0 400,100" --out walk.bvh
    motionvar du2022 style --dataset synthetic --style old --n 5 --out styles/

Every subcommand reads the model files of ``--results`` (default ``results``) and never
fits anything. Errors a user can fix (a model not built yet, an argument outside what the
model covers) are one line on stderr and exit status 2; no output file is left behind.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence

from . import du2022, egges2004, ma2010, models
from .common import CLIError


def _common() -> argparse.ArgumentParser:
    c = argparse.ArgumentParser(add_help=False)
    g = c.add_argument_group("common options")
    g.add_argument("--dataset", default="synthetic", help="dataset name under --results (default synthetic)")
    g.add_argument("--results", default="results", help="results folder of a pipeline run (default results)")
    g.add_argument("--seed", type=int, default=0, help="random seed: the same seed gives the same output (default 0)")
    g.add_argument(
        "--unit-cm",
        type=float,
        default=1.0,
        help="centimetres per BVH length unit of the output (default 1: cm; 100: metres, 0.1: mm)",
    )
    g.add_argument("--quiet", action="store_true", help="no progress bar")
    return c


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="motionvar",
        description="Generate BVH motion with the models a motionvar pipeline run saved under "
        "results/<dataset>/models/ (Ma et al. 2010, Egges et al. 2004, Du 2022).",
    )
    sub = p.add_subparsers(dest="command", metavar="{models,ma2010,egges2004,du2022}", required=True)
    for part in (models, ma2010, egges2004, du2022):  # each its own copy of the common options (set_defaults
        part.add_parser(sub, _common)  # on a subparser changes the default of a shared action)
    return p


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line ``argv`` (default ``sys.argv[1:]``); returns the exit status
    (argparse's own usage errors exit with 2 through SystemExit)."""
    args = build_parser().parse_args(argv)
    try:
        if not (args.unit_cm > 0):
            raise CLIError(f"--unit-cm must be > 0; got {args.unit_cm:g}")
        return int(args.run(args) or 0)
    except CLIError as exc:
        print(f"motionvar {args.command}: error: {exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print(f"motionvar {args.command}: interrupted", file=sys.stderr)
        return 130


if __name__ == "__main__":
    sys.exit(main())
