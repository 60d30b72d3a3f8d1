"""Claims: the contract between evaluations and the report (docs/design.md, "Claims").

A claim is one statement a paper makes that our data can check. Its verdict is always
computed from measured numbers by one of the helpers below, never written by hand.

Verdicts of a claim that was checked: ``reproduced``, ``partial``, ``not reproduced``.
Two more say why a claim was not decided, each with its reason in the note:
``not testable`` (even the ideal, e.g. brute force, cannot meet the bar on this data) and
``not applicable`` (the dataset lacks what the evaluation needs: no idle clips, one
subject). An evaluation that finds its input insufficient raises :class:`NotApplicable`
or returns :func:`not_applicable_result`.
"""

from __future__ import annotations

import json
import math
import numbers
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:  # pandas is imported where a table is built: every rule imports this module, not all need it
    import pandas as pd

CHECKED_VERDICTS = ("reproduced", "partial", "not reproduced")
UNDECIDED_VERDICTS = ("not testable", "not applicable")
VERDICTS = CHECKED_VERDICTS + UNDECIDED_VERDICTS
#: the kinds of evidence (docs/claims.md): the paper's own experiment, a stated proxy for what the paper judged by
#: eye or cited, and a check that is true by construction (listed, never counted as reproduction)
KINDS = ("replication", "stand-in", "consistency")
#: the kinds that count towards a reproduction rate, each apart
EVIDENCE_KINDS = ("replication", "stand-in")
TEXT_COLUMNS = ("claim_id", "paper", "source", "kind", "statement", "published", "measured", "verdict", "note")
CLAIM_COLUMNS = (*TEXT_COLUMNS, "value", "bound", "unit", "direction")
#: how a claim's ``value`` is compared with its ``bound`` for the verdict
DIRECTIONS = ("<=", ">=", "<", ">", "")


@dataclass(frozen=True)
class Claim:
    """One checked statement of a paper.

    ``note`` says why a claim did not reproduce, or what differs from the paper's setup.
    ``value`` is the number the verdict is computed from (in ``unit``), ``bound`` the number
    it is compared with in ``direction`` (e.g. max stride error 1.88 "<=" 1.2 cm; a share of
    cases 0.8 ">=" 1.0): what a stability run aggregates over seeds. Claims without a single
    deciding number leave them None (claims files written before these fields still read).
    """

    claim_id: str
    paper: str
    source: str
    kind: str
    statement: str
    published: str
    measured: str
    verdict: str
    note: str = ""
    value: float | None = None
    bound: float | None = None
    unit: str = ""
    direction: str = ""

    def __post_init__(self) -> None:
        if self.verdict not in VERDICTS:
            raise ValueError(f"claim {self.claim_id}: verdict {self.verdict!r} not in {VERDICTS}")
        if not self.claim_id.startswith(self.paper + "."):
            raise ValueError(f"claim {self.claim_id}: id must start with the paper key {self.paper!r}")
        if self.verdict in UNDECIDED_VERDICTS and not self.note.strip():
            raise ValueError(f"claim {self.claim_id}: a {self.verdict!r} claim needs its reason in the note")
        if self.kind not in KINDS:
            raise ValueError(f"claim {self.claim_id}: kind {self.kind!r} not in {KINDS}")
        if self.direction not in DIRECTIONS:
            raise ValueError(f"claim {self.claim_id}: direction {self.direction!r} not in {DIRECTIONS}")
        for name in ("value", "bound"):
            v = getattr(self, name)
            if v is not None:
                if isinstance(v, bool) or not isinstance(v, numbers.Real):
                    raise ValueError(f"claim {self.claim_id}: {name} must be a number or None; got {v!r}")
                object.__setattr__(self, name, float(v))  # numpy scalars -> float (JSON)


@dataclass(frozen=True)
class Judgement:
    """What a claim's verdict function makes of its evaluation's measurements: the verdict, the
    measured numbers as text, the number it was decided on (``value`` against ``bound`` in
    ``direction``, in ``unit``) and the note (at most three sentences: what was measured, how it
    differs from the paper's setup)."""

    verdict: str
    measured: str
    note: str = ""
    value: float | None = None
    bound: float | None = None
    unit: str = ""
    direction: str = ""


