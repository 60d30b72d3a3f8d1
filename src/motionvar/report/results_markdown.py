"""docs/results.md and README's Results counts (tools/readme_results.py) from merged claims tables:
per paper and kind of evidence, the verdict counts (``unstable`` where a stability run's seeds do not
share the verdict) and the unstable claims' value and verdict per seed; per paper one line per claim
(source, kind, verdict, how many seeds give it, the value's interval over the seeds, the measured
value); per further dataset, one line of counts."""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence

import pandas as pd

from ..claims import CHECKED_VERDICTS, UNDECIDED_VERDICTS
from .counts import UNSTABLE, counts_text, kind_counts, seed_agreement, seed_bounds, seed_names, shown_verdicts

PAPER_TITLES = {"ma2010": "Ma et al. 2010", "du2022": "Du 2022", "egges2004": "Egges et al. 2004"}


def verdict_counts(verdicts: pd.Series) -> str:
    """``18 reproduced, 5 partial, 9 not reproduced`` (+ the undecided ones, if any)."""
    parts = [f"{int((verdicts == v).sum())} {v}" for v in CHECKED_VERDICTS]
    parts += [f"{int((verdicts == v).sum())} {v}" for v in UNDECIDED_VERDICTS if (verdicts == v).any()]
    return ", ".join(parts)


def _cell(text: str) -> str:
    return str(text).replace("|", "\\|").replace("\n", " ")


def counts_markdown(claims: pd.DataFrame, shown: pd.Series, titles: Mapping[str, str] = PAPER_TITLES) -> str:
    """A table paper | kind | claims | verdicts (:func:`motionvar.report.counts.kind_counts`)."""
    lines = ["| paper | kind | claims | verdicts |", "|---|---|---|---|"]
    counts = kind_counts(claims, shown)
    order = {paper: i for i, paper in enumerate(titles)}
    counts = counts.assign(order=counts["paper"].map(lambda p: order.get(p, len(order)))).sort_values(
        "order", kind="stable"
    )
    for row in counts.to_dict("records"):
        title = titles.get(row["paper"], row["paper"])
        lines.append(f"| {title} | {row['kind']} | {row['claims']} | {counts_text(row)} |")
    return "\n".join(lines) + "\n"


def _interval(stability: pd.DataFrame | None, claim_id: str, unit: str) -> str:
    if stability is None or claim_id not in set(stability["claim_id"]):
        return "-"
    r = stability.set_index("claim_id").loc[claim_id]
    mean, low, high = (float(r[c]) for c in ("value_mean", "value_ci_low", "value_ci_high"))
    if not math.isfinite(mean):
        return "-"
    if not math.isfinite(low):
        return f"{mean:.3g} {unit}".strip()
    return f"{mean:.3g} [{low:.3g}, {high:.3g}] {unit}".strip()


def paper_results(
    claims: pd.DataFrame,
    paper: str,
    shown: pd.Series,
    agreement: pd.DataFrame | None = None,
    stability: pd.DataFrame | None = None,
    same_run: bool = True,
) -> str:
    """Markdown of one paper's claims: source | kind | claim | verdict | seeds | value over the
    seeds | measured, ordered by kind (replication, stand-in, consistency), then id. The seeds column
    says how many seeds give this verdict (``same_run``: this run is one of the seeds) or, for seeds of
    another configuration, their most common verdict and how many give it."""
    order = {"replication": 0, "stand-in": 1, "consistency": 2}
    rows = claims.assign(shown_verdict=shown.to_numpy(), kind_order=claims["kind"].map(order))
    rows = rows[rows["paper"] == paper].sort_values(["kind_order", "claim_id"], kind="stable")
    if rows.empty:
        return "*(no claims)*\n"
    seeds = agreement.set_index("claim_id") if agreement is not None else None
    lines = [
        f"| source | kind | claim | verdict | {'seeds: verdict, agreeing' if stability is not None and not same_run else 'seeds giving it'} | "
        "value over the seeds [95 %] | measured |",
        "|---|---|---|---|---|---|---|",
    ]
    for r in rows.itertuples(index=False):
        verdict = r.verdict if r.shown_verdict == r.verdict else f"{r.shown_verdict} ({r.verdict})"
        agree = "-"
        if seeds is not None and int(seeds.loc[r.claim_id, "n_seeds"]):
            agree = f"{int(seeds.loc[r.claim_id, 'n_agree'])}/{int(seeds.loc[r.claim_id, 'n_seeds'])}"
        elif stability is not None and not same_run and r.claim_id in set(stability["claim_id"]):
            row = stability.set_index("claim_id").loc[r.claim_id]
            agree = f"{row['verdict']} {int(row['n_agree'])}/{int(row['n_seeds'])}"
        lines.append(
            f"| {_cell(r.source)} | {r.kind} | {_cell(r.statement)} | {verdict} | {agree} | "
            f"{_cell(_interval(stability, r.claim_id, r.unit))} | {_cell(r.measured)} |"
        )
    return "\n".join(lines) + "\n"


