"""Rewrite docs/results.md (every claim of the last runs) and the counts of README's Results from the
merged claims of finished runs.

    python tools/readme_results.py [--main synthetic] [--others xia bandai_ds1 dfki_markerless]
        [--stability results/stability_full/claims_stability.csv] [--note "config/config.yaml, 25 subjects"]

Reads results/<dataset>/claims.csv (the `claims` rule's output) and, where it exists, the
full-size stability run's table (config/seeds_full.yaml, rule claims_stability), and replaces the
text between the markers <!-- results:start --> and <!-- results:end --> of docs/results.md and
between <!-- counts:start --> and <!-- counts:end --> of README.md (the counts per paper and kind).
A dataset whose claims file is missing is left out with a warning.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import pandas as pd

from motionvar.report.results_markdown import readme_counts, results_markdown

ROOT = Path(__file__).resolve().parents[1]
START, END = "<!-- results:start -->", "<!-- results:end -->"
COUNTS_START, COUNTS_END = "<!-- counts:start -->", "<!-- counts:end -->"


def read(dataset: str) -> pd.DataFrame | None:
    path = ROOT / "results" / dataset / "claims.csv"
    if not path.is_file():
        print(f"warning: {path} missing (run the pipeline for {dataset} first); left out", file=sys.stderr)
        return None
    return pd.read_csv(path, dtype=str, keep_default_na=False)


def replace_between(path: Path, start: str, end: str, body: str) -> None:
    """Replace the text between the markers ``start`` and ``end`` of ``path`` by ``body``."""
    text = path.read_text(encoding="utf-8")
    if start not in text or end not in text:
        sys.exit(f"error: {path} has no {start} ... {end} markers")
    head, rest = text.split(start, 1)
    _, tail = rest.split(end, 1)
    path.write_text(f"{head}{start}\n{body}{end}{tail}", encoding="utf-8")


def main() -> None:
    parser = argparse.ArgumentParser(description=" ".join(__doc__.split("\n\n")[0].split()))
    parser.add_argument("--main", default="synthetic", help="the dataset whose claims README counts")
    parser.add_argument(
        "--others",
        nargs="*",
        default=["xia", "bandai_ds1", "dfki_markerless"],
        help="further datasets listed in docs/results.md",
    )
    parser.add_argument(
        "--stability",
        default="results/stability_full/claims_stability.csv",
        help="the five-seed claims_stability table (relative to the repository)",
    )
    parser.add_argument("--note", default="", help="what the runs were (configs, commit), printed above the counts")
    args = parser.parse_args()
    main_claims = read(args.main)
    if main_claims is None:
        sys.exit(f"error: no claims for {args.main}")
    others = {name: t for name in args.others if (t := read(name)) is not None}
    stability_path = ROOT / args.stability
    stability = pd.read_csv(stability_path) if stability_path.is_file() else None
    if stability is None:
        print(f"warning: {stability_path} missing: verdicts without their agreement over seeds", file=sys.stderr)
    body = results_markdown(main_claims, args.main, others, args.note, stability)
    replace_between(ROOT / "docs" / "results.md", START, END, body)
    replace_between(ROOT / "README.md", COUNTS_START, COUNTS_END, readme_counts(main_claims, args.main, stability))
    print(f"docs/results.md and README.md: Results from {args.main} and {len(others)} further dataset(s)")


if __name__ == "__main__":
    main()
