"""What an evaluation needs from a dataset, and whether a dataset has it.

Each paper declares, per evaluation, the clips it needs (:class:`Need`: which behaviour,
style, variant or primitive, how many, from how many subjects) in its
``requirements.py``. :func:`unmet_reason` checks them against a dataset's metadata (the
imported clips, ``data/metadata.csv``, and the segmented primitives,
``prep/metadata.csv``) and says in words what is missing. An evaluation whose needs are
not met is not run: it gets the verdict ``not applicable`` with that reason
(:func:`motionvar.claims.not_applicable_result`). The decision comes from the data,
never from the dataset's name.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field

import pandas as pd

STAGES = ("data", "prep")


@dataclass(frozen=True)
class Need:
    """At least ``min_count`` rows of one stage's metadata (``"data"``: clips as
    imported; ``"prep"``: primitives after segmentation) whose columns take one of the
    given values (``where``: column -> accepted values; an empty tuple accepts any),
    from at least ``min_subjects`` subjects, with at least ``min_distinct[column]``
    distinct values of a column among them; with ``min_seconds``, only rows of at least
    that duration (columns ``n_frames`` and ``fps``) count. ``what`` names them in
    messages ("neutral forward walks"), ``why`` says what the paper does with them."""

    what: str
    why: str
    stage: str = "data"
    where: Mapping[str, tuple[str, ...]] = field(default_factory=dict)
    min_count: int = 1
    min_subjects: int = 1
    min_distinct: Mapping[str, int] = field(default_factory=dict)
    min_seconds: float = 0.0

    def __post_init__(self) -> None:
        if self.stage not in STAGES:
            raise ValueError(f"Need {self.what!r}: stage {self.stage!r} not in {STAGES}")


@dataclass(frozen=True)
class Requirement:
    """What one evaluation checks (``source``: the paper's figure or section; ``checks``:
    one line) and the clips it needs."""

    evaluation: str
    paper: str
    source: str
    checks: str
    needs: tuple[Need, ...] = ()


def _matching(need: Need, meta: pd.DataFrame) -> pd.DataFrame:
    mask = pd.Series(True, index=meta.index)
    for column, accepted in need.where.items():
        values = [accepted] if isinstance(accepted, str) else list(accepted)
        if not values:
            continue
        if column not in meta:
            return meta.iloc[0:0]
        mask &= meta[column].astype(str).isin([str(v) for v in values])
    if need.min_seconds > 0:
        if not {"n_frames", "fps"} <= set(meta.columns):
            return meta.iloc[0:0]
        seconds = pd.to_numeric(meta["n_frames"], errors="coerce") / pd.to_numeric(meta["fps"], errors="coerce")
        mask &= seconds >= need.min_seconds
    return meta[mask]


def _filters(need: Need) -> str:
    parts = [f"{c} {'/'.join(map(str, v))}" for c, v in need.where.items() if v]
    parts += [f"at least {need.min_seconds:g} s long"] if need.min_seconds > 0 else []
    return ", ".join(parts) if parts else "any"


def unmet(need: Need, meta: pd.DataFrame) -> str | None:
    """Why ``meta`` (one stage's metadata) does not meet ``need``, or None."""
    rows = _matching(need, meta)
    unit = "clips" if need.stage == "data" else "segmented primitives"
    found = f"the dataset has {len(rows)}" if len(rows) else "the dataset has none"
    if len(rows) < need.min_count:
        return f"needs at least {need.min_count} {need.what} ({unit} with {_filters(need)}), {found}: {need.why}"
    if need.min_subjects > 1:
        n_subjects = rows["subject"].nunique() if "subject" in rows else 0
        if n_subjects < need.min_subjects:
            return (
                f"needs {need.what} from at least {need.min_subjects} subjects, the dataset has "
                f"{n_subjects}: {need.why}"
            )
    for column, minimum in need.min_distinct.items():
        values = rows[column].replace("", pd.NA).dropna().astype(str) if column in rows else pd.Series([], dtype=str)
        if values.nunique() < minimum:
            have = sorted(values.unique())
            return (
                f"needs {need.what} with at least {minimum} different {column} values, the dataset has "
                f"{len(have)}{' (' + ', '.join(have) + ')' if have else ''}: {need.why}"
            )
    return None


def unmet_reason(requirement: Requirement, metadata: Mapping[str, pd.DataFrame]) -> str | None:
    """The reason ``requirement`` is not met by the dataset (``metadata``: stage ->
    metadata table), all unmet needs joined; None when every need is met."""
    reasons = [r for need in requirement.needs if (r := unmet(need, metadata[need.stage])) is not None]
    return "; ".join(reasons) if reasons else None


def applicability_table(requirements: Sequence[Requirement], metadata: Mapping[str, pd.DataFrame]) -> pd.DataFrame:
    """One row per evaluation: evaluation, paper, source, checks, applicable, reason."""
    rows = []
    for req in requirements:
        reason = unmet_reason(req, metadata)
        rows.append(
            {
                "evaluation": req.evaluation,
                "paper": req.paper,
                "source": req.source,
                "checks": req.checks,
                "applicable": reason is None,
                "reason": reason or "",
            }
        )
    return pd.DataFrame(rows, columns=["evaluation", "paper", "source", "checks", "applicable", "reason"])