def unstable_markdown(stability: pd.DataFrame, claim_ids: Sequence[str]) -> str:
    """The unstable claims ``claim_ids`` of the seeds of ``stability``: per seed, the value and
    the verdict (empty without any)."""
    rows = stability.set_index("claim_id").reindex([c for c in claim_ids if c in set(stability["claim_id"])])
    if rows.empty:
        return ""
    seeds = seed_names(stability)
    lines = [
        f"Unstable claims ({len(rows)} of {len(stability)}), per seed: value and verdict.",
        "",
        "| claim | kind | bound | " + " | ".join(seeds) + " |",
        "|---|---|---|" + "---|" * len(seeds),
    ]
    for claim_id, r in rows.iterrows():
        values = [float(r[f"value_{s}"]) for s in seeds]
        cells = [
            f"{v:.3g} {r[f'verdict_{s}']}" if math.isfinite(v) else r[f"verdict_{s}"] for v, s in zip(values, seeds)
        ]
        direction, unit = (r[c] if isinstance(r[c], str) else "" for c in ("direction", "unit"))  # CSV: NaN for ""
        per_seed = seed_bounds(r, seeds)
        if per_seed is not None:  # a bound measured on each seed's data
            cells = [f"{c} ({direction} {b:.3g})".replace("( ", "(") for c, b in zip(cells, per_seed)]
        bound = "measured per seed" if per_seed is not None else f"{float(r['bound']):.4g}"
        bound = f"{direction} {bound} {unit}".strip()
        lines.append(f"| `{claim_id}` | {r['kind']} | {_cell(bound)} | " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def readme_counts(main: pd.DataFrame, main_name: str, stability: pd.DataFrame | None = None) -> str:
    """The counts of README's Results: ``main`` per paper and kind, ``unstable`` where the seeds of
    ``stability`` (``main_name`` among them) do not share a verdict."""
    main = main.reset_index(drop=True)
    seeds = seed_names(stability) if stability is not None else []
    agreement = seed_agreement(main, stability, main_name) if main_name in seeds else None
    return counts_markdown(main, shown_verdicts(main, agreement))


def seeds_counts(stability: pd.DataFrame) -> str:
    """The counts of a stability run of its own: each claim's most common verdict over the seeds,
    ``unstable`` where fewer than 4 of 5 give it."""
    seeds = seed_names(stability)
    modal = stability.assign(verdict=stability["verdict"].where(stability["stable"].astype(bool), UNSTABLE))
    return (
        f"Across the {len(seeds)} seeds ({', '.join(seeds)}): the most common verdict of each claim, "
        f"`unstable` where fewer than 4 of {len(seeds)} give it.\n\n{counts_markdown(modal, modal['verdict'])}"
    )


def results_markdown(
    main: pd.DataFrame,
    main_name: str,
    others: Mapping[str, pd.DataFrame] | None = None,
    run_note: str = "",
    stability: pd.DataFrame | None = None,
) -> str:
    """The body of docs/results.md: ``main`` (the full synthetic run) counted per paper and kind,
    with each verdict's agreement over the seeds of ``stability`` (a claims-stability table with
    ``main_name`` among its seeds; ``unstable`` where fewer than 4 of 5 give it), then one line per
    dataset of ``others`` (name -> claims)."""
    main = main.reset_index(drop=True)
    seeds = seed_names(stability) if stability is not None else []
    same_run = main_name in seeds
    agreement = seed_agreement(main, stability, main_name) if same_run else None
    shown = shown_verdicts(main, agreement)
    seeds_text = ""
    if same_run:
        seeds_text = (
            f" Seeds: {len(seeds)} runs of this configuration, this one among them; a verdict that fewer than 4 "
            f"of {len(seeds)} seeds give is counted as unstable."
        )
    elif stability is not None:
        seeds_text = (
            f" Seeds: {len(seeds)} runs of another configuration ({', '.join(seeds)}); the per-claim columns give "
            "their most common verdict, how many seeds give it and their value's interval, and the counts of those "
            "runs follow below."
        )
    parts = [
        f"Claims of the last run on `{main_name}`{(' (' + run_note + ')') if run_note else ''}. Reproduction "
        "is counted over replication and stand-in claims, each kind apart; consistency claims are checks "
        f"(true by construction or sanity checks), never counted as reproduction.{seeds_text} The report holds "
        "the figures, tables and notes.",
        "",
        readme_counts(main, main_name, stability),
    ]
    if stability is not None and not same_run:
        parts += [seeds_counts(stability)]
    if stability is not None:
        # this run's verdict shared by fewer than 4 of 5 seeds, or (seeds of another configuration) no verdict that is
        unstable = (
            main["claim_id"][(shown == UNSTABLE).to_numpy()]
            if same_run
            else stability["claim_id"][~stability["stable"].astype(bool)]
        )
        parts += [unstable_markdown(stability, list(unstable))] if len(unstable) else []
    for paper, title in PAPER_TITLES.items():
        parts += [f"### {title}", "", paper_results(main, paper, shown, agreement, stability, same_run)]
    if others:
        parts += ["### Real data sets (`config/real/`)", ""]
        for name, table in others.items():
            table = table.reset_index(drop=True)
            na = table[table["verdict"] == "not applicable"]
            skipped = ", ".join(sorted(set(na["source"] + " (" + na["paper"] + ")"))) if len(na) else "none"
            by_kind = "; ".join(
                f"{row['kind']} {counts_text(row)}" for row in kind_counts(table.assign(paper="all")).to_dict("records")
            )
            parts.append(f"- `{name}`: {len(table)} claims: {by_kind}; not applicable: {skipped}.")
        parts.append("")
    return "\n".join(parts)
