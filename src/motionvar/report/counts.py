"""Verdict counts by paper and kind of evidence (docs/claims.md): reproduction is counted over
``replication`` and ``stand-in`` claims, each kind apart; ``consistency`` claims are checks that hold
or fail, never part of a reproduction rate. With a stability run (one dataset per seed,
:func:`motionvar.report.stability.claims_stability`), a verdict that fewer than ``stable_share`` of
the seeds share is counted as ``unstable`` instead."""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence

import numpy as np
import pandas as pd

from ..claims import CHECKED_VERDICTS, EVIDENCE_KINDS, KINDS, UNDECIDED_VERDICTS

UNSTABLE = "unstable"
#: the columns of :func:`kind_counts`, in the order they are shown
COUNT_COLUMNS = (*CHECKED_VERDICTS, UNSTABLE, *UNDECIDED_VERDICTS)
STABLE_SHARE = 0.8  # 4 of 5 seeds


def seed_names(stability: pd.DataFrame) -> list[str]:
    """The seeds of a :func:`motionvar.report.stability.claims_stability` table, in column order."""
    return [c[len("verdict_") :] for c in stability.columns if c.startswith("verdict_")]


def seed_bounds(row: Mapping, seeds: Sequence[str]) -> np.ndarray | None:
    """(S,) the bound of each seed of a stability-table row where the seeds' bounds differ (a bound
    measured on the data, e.g. a recorded reference); None where they share one."""
    bounds = np.array([float(row.get(f"bound_{s}", np.nan)) for s in seeds])
    finite = bounds[np.isfinite(bounds)]
    if len(finite) < 2 or np.all(finite == finite[0]):
        return None
    return bounds


def seed_agreement(table: pd.DataFrame, stability: pd.DataFrame, dataset: str) -> pd.DataFrame:
    """Per claim of ``table`` (one run's merged claims, the run on ``dataset``): ``n_agree``, how
    many seeds of ``stability`` give this run's verdict, and ``n_seeds``; a claim the stability run
    lacks gets 0 of 0."""
    seeds = seed_names(stability)
    if dataset not in seeds:
        raise ValueError(f"the stability run's seeds {seeds} do not include dataset {dataset!r}")
    per_seed = stability.set_index("claim_id")[[f"verdict_{s}" for s in seeds]]
    rows = []
    for claim_id, verdict in zip(table["claim_id"], table["verdict"]):  # tens of claims
        agree = int((per_seed.loc[claim_id] == verdict).sum()) if claim_id in per_seed.index else 0
        rows.append({"claim_id": claim_id, "n_agree": agree, "n_seeds": len(seeds) if agree else 0})
    return pd.DataFrame(rows, columns=["claim_id", "n_agree", "n_seeds"])


def shown_verdicts(
    table: pd.DataFrame, agreement: pd.DataFrame | None = None, stable_share: float = STABLE_SHARE
) -> pd.Series:
    """Each claim's verdict as counted: ``unstable`` where ``agreement`` (:func:`seed_agreement`)
    says fewer than ``stable_share`` of the seeds share it (a claim missing from the stability run
    keeps its verdict)."""
    verdicts = table["verdict"].reset_index(drop=True).copy()
    if agreement is None:
        return verdicts
    a = agreement.set_index("claim_id").reindex(table["claim_id"]).reset_index(drop=True)
    need = (a["n_seeds"] * stable_share - 1e-9).apply(math.ceil)
    unstable = (a["n_seeds"] > 0) & (a["n_agree"] < need)
    verdicts[unstable.to_numpy()] = UNSTABLE
    return verdicts


def kind_counts(table: pd.DataFrame, verdicts: pd.Series | None = None) -> pd.DataFrame:
    """One row per (paper, kind) present in ``table``, in the order of :data:`KINDS`: the number of
    claims and of each verdict of :data:`COUNT_COLUMNS` (``verdicts``, e.g. :func:`shown_verdicts`,
    replaces the table's own)."""
    v = (table["verdict"] if verdicts is None else verdicts).reset_index(drop=True)
    t = table.reset_index(drop=True).assign(_v=v)
    rows = []
    for paper in dict.fromkeys(t["paper"]):
        for kind in KINDS:
            sel = t[(t["paper"] == paper) & (t["kind"] == kind)]
            if len(sel):
                counts = {c: int((sel["_v"] == c).sum()) for c in COUNT_COLUMNS}
                rows.append({"paper": paper, "kind": kind, "claims": len(sel), **counts})
    return pd.DataFrame(rows, columns=["paper", "kind", "claims", *COUNT_COLUMNS])


def counts_text(row: pd.Series | dict) -> str:
    """One row of :func:`kind_counts` in words: ``4 reproduced, 1 partial, 0 not reproduced, 1 unstable``
    (+ the undecided ones) for evidence; ``3 checks: 3 hold, 0 fail`` for consistency."""
    if row["kind"] not in EVIDENCE_KINDS:
        hold = int(row["reproduced"])
        undecided = sum(int(row[c]) for c in UNDECIDED_VERDICTS)
        fail = int(row["claims"]) - hold - undecided
        extra = f", {undecided} undecided" if undecided else ""
        return f"{int(row['claims'])} checks: {hold} hold, {fail} fail{extra}"
    parts = [f"{int(row[c])} {c}" for c in (*CHECKED_VERDICTS, UNSTABLE) if c != UNSTABLE or int(row[c])]
    parts += [f"{int(row[c])} {c}" for c in UNDECIDED_VERDICTS if int(row[c])]
    return ", ".join(parts)
