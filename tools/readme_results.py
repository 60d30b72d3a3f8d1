"""Rewrite docs/results.md (every claim of the last runs) from the merged claims of finished runs.

    python tools/readme_results.py [--main synthetic] [--others xia bandai_ds1 dfki_markerless]
        [--note "config/config.yaml, 25 subjects"]

Reads results/<dataset>/claims.csv (the `claims` rule's output) and replaces the text
between the markers <!-- results:start --> and <!-- results:end --> of docs/results.md
(the README's "Results" section gives the counts and links there).
A dataset whose claims file is missing is left out with a warning.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import pandas as pd

from motionvar.report.results_markdown import results_markdown

ROOT = Path(__file__).resolve().parents[1]
START, END = "<!-- results:start -->", "<!-- results:end -->"


def read(dataset: str) -> pd.DataFrame | None:
    path = ROOT / "results" / dataset / "claims.csv"
    if not path.is_file():
        print(f"warning: {path} missing (run the pipeline for {dataset} first); left out", file=sys.stderr)
        return None
    return pd.read_csv(path, dtype=str, keep_default_na=False)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--main", default="synthetic")
    parser.add_argument("--others", nargs="*", default=["xia", "bandai_ds1", "dfki_markerless"])
    parser.add_argument("--note", default="")
    args = parser.parse_args()
    main_claims = read(args.main)
    if main_claims is None:
        sys.exit(f"error: no claims for {args.main}")
    others = {name: t for name in args.others if (t := read(name)) is not None}
    readme = ROOT / "docs" / "results.md"
    text = readme.read_text(encoding="utf-8")
    if START not in text or END not in text:
        sys.exit(f"error: {readme} has no {START} ... {END} markers")
    head, rest = text.split(START, 1)
    _, tail = rest.split(END, 1)
    body = results_markdown(main_claims, args.main, others, args.note)
    readme.write_text(f"{head}{START}\n{body}{END}{tail}", encoding="utf-8")
    print(f"{readme}: Results from {args.main} and {len(others)} further dataset(s)")


if __name__ == "__main__":
    main()