@dataclass(frozen=True)
class ClaimSpec:
    """One claim as its paper declares it (``motionvar.<paper>.claims``): what the paper states,
    where, the kind of evidence our check is, the bound in words, and ``judge``, the function from
    the measurements of ``evaluation`` (a mapping of numbers, :attr:`EvaluationResult.measurements`)
    to a :class:`Judgement`. The verdict is computed there and nowhere else."""

    claim_id: str
    evaluation: str
    source: str
    kind: str
    statement: str
    published: str
    bound: str
    judge: Callable[[Mapping[str, Any]], Judgement]

    def __post_init__(self) -> None:
        if self.kind not in KINDS:
            raise ValueError(f"claim {self.claim_id}: kind {self.kind!r} not in {KINDS}")
        if not self.claim_id.startswith(self.paper + ".") or not self.evaluation.startswith(self.paper + "_"):
            raise ValueError(f"claim {self.claim_id}: id and evaluation {self.evaluation!r} must name one paper")

    @property
    def paper(self) -> str:
        return self.claim_id.partition(".")[0]

    def claim(self, measurements: Mapping[str, Any]) -> Claim:
        """The claim with its verdict, judged from ``measurements``."""
        j = self.judge(measurements)
        return Claim(
            claim_id=self.claim_id,
            paper=self.paper,
            source=self.source,
            kind=self.kind,
            statement=self.statement,
            published=self.published,
            measured=j.measured,
            verdict=j.verdict,
            note=j.note,
            value=j.value,
            bound=j.bound,
            unit=j.unit,
            direction=j.direction,
        )

    def undecided(self, verdict: str, reason: str) -> Claim:
        """The claim left undecided (``not applicable`` or ``not testable``) with ``reason``."""
        if verdict not in UNDECIDED_VERDICTS:
            raise ValueError(f"claim {self.claim_id}: {verdict!r} is not one of {UNDECIDED_VERDICTS}")
        return Claim(
            claim_id=self.claim_id,
            paper=self.paper,
            source=self.source,
            kind=self.kind,
            statement=self.statement,
            published=self.published,
            measured="-",
            verdict=verdict,
            note=reason,
        )


def judge_claims(specs: Iterable[ClaimSpec], evaluation: str, measurements: Mapping[str, Any]) -> list[Claim]:
    """The claims of ``evaluation`` among ``specs`` (a paper's declarations), in declaration order,
    each judged from ``measurements``."""
    claims = [spec.claim(measurements) for spec in specs if spec.evaluation == evaluation]
    if not claims:
        raise ValueError(f"no claim declared for evaluation {evaluation!r}")
    return claims


def specs_table(specs: Iterable[ClaimSpec]) -> pd.DataFrame:
    """A paper's declarations as one table (id, evaluation, source, kind, statement, published,
    bound): every claim and its bound on one screen."""
    import pandas as pd

    cols = ("claim_id", "evaluation", "source", "kind", "statement", "published", "bound")
    return pd.DataFrame([{c: getattr(s, c) for c in cols} for s in specs], columns=list(cols))


class NotApplicable(Exception):
    """Raised by an evaluation (or the loading of its inputs) when the dataset lacks what
    it needs; the rule then writes :func:`not_applicable_result` with ``reason``
    instead of failing. ``reason`` speaks of the user's data ("no idle clips: Egges 2004
    needs standing idle motion")."""

    def __init__(self, reason: str) -> None:
        super().__init__(reason)
        self.reason = reason


