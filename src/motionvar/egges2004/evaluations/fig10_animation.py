"""The motions of the animation of generated idle motion (Egges et al. 2004, Sec. 5.6,
Fig. 10: personalised idle motion from different people's databases)."""

from __future__ import annotations

from ...core.motion import Motion
from ..engine import generate_idle
from ..pipeline import IdleModel
from ..settings import Egges2004Settings
from .common import subject_rng


def idle_animation(model: IdleModel, settings: Egges2004Settings) -> tuple[list[Motion], list[str]]:
    """``settings.animation.seconds`` of generated idle motion for each of the first
    ``settings.figure_subjects`` subjects, and a label per motion."""
    shown = list(model.databases)[: settings.figure_subjects]
    seconds, seed = settings.animation.seconds, settings.seed
    motions = [
        generate_idle(model.databases[s], model.pca, model.skeletons[s], seconds, subject_rng(seed, s, "animation"))
        for s in shown
    ]
    return motions, [f"subject {s} (generated)" for s in shown]
