"""The claims summary of the report: one table per paper (statement, published value,
measured value, verdict, note) with the verdicts coloured, as a self-contained HTML page.
"""

from __future__ import annotations

import html
from collections.abc import Mapping
from pathlib import Path

import pandas as pd

from ..claims import CHECKED_VERDICTS, CLAIM_COLUMNS, UNDECIDED_VERDICTS, VERDICTS
from .counts import UNSTABLE, counts_text, kind_counts, seed_agreement, shown_verdicts

VERDICT_COLOURS = {
    "reproduced": "#c9ecd0",
    "partial": "#ffe8a8",
    "not reproduced": "#f6c6c6",
    "not testable": "#d6e4f0",
    "not applicable": "#e4e4e4",
    UNSTABLE: "#e6d6f2",
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
    if cols != list(CLAIM_COLUMNS):
        raise ValueError(f"{path}: columns {cols}, expected {list(CLAIM_COLUMNS)} (rerun rule claims)")
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
span.kind { font-size: 0.8em; font-style: italic; color: #555; }
details.measured summary { cursor: pointer; }
details.measured summary span { color: #555; font-size: 0.85em; }
details.measured div { font-size: 0.85em; color: #333; margin-top: 0.3em; }
"""


def _number(x: object) -> str:
    """A value or bound as the summary shows it (3 significant digits; blank for none)."""
    try:
        v = float(x)
    except (TypeError, ValueError):
        return str(x)
    return "" if v != v else f"{v:.3g}"


def _measured_cell(r) -> str:
    """One line, the value and its bound ("no value" for a claim without one); the measured
    numbers behind it folded beneath (the claims table keeps them whole)."""
    esc = html.escape
    value, bound = _number(r.value), " ".join(x for x in (str(r.direction), _number(r.bound)) if x)
    line = (
        esc(" ".join(x for x in (value, str(r.unit)) if x) + (f", bound {bound}" if bound else ""))
        if value
        else "no value"
    )
    if not str(r.measured).strip() or str(r.measured).strip() == "-":
        return line
    return (
        f'<details class="measured"><summary>{line} <span>(the numbers)</span></summary>'
        f"<div>{esc(r.measured)}</div></details>"
    )


def _counts(row: pd.Series) -> str:
    """One (paper, kind) row of :func:`motionvar.report.counts.kind_counts` as coloured counts;
    consistency checks in words."""
    if row["kind"] == "consistency":
        return f'<span class="apart">{html.escape(counts_text(row))}</span>'

    def span(c: str) -> str:
        return f'<span style="background:{VERDICT_COLOURS[c]}">{int(row[c])} {c}</span>'

    checked = "".join(span(c) for c in (*CHECKED_VERDICTS, UNSTABLE) if c != UNSTABLE or int(row[c]))
    undecided = [span(c) for c in UNDECIDED_VERDICTS if int(row[c])]
    return checked + (' <span class="apart">not decided:</span> ' + "".join(undecided) if undecided else "")


def _stability_text(agreement: pd.DataFrame | None, claim_id: str, shown: str) -> str:
    if agreement is None:
        return ""
    r = agreement.set_index("claim_id").loc[claim_id]
    if not int(r["n_seeds"]):
        return '<br><span class="stab">not in the stability run</span>'
    word = "UNSTABLE: " if shown == UNSTABLE else ""
    return f'<br><span class="stab">{word}{int(r["n_agree"])} of {int(r["n_seeds"])} seeds give it</span>'


def claims_html(
    table: pd.DataFrame,
    paper_titles: Mapping[str, str] | None = None,
    title: str = "Claims",
    stability: pd.DataFrame | None = None,
    dataset: str = "",
) -> str:
    """An HTML page of ``table`` (columns :data:`motionvar.claims.CLAIM_COLUMNS`): counts of
    verdicts per paper and kind of evidence (reproduction over replication and stand-in claims, each
    apart; consistency claims as checks), then per paper a table of its claims in id order. Papers
    appear in the order of ``paper_titles`` (paper key -> heading), others after. With ``stability``
    (a :func:`motionvar.report.stability.claims_stability` table with ``dataset`` among its seeds)
    each verdict says how many seeds give it, and one that fewer than 4 of 5 give is counted
    ``unstable``."""
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
    table = table.reset_index(drop=True)
    agreement = seed_agreement(table, stability, dataset) if stability is not None else None
    shown = shown_verdicts(table, agreement)
    papers = [p for p in titles if p in set(table["paper"])]
    papers += sorted(set(table["paper"]) - set(papers))
    parts.append(
        '<p class="none">Kinds of evidence: <b>replication</b>, the paper&#8217;s own experiment; <b>stand-in</b>, a '
        "stated measure for what the paper judged by eye or cited; <b>consistency</b>, true by construction or a "
        "sanity check, listed as a check and never counted as reproduction.</p>"
    )
    if stability is not None:
        parts.append(
            '<p class="none">Each verdict also says how many seeds of the stability run give it; one that fewer '
            "than 4 of 5 give is counted as unstable.</p>"
        )
    counts = kind_counts(table, shown)
    counts = counts.assign(order=counts["paper"].map(papers.index)).sort_values("order", kind="stable")
    parts.append("<table><tr><th>paper</th><th>kind</th><th>claims</th><th>verdicts</th></tr>")
    for row in counts.to_dict("records"):
        paper = row["paper"]
        parts.append(
            f'<tr><td><a href="#{esc(paper)}">{esc(titles.get(paper, paper))}</a></td><td>{esc(row["kind"])}</td>'
            f'<td>{row["claims"]}</td><td class="counts">{_counts(row)}</td></tr>'
        )
    parts.append("</table>")
    for paper in papers:
        rows = table.assign(shown_verdict=shown)[table["paper"] == paper].sort_values("claim_id", kind="stable")
        parts.append(f'<h2 id="{esc(paper)}">{esc(titles.get(paper, paper))}</h2>')
        parts.append(
            '<table class="claims"><colgroup><col style="width:13%"><col style="width:22%">'
            '<col style="width:14%"><col style="width:18%"><col style="width:12%"><col style="width:21%">'
            "</colgroup><tr><th>source, kind</th><th>statement</th><th>published</th><th>measured</th>"
            "<th>verdict</th><th>note</th></tr>"
        )
        for r in rows.itertuples(index=False):
            parts.append(
                f'<tr><td>{esc(r.source)}<br><span class="kind">{esc(r.kind)}</span><br>'
                f'<span class="id">{esc(r.claim_id)}</span></td>'
                f"<td>{esc(r.statement)}</td><td>{esc(r.published)}</td><td>{_measured_cell(r)}</td>"
                f'<td class="verdict" style="background:{VERDICT_COLOURS[r.shown_verdict]}">{esc(r.verdict)}'
                f"{_stability_text(agreement, r.claim_id, r.shown_verdict)}</td>"
                f'<td class="note">{esc(r.note)}</td></tr>'
            )
        parts.append("</table>")
    return "\n".join(parts + ["</body></html>"]) + "\n"