@dataclass(frozen=True)
class Evaluation:
    """One published evaluation as its paper's package declares it (``<paper>/catalog.py``); the
    workflow makes its rule from this declaration alone (workflow/rules/evaluations.smk).

    ``name`` (``<paper>_<what>``) names its rule, its report caption (``workflow/report/<name>.rst``)
    and its claims (``ClaimSpec.evaluation``); ``source`` is the paper's figure or section,
    ``checks`` what it checks in one line, ``section`` the config section whose settings it reads,
    ``label`` how the report names it (``source`` where empty).

    How it runs: ``inputs`` names the input set the workflow loads for it (its files and their
    loader: ``add_input_set`` in the paper's rule files, ``workflow/scripts/_evaluation.py``), passed to
    ``measure`` as keyword arguments with ``settings=`` the section's settings (where ``measure``
    takes them); ``measure`` returns an :class:`EvaluationResult` and ``draw`` its figure. Both are
    ``"module:function"`` names, imported when the rule runs (:func:`resolve`). ``table_format``:
    the table's float format (pandas ``float_format``; empty: repr), ``dpi``: the figure's,
    ``mem_mb``: the rule's memory. ``own_keys``: the keys (or subsections) of its section that only
    this evaluation reads; no other rule is given them, so an edit of one reruns this evaluation
    alone. An evaluation with outputs besides its table, figure and claims (a GIF) has its own
    script, ``workflow/scripts/<name>.py``, which writes them after ``_rule.write_declared``."""

    name: str
    source: str
    checks: str
    section: str
    label: str = ""
    inputs: str = ""
    measure: str = ""
    draw: str = ""
    table_format: str = ""
    dpi: int = 110
    mem_mb: int = 3000
    own_keys: tuple[str, ...] = ()

    @property
    def paper(self) -> str:
        return self.name.split("_", 1)[0]

    @property
    def shown(self) -> str:
        return self.label or self.source


def resolve(name: str) -> Callable[..., Any]:
    """The function a declaration names as ``"module:function"`` (:class:`Evaluation`);
    ValueError naming it when the module or the function is not there."""
    import importlib

    module, _, attr = name.partition(":")
    try:
        return getattr(importlib.import_module(module), attr)
    except (ImportError, AttributeError) as exc:
        raise ValueError(f"{name!r} names no function (module:function): {exc}") from exc


@dataclass
class EvaluationResult:
    """What an evaluation function returns: its ``table`` (written as the evaluation's
    CSV), its ``claims`` (judged from ``measurements`` by the paper's declarations,
    :func:`judge_claims`), ``figure``, the numbers its figure draws (passed to the paper's
    ``figures.py``; keys are the evaluation's own), and ``measurements``, the numbers its
    claims are judged from."""

    table: pd.DataFrame
    claims: list[Claim]
    figure: dict[str, Any] = field(default_factory=dict)
    measurements: dict[str, Any] = field(default_factory=dict)


_SOURCE_KINDS = {"fig": "Fig.", "table": "Table", "sec": "Sec."}


def evaluation_source(evaluation: str) -> str:
    """The paper's label of an evaluation from its name: ``ma2010_fig6`` -> "Fig. 6",
    ``du2022_sec4_6_1`` -> "Sec. 4.6.1" (the name itself when it follows no pattern)."""
    parts = evaluation.split("_")[1:]
    for i, part in enumerate(parts):
        for prefix, label in _SOURCE_KINDS.items():
            if part.startswith(prefix) and part[len(prefix) :].isdigit():
                return f"{label} {'.'.join([part[len(prefix) :], *parts[i + 1 :]])}"
    return evaluation


def not_applicable_result(
    evaluation: str, reason: str, specs: Iterable[ClaimSpec] = (), checks: str = "", source: str = ""
) -> EvaluationResult:
    """The outputs of an evaluation that a dataset cannot support: each of its claims (``specs``,
    the paper's declarations; those of other evaluations are skipped) with verdict ``not
    applicable`` and ``reason`` in its note, a one-row table saying so, and the reason for the
    figure. ``checks`` says in words what the evaluation checks (the table's column)."""
    import pandas as pd

    paper = evaluation.partition("_")[0]
    source = source or evaluation_source(evaluation)
    claims = [s.undecided("not applicable", reason) for s in specs if s.evaluation == evaluation]
    row = {"evaluation": evaluation, "source": source, "checks": checks or f"the checks of {source}"}
    table = pd.DataFrame([{**row, "verdict": "not applicable", "reason": reason}])
    return EvaluationResult(
        table=table, claims=claims, figure={"title": f"{paper} {source}", "reason": reason, "not_applicable": True}
    )


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
    path.write_text(json.dumps([asdict(c) for c in claims], indent=2, allow_nan=True) + "\n")


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
    import pandas as pd

    rows = [asdict(c) for p in sorted(map(str, paths)) for c in read_claims(p)]
    table = pd.DataFrame(rows, columns=list(CLAIM_COLUMNS))
    dup = table["claim_id"][table["claim_id"].duplicated()]
    if len(dup):
        raise ValueError(f"claim ids reported by more than one evaluation: {sorted(set(dup))}")
    return table.sort_values("claim_id", kind="stable").reset_index(drop=True)
