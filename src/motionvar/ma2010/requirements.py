"""What the Ma et al. 2010 evaluations need from a dataset (:mod:`motionvar.applicability`):
walking clips of the modelled styles and variants, long enough to hold gait cycles."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..applicability import Joints, Need, Requirement
from .catalog import EVALUATIONS
from .claims import FIG8_MIN_EXAMPLES, FIG8_MIN_SUBJECTS

if TYPE_CHECKING:
    from .settings import Ma2010Settings


# A walking clip holds a complete gait cycle (Sec. 4.2: legs farthest apart, left foot
# ahead, to the next such frame) when it has two foot strikes of each foot: ~2 s of walking.
MIN_WALK_S = 2.0

# the least the model of Sec. 5-6 is fitted to: two walking clips (one subject); an evaluation
# not listed in WALKS_NEEDED needs that
MODEL_WALKS = (2, 1)
# evaluation (.catalog) -> the minimum number of walking clips it needs, and of subjects, where it
# needs more than the model (or, Fig. 3, less)
WALKS_NEEDED = {
    "ma2010_fig3": (1, 1),
    # the variants' spread is compared with that of the example cycles nearest the style, one per subject
    # (Fig. 1's clips): at least FIG8_MIN_EXAMPLES of them, so as many subjects (and at least FIG8_MIN_SUBJECTS)
    "ma2010_fig8": (FIG8_MIN_EXAMPLES, max(FIG8_MIN_EXAMPLES, FIG8_MIN_SUBJECTS)),
    # the example cycles are taken one per subject (Fig. 1's five clips)
    "ma2010_sec7_4": (2, 2),
}


# evaluation -> why it needs more than walking cycles (appended to the requirement's reason)
WHY = {
    "ma2010_fig8": f"; Fig. 8a compares the spread of variants at one style with that of the example cycles nearest "
    f"it, one per subject, and needs at least {FIG8_MIN_EXAMPLES} of them",
}


# the footskate cleanup stands each foot on its ankle or its toe (Sec. 5; ma2010.examples.root_solver)
TOES = Joints(("left_toe", "right_toe"), "Ma 2010's footskate cleanup stands each foot on its ankle or its toe")


def requirements(settings: Ma2010Settings) -> list[Requirement]:
    """One requirement per evaluation: walking clips (``behaviour`` walk) of the settings'
    ``walk_styles`` and ``walk_variants`` (an empty list accepts any)."""
    walk_styles, walk_variants = settings.clips.walk_styles, settings.clips.walk_variants
    styles = "/".join(walk_styles) if walk_styles else "any-style"
    where = {"behaviour": ("walk",), "style": tuple(walk_styles), "variant": tuple(walk_variants)}
    out = []
    for ev in EVALUATIONS:
        n, subjects = WALKS_NEEDED.get(ev.name, MODEL_WALKS)
        need = Need(
            what=f"{styles} walking clips",
            stage="data",
            where=where,
            min_count=n,
            min_subjects=subjects,
            min_seconds=MIN_WALK_S,
            why="Ma 2010 models the gait cycles of walking (Sec. 4; a cycle needs two foot strikes of each "
            "foot); set ma2010.clips.walk_styles and ma2010.clips.walk_variants to labels your data has"
            + WHY.get(ev.name, ""),
        )
        out.append(Requirement.of(ev, (need,), TOES))
    return out
