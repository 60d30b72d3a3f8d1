"""The motions of the animation of generated idle motion (Egges et al. 2004, Sec. 5.6,
Fig. 10: personalised idle motion from different people's databases)."""

from __future__ import annotations

from ...core.motion import Motion
from ..engine import generate_idle
from ..pipeline import IdleModel
from .common import subject_rng


def idle_animation(model: IdleModel, subjects: int, seconds: float, seed: int) -> tuple[list[Motion], list[str]]:
    """``seconds`` of generated idle motion for each of the first ``subjects`` subjects,
    and a label per motion."""
    shown = list(model.databases)[:subjects]
    motions = [
        generate_idle(model.databases[s], model.pca, model.skeletons[s], seconds, subject_rng(seed, s, "animation"))
        for s in shown
    ]
    return motions, [f"subject {s} (generated)" for s in shown]
