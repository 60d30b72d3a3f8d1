"""docs/results.md (linked from the README's "Results") from merged claims tables: per paper, the verdict
counts and one line per claim (source, verdict, measured value); per further dataset,
one line of counts. Regenerate with ``python tools/readme_results.py``."""

from __future__ import annotations

from collections.abc import Mapping

import pandas as pd

from ..claims import CHECKED_VERDICTS, UNDECIDED_VERDICTS

PAPER_TITLES = {"ma2010": "Ma et al. 2010", "du2022": "Du 2022", "egges2004": "Egges et al. 2004"}


def verdict_counts(verdicts: pd.Series) -> str:
    """``18 reproduced, 5 partial, 9 not reproduced`` (+ the undecided ones, if any)."""
    parts = [f"{int((verdicts == v).sum())} {v}" for v in CHECKED_VERDICTS]
    parts += [f"{int((verdicts == v).sum())} {v}" for v in UNDECIDED_VERDICTS if (verdicts == v).any()]
    return ", ".join(parts)


def _cell(text: str) -> str:
    return str(text).replace("|", "\\|").replace("\n", " ")


def paper_results(claims: pd.DataFrame, paper: str) -> str:
    """Markdown of one paper's claims: counts, then a table source | claim | verdict | measured."""
    rows = claims[claims["paper"] == paper].sort_values("claim_id", kind="stable")
    if rows.empty:
        return "*(no claims)*\n"
    lines = [
        f"{len(rows)} claims: {verdict_counts(rows['verdict'])}.",
        "",
        "| source | claim | verdict | measured |",
        "|---|---|---|---|",
    ]
    lines += [
        f"| {_cell(r.source)} | {_cell(r.statement)} | {r.verdict} | {_cell(r.measured)} |"
        for r in rows.itertuples(index=False)
    ]
    return "\n".join(lines) + "\n"


def results_markdown(
    main: pd.DataFrame, main_name: str, others: Mapping[str, pd.DataFrame] | None = None, run_note: str = ""
) -> str:
    """The Results section body: ``main`` (the full synthetic run) per paper, then one
    line per dataset of ``others`` (name -> claims)."""
    parts = [
        f"Claims of the last run on `{main_name}`{(' (' + run_note + ')') if run_note else ''}: "
        f"{verdict_counts(main['verdict'])}. The report holds the figures, tables and notes.",
        "",
    ]
    for paper, title in PAPER_TITLES.items():
        parts += [f"### {title}", "", paper_results(main, paper)]
    if others:
        parts += ["### Real data sets (`config/real/`)", ""]
        for name, table in others.items():
            na = table[table["verdict"] == "not applicable"]
            skipped = ", ".join(sorted(na["source"] + " (" + na["paper"] + ")")) if len(na) else "none"
            parts.append(
                f"- `{name}`: {len(table)} claims: {verdict_counts(table['verdict'])}; not applicable: {skipped}."
            )
        parts.append("")
    return "\n".join(parts)
