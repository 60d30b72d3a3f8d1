"""What an evaluation needs from a dataset, and whether a dataset has it.

Each paper declares, per evaluation, the clips it needs (:class:`Need`: which behaviour,
style, variant or primitive, how many, from how many subjects) and the hands or toes it
needs from the rig (:class:`Joints`) in its ``requirements.py``. :func:`unmet_reason` checks them against a dataset's metadata (the
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

from .claims import Evaluation
from .core.joint_map import JointMap

STAGES = ("data", "prep")


@dataclass(frozen=True)
class Need:
    """At least ``min_count`` rows of one stage's metadata (``"data"``: clips as
    imported; ``"prep"``: primitives after segmentation) whose columns take one of the
    given values (``where``: column -> accepted values; an empty tuple accepts any),
    from at least ``min_subjects`` subjects, with at least ``min_distinct[column]``
    distinct values of a column among them; with ``min_seconds``, only rows of at least
    that duration (columns ``n_frames`` and ``fps``) count; with ``min_per_subject``, only
    the rows of subjects that have at least that many (a model built per person). ``what``
    names them in messages ("neutral forward walks"), ``why`` says what the paper does with
    them."""

    what: str
    why: str
    stage: str = "data"
    where: Mapping[str, tuple[str, ...]] = field(default_factory=dict)
    min_count: int = 1
    min_subjects: int = 1
    min_distinct: Mapping[str, int] = field(default_factory=dict)
    min_seconds: float = 0.0
    min_per_subject: int = 1

    def __post_init__(self) -> None:
        if self.stage not in STAGES:
            raise ValueError(f"Need {self.what!r}: stage {self.stage!r} not in {STAGES}")


@dataclass(frozen=True)
class Joints:
    """Semantic joints of :data:`~motionvar.core.joint_map.OPTIONAL_JOINTS` (hands, toes) that
    an evaluation needs from the rig; ``why`` says what the paper does with them."""

    names: tuple[str, ...]
    why: str


@dataclass(frozen=True)
class Requirement:
    """What one evaluation checks (``source``: the paper's figure or section; ``checks``:
    one line), the clips it needs and the joints it needs from the rig."""

    evaluation: str
    paper: str
    source: str
    checks: str
    needs: tuple[Need, ...] = ()
    joints: Joints | None = None

    @classmethod
    def of(cls, evaluation: Evaluation, needs: tuple[Need, ...] = (), joints: Joints | None = None) -> Requirement:
        """The requirement of a declared evaluation (its name, paper, source and checks)."""
        return cls(evaluation.name, evaluation.paper, evaluation.source, evaluation.checks, needs, joints)


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
    parts += [f"at least {need.min_per_subject} of a subject"] if need.min_per_subject > 1 else []
    return ", ".join(parts) if parts else "any"


def _per_subject(need: Need, rows: pd.DataFrame) -> pd.DataFrame:
    """``rows`` of the subjects that have at least ``need.min_per_subject`` of them."""
    if need.min_per_subject <= 1:
        return rows
    if "subject" not in rows:
        return rows.iloc[0:0]
    counts = rows["subject"].astype(str).value_counts()
    return rows[rows["subject"].astype(str).isin(counts[counts >= need.min_per_subject].index)]


def unmet(need: Need, meta: pd.DataFrame) -> str | None:
    """Why ``meta`` (one stage's metadata) does not meet ``need``, or None."""
    rows = _per_subject(need, _matching(need, meta))
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


def lacking_joints(joints: Joints, joint_map: JointMap) -> str | None:
    """Why the rig of ``joint_map`` does not have ``joints``, or None."""
    lacking = [j for j in joints.names if not joint_map.has(j)]
    if not lacking:
        return None
    where = f" ({joint_map.origin})" if joint_map.origin else ""
    return f"needs the rig's {', '.join(lacking)}, which the joint map{where} leaves out: {joints.why}"


def unmet_reason(
    requirement: Requirement, metadata: Mapping[str, pd.DataFrame], joint_map: JointMap | None = None
) -> str | None:
    """The reason ``requirement`` is not met by the dataset (``metadata``: stage ->
    metadata table; ``joint_map``: its rig's, None for one with every semantic joint), all
    unmet needs joined; None when every need is met."""
    reasons = [r for need in requirement.needs if (r := unmet(need, metadata[need.stage])) is not None]
    if requirement.joints is not None and joint_map is not None:
        reasons += [r] if (r := lacking_joints(requirement.joints, joint_map)) else []
    return "; ".join(reasons) if reasons else None


def applicability_table(
    requirements: Sequence[Requirement], metadata: Mapping[str, pd.DataFrame], joint_map: JointMap | None = None
) -> pd.DataFrame:
    """One row per evaluation: evaluation, paper, source, checks, applicable, reason."""
    rows = []
    for req in requirements:
        reason = unmet_reason(req, metadata, joint_map)
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
