"""The claims summary of the report: one table per paper (statement, published value,
measured value, verdict, note) with the verdicts coloured, as a self-contained HTML page.
"""

from __future__ import annotations

import html
from collections.abc import Mapping
from pathlib import Path

import pandas as pd

from ..claims import CHECKED_VERDICTS, CLAIM_COLUMNS, TEXT_COLUMNS, UNDECIDED_VERDICTS, VERDICTS

VERDICT_COLOURS = {
    "reproduced": "#c9ecd0",
    "partial": "#ffe8a8",
    "not reproduced": "#f6c6c6",
    "not testable": "#d6e4f0",
    "not applicable": "#e4e4e4",
}


def read_claims_table(path: str | Path) -> pd.DataFrame:
    """A merged claims CSV (rule ``claims``); ValueError naming the file if its columns
    or verdicts are not those of :mod:`motionvar.claims`."""
    path = Path(path)
    try:
        table = pd.read_csv(path, dtype=str, keep_default_na=False)
    except (pd.errors.ParserError, pd.errors.EmptyDataError, UnicodeDecodeError) as exc:
        raise ValueError(f"{path}: not a readable claims table ({exc})") from exc
    cols = list(table.columns)
    if cols == list(CLAIM_COLUMNS[: len(TEXT_COLUMNS)]):  # written before claims carried value and bound
        table = table.reindex(columns=list(CLAIM_COLUMNS), fill_value="")
    elif cols != list(CLAIM_COLUMNS):
        raise ValueError(f"{path}: columns {cols}, expected {list(CLAIM_COLUMNS)}")
    bad = sorted(set(table["verdict"]) - set(VERDICTS))
    if bad:
        raise ValueError(f"{path}: unknown verdicts {bad} (expected {list(VERDICTS)})")
    return table


_STYLE = """
body { font-family: -apple-system, "Segoe UI", Helvetica, Arial, sans-serif; margin: 1.5em; color: #222; }
h1 { font-size: 1.4em; } h2 { font-size: 1.15em; margin-top: 1.6em; }
table { border-collapse: collapse; width: 100%; font-size: 0.9em; }
th, td { border: 1px solid #ccc; padding: 0.35em 0.5em; text-align: left; vertical-align: top; }
th { background: #f0f0f0; }
table.claims { table-layout: fixed; }
td.verdict { font-weight: bold; font-size: 0.85em; }
span.stab { font-weight: normal; font-size: 0.85em; }
td.note { font-size: 0.85em; color: #444; }
.id { font-family: monospace; font-size: 0.75em; overflow-wrap: anywhere; color: #555; }
.counts span { display: inline-block; padding: 0.15em 0.6em; margin-right: 0.5em; border-radius: 0.3em; }
p.none { color: #666; font-style: italic; }
.counts span.apart { background: none; color: #555; font-size: 0.85em; padding: 0; }
"""


def _counts(verdicts: pd.Series) -> str:
    """Counts of the checked verdicts, then (apart) those not decided, when there are any."""

    def span(v: str) -> str:
        return f'<span style="background:{VERDICT_COLOURS[v]}">{int((verdicts == v).sum())} {v}</span>'

    checked = "".join(span(v) for v in CHECKED_VERDICTS)
    undecided = [span(v) for v in UNDECIDED_VERDICTS if (verdicts == v).any()]
    return checked + (' <span class="apart">not decided:</span> ' + "".join(undecided) if undecided else "")


def _stability_text(stability: pd.DataFrame | None, claim_id: str) -> str:
    if stability is None:
        return ""
    rows = stability[stability["claim_id"] == claim_id]
    if rows.empty:
        return '<br><span class="stab">not in the stability run</span>'
    r = rows.iloc[0]
    word = "stable" if bool(r["stable"]) else "NOT stable"
    return (
        f'<br><span class="stab">{word} across seeds: {html.escape(str(r["verdict"]))} in '
        f"{int(r['n_agree'])}/{int(r['n_seeds'])}</span>"
    )


def claims_html(
    table: pd.DataFrame,
    paper_titles: Mapping[str, str] | None = None,
    title: str = "Claims",
    stability: pd.DataFrame | None = None,
) -> str:
    """An HTML page of ``table`` (columns :data:`motionvar.claims.CLAIM_COLUMNS`):
    counts of verdicts per paper, then per paper a table of its claims in id order.
    Papers appear in the order of ``paper_titles`` (paper key -> heading), others after.
    With ``stability`` (a :func:`motionvar.report.stability.claims_stability` table) each
    verdict says whether the seeds agree on it."""
    titles = dict(paper_titles or {})
    esc = html.escape
    parts = [
        "<!DOCTYPE html>",
        '<html lang="en"><head><meta charset="utf-8">',
        f"<title>{esc(title)}</title><style>{_STYLE}</style></head><body>",
        f"<h1>{esc(title)}</h1>",
    ]
    if table.empty:
        parts.append('<p class="none">No claims yet: no evaluation is registered, or none wrote a claim.</p>')
        return "\n".join(parts + ["</body></html>"]) + "\n"
    papers = [p for p in titles if p in set(table["paper"])]
    papers += sorted(set(table["paper"]) - set(papers))
    if stability is not None:
        parts.append(
            '<p class="none">Each verdict also says whether the seeds of the stability run '
            "(results/stability/claims_stability.csv, config/seeds.yaml at its own, reduced sizes) agree "
            "on it: stable when at least 4 of 5 give the same verdict.</p>"
        )
    parts.append("<table><tr><th>paper</th><th>claims</th><th>verdicts</th></tr>")
    for paper in papers:
        rows = table[table["paper"] == paper]
        parts.append(
            f'<tr><td><a href="#{esc(paper)}">{esc(titles.get(paper, paper))}</a></td>'
            f'<td>{len(rows)}</td><td class="counts">{_counts(rows["verdict"])}</td></tr>'
        )
    parts.append("</table>")
    for paper in papers:
        rows = table[table["paper"] == paper].sort_values("claim_id", kind="stable")
        parts.append(f'<h2 id="{esc(paper)}">{esc(titles.get(paper, paper))}</h2>')
        parts.append(
            '<table class="claims"><colgroup><col style="width:13%"><col style="width:22%">'
            '<col style="width:14%"><col style="width:18%"><col style="width:12%"><col style="width:21%">'
            "</colgroup><tr><th>source</th><th>statement</th><th>published</th><th>measured</th>"
            "<th>verdict</th><th>note</th></tr>"
        )
        for r in rows.itertuples(index=False):
            parts.append(
                f'<tr><td>{esc(r.source)}<br><span class="id">{esc(r.claim_id)}</span></td>'
                f"<td>{esc(r.statement)}</td><td>{esc(r.published)}</td><td>{esc(r.measured)}</td>"
                f'<td class="verdict" style="background:{VERDICT_COLOURS[r.verdict]}">{esc(r.verdict)}'
                f"{_stability_text(stability, r.claim_id)}</td>"
                f'<td class="note">{esc(r.note)}</td></tr>'
            )
        parts.append("</table>")
    return "\n".join(parts + ["</body></html>"]) + "\n"
