"""What the Egges et al. 2004 evaluations need from a dataset
(:mod:`motionvar.applicability`): recordings of standing idle motion."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..applicability import Need, Requirement
from .catalog import EVALUATIONS

if TYPE_CHECKING:
    from .settings import Egges2004Settings


WHY = "Egges 2004 builds its model from recordings of a person standing idle (balance shifts, Sec. 5)"


def requirements(settings: Egges2004Settings) -> list[Requirement]:
    """Idle clips (``behaviour`` idle) per person: with ``held_out_by: clips`` more than the
    settings' ``held_out_clips`` of one subject, for the database and its held-out test
    recordings; with ``held_out_by: time`` one recording of a subject, and for identification
    one long enough that its held-out end holds an identification window. Two such subjects
    or more to identify people. A subject who has fewer is left out of the model, not the
    paper (:func:`~.pipeline.split_clips`)."""
    if settings.held_out_by == "time":
        per_subject, long_s = 1, settings.identification.window_s / settings.held_out_fraction
        windows = (
            f"; its held-out end (egges2004.held_out_fraction {settings.held_out_fraction:g}) must hold one "
            f"{settings.identification.window_s:g} s window (egges2004.identification.window_s)"
        )
    else:
        per_subject, long_s, windows = settings.held_out_clips + 1, 0.0, ""
    idle = Need(
        what="idle recordings",
        stage="data",
        where={"behaviour": ("idle",)},
        min_count=per_subject,
        min_per_subject=per_subject,
        why=WHY,
    )
    people = Need(
        what="idle recordings",
        stage="data",
        where={"behaviour": ("idle",)},
        min_count=2 * per_subject,
        min_subjects=2,
        min_per_subject=per_subject,
        min_seconds=long_s,
        why="Sec. 8 tells people apart by their generated idle motion" + windows,
    )
    declared = {e.name: e for e in EVALUATIONS}
    return [
        Requirement.of(declared["egges2004_identification"], (idle, people)),
        Requirement.of(declared["egges2004_repetition"], (idle,)),
        Requirement.of(declared["egges2004_fitting"], (idle,)),
        Requirement.of(declared["egges2004_speed"], (idle,)),
    ]
