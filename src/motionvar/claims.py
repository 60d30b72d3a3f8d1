"""Claims: the contract between evaluations and the report (docs/design.md, "Claims").

A claim is one statement a paper makes that our data can check. Its verdict is always
computed from measured numbers by one of the helpers below, never written by hand.
"""

from __future__ import annotations

import json
import math
from collections.abc import Iterable, Sequence
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

import pandas as pd

VERDICTS = ("reproduced", "partial", "not reproduced")
CLAIM_COLUMNS = ("claim_id", "paper", "source", "statement", "published", "measured", "verdict", "note")


@dataclass(frozen=True)
class Claim:
    """One checked statement of a paper.

    ``note`` says why a claim did not reproduce, or what differs from the paper's setup.
    """

    claim_id: str
    paper: str
    source: str
    statement: str
    published: str
    measured: str
    verdict: str
    note: str = ""

    def __post_init__(self) -> None:
        if self.verdict not in VERDICTS:
            raise ValueError(f"claim {self.claim_id}: verdict {self.verdict!r} not in {VERDICTS}")
        if not self.claim_id.startswith(self.paper + "."):
            raise ValueError(f"claim {self.claim_id}: id must start with the paper key {self.paper!r}")


@dataclass
class EvaluationResult:
    """What an evaluation function returns: its ``table`` (written as the evaluation's
    CSV), its ``claims`` (built by the evaluation that measured them) and ``figure``, the
    numbers its figure draws (passed to the paper's ``figures.py``; keys are the
    evaluation's own)."""

    table: pd.DataFrame
    claims: list[Claim]
    figure: dict[str, Any] = field(default_factory=dict)


def verdict_from_bool(ok: bool) -> str:
    """``reproduced`` when the measured condition holds, else ``not reproduced``."""
    return "reproduced" if bool(ok) else "not reproduced"


def verdict_from_fraction(n_ok: int, n_total: int, full: float = 1.0, partial: float = 0.5) -> str:
    """Verdict from the share of cases that agree with the paper: all (>= ``full``) is
    reproduced, at least ``partial`` is partial, less is not reproduced."""
    if n_total <= 0:
        return "not reproduced"
    share = n_ok / n_total
    if share >= full:
        return "reproduced"
    return "partial" if share >= partial else "not reproduced"


def verdict_threshold(value: float, threshold: float, direction: str = "<=", tolerance: float = 0.0) -> str:
    """``reproduced`` when ``value`` meets ``threshold`` in ``direction`` ('<=' or '>='),
    ``partial`` when it misses by at most ``tolerance`` (relative), else not reproduced."""
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return "not reproduced"
    if direction == "<=":
        if value <= threshold:
            return "reproduced"
        return "partial" if value <= threshold * (1 + tolerance) else "not reproduced"
    if direction == ">=":
        if value >= threshold:
            return "reproduced"
        return "partial" if value >= threshold * (1 - tolerance) else "not reproduced"
    raise ValueError(f"direction must be '<=' or '>=', got {direction!r}")


def write_claims(path: str | Path, claims: Sequence[Claim]) -> None:
    """Write claims as a JSON list (one evaluation's claims file)."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    ids = [c.claim_id for c in claims]
    if len(set(ids)) != len(ids):
        raise ValueError(f"{path}: duplicate claim ids {ids}")
    path.write_text(json.dumps([asdict(c) for c in claims], indent=2) + "\n")


def read_claims(path: str | Path) -> list[Claim]:
    """Read one claims JSON file; ValueError naming the file when it is malformed."""
    path = Path(path)
    try:
        records = json.loads(path.read_text())
        return [Claim(**r) for r in records]
    except (json.JSONDecodeError, TypeError, ValueError) as exc:
        raise ValueError(f"{path}: not a valid claims file ({exc})") from exc


def merge_claims(paths: Iterable[str | Path]) -> pd.DataFrame:
    """All claims of the given files as one table (empty with the right columns if none)."""
    rows = [asdict(c) for p in sorted(map(str, paths)) for c in read_claims(p)]
    table = pd.DataFrame(rows, columns=list(CLAIM_COLUMNS))
    dup = table["claim_id"][table["claim_id"].duplicated()]
    if len(dup):
        raise ValueError(f"claim ids reported by more than one evaluation: {sorted(set(dup))}")
    return table.sort_values("claim_id", kind="stable").reset_index(drop=True)
