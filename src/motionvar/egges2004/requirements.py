"""What the Egges et al. 2004 evaluations need from a dataset
(:mod:`motionvar.applicability`): recordings of standing idle motion."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..applicability import Need, Requirement

if TYPE_CHECKING:
    from .settings import Egges2004Settings

PAPER = "egges2004"

WHY = "Egges 2004 builds its model from recordings of a person standing idle (balance shifts, Sec. 5)"


def requirements(settings: Egges2004Settings) -> list[Requirement]:
    """Idle clips (``behaviour`` idle): more than the settings' ``held_out_clips`` per subject
    for the database and its held-out test recordings; two subjects or more to identify people."""
    held_out_clips = settings.held_out_clips
    idle = Need(
        what="idle recordings", stage="data", where={"behaviour": ("idle",)}, min_count=held_out_clips + 1, why=WHY
    )
    people = Need(
        what="idle recordings",
        stage="data",
        where={"behaviour": ("idle",)},
        min_count=2 * (held_out_clips + 1),
        min_subjects=2,
        why="Sec. 8 tells people apart by their generated idle motion",
    )
    return [
        Requirement(
            "egges2004_identification",
            PAPER,
            "Sec. 8",
            "Generated idle motion is recognisably the person's own.",
            (idle, people),
        ),
        Requirement(
            "egges2004_repetition",
            PAPER,
            "Sec. 6",
            "Generated idle motion does not repeat itself, unlike a looped clip.",
            (idle,),
        ),
        Requirement(
            "egges2004_fitting",
            PAPER,
            "Sec. 5.4.4, Fig. 4-5",
            "Fitted animations start and end at the given postures; the pieces join smoothly.",
            (idle,),
        ),
        Requirement("egges2004_speed", PAPER, "Sec. 8", "Idle motion is generated in real time.", (idle,)),
    ]
