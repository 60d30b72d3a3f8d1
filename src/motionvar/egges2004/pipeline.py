"""From a dataset's idle clips to one idle-motion database per person (Egges et al. 2004,
Sec. 5.6): select the idle clips, hold some out per subject, fit the posture PCA on the
training clips of all subjects (Sec. 3.2) and build each subject's database; for a
fitted model, its training and held-out clips analysed again (PC values, support ratio).
The model is saved by :mod:`.storage`; its categories are checked against the ground
truth by :mod:`.evaluations.fig3_categories`.
"""

from __future__ import annotations

import logging
import re
from dataclasses import dataclass

import numpy as np
import pandas as pd

from ..core.joint_map import JointMap
from ..core.motion import Motion
from ..core.skeleton import Skeleton
from ..io.dataset import MotionDataset
from .database import IdleDatabase, Recording, analyse_recording, build_database
from .pca import PosturePCA
from .settings import Egges2004Settings

log = logging.getLogger(__name__)


@dataclass
class IdleModel:
    """The fitted idle engine of a dataset: the shared posture PCA, one database per
    subject, each subject's skeleton, and which clips trained and which were held out."""

    pca: PosturePCA
    databases: dict[str, IdleDatabase]
    skeletons: dict[str, Skeleton]
    train_clips: dict[str, list[str]]
    test_clips: dict[str, list[str]]


def idle_clips(dataset: MotionDataset, source: str) -> dict[str, list[tuple[pd.Series, Motion]]]:
    """Subject -> [(metadata row, Motion)] of the clips with behaviour ``idle``, by clip_id."""
    meta = dataset.metadata
    missing = [c for c in ("clip_id", "subject", "behaviour") if c not in meta.columns]
    if missing:
        raise ValueError(f"{source}: metadata lacks columns {missing}")
    mask = (meta["behaviour"] == "idle").to_numpy()
    if not mask.any():
        raise ValueError(f"{source}: no idle clips (behaviour == 'idle'); Egges 2004 needs recordings of standing")
    out: dict[str, list[tuple[pd.Series, Motion]]] = {}
    for row, motion in sorted(dataset.select(mask), key=lambda rm: str(rm[0]["clip_id"])):
        out.setdefault(str(row["subject"]), []).append((row, motion))
    return dict(sorted(out.items()))


Clips = dict[str, list[tuple[pd.Series, Motion]]]

#: a held-out or training part of a recording: ``<clip_id>[<start>:<stop>]`` (frames)
_SPAN = re.compile(r"^(?P<clip>.+)\[(?P<start>\d+):(?P<stop>\d+)\]$")


def split_clips(clips: Clips, held_out: int) -> tuple[Clips, Clips]:
    """Per subject, the last ``held_out`` clips (by clip_id) for testing, the rest for
    training. A subject with ``held_out`` or fewer clips is left out, with a line in the log;
    ValueError when no subject is left."""
    short = [s for s, c in clips.items() if len(c) <= held_out]
    for s in short:
        log.warning(
            "subject %s left out of Egges 2004: %d idle clip(s), need more than egges2004.held_out_clips = %d "
            "(or egges2004.held_out_by: time, to hold out the end of each recording)",
            s,
            len(clips[s]),
            held_out,
        )
    kept = {s: c for s, c in clips.items() if s not in short}
    if not kept:
        raise ValueError(
            f"every subject has {held_out} or fewer idle clips; need more than egges2004.held_out_clips = {held_out} "
            "(or egges2004.held_out_by: time, to hold out the end of each recording)"
        )
    train = {s: c[: len(c) - held_out] for s, c in kept.items()}
    test = {s: c[len(c) - held_out :] for s, c in kept.items()}
    return train, test


def rest_cut(motion: Motion, target: int, search_s: float, smooth_s: float = 1.0) -> int:
    """The frame within ``search_s`` seconds of ``target`` where the pelvis moves least over
    the ground (its horizontal speed averaged over ``smooth_s`` s): a cut there falls in a rest,
    so the balance shifts on either side stay whole (Sec. 5.1's units: rests and the shifts
    between them)."""
    n = motion.n_frames
    if n < 3:
        return target
    root = motion.root_pos[:, [0, 2]]
    speed = np.linalg.norm(np.gradient(root, axis=0), axis=1)
    w = max(1, int(round(smooth_s * motion.fps)))
    speed = np.convolve(speed, np.ones(w) / w, mode="same")
    r = int(round(search_s * motion.fps))
    lo, hi = max(1, target - r), min(n - 1, target + r + 1)
    return lo + int(np.argmin(speed[lo:hi])) if hi > lo else target


def split_recordings(clips: Clips, fraction: float, search_s: float) -> tuple[Clips, Clips]:
    """Per recording, its first frames for training and about its last ``fraction`` of them
    held out, cut at a rest within ``search_s`` s of that point (:func:`rest_cut`; each part's
    clip_id ``<clip_id>[<start>:<stop>]``): one long recording per person serves both, as the
    paper builds a database from "one or more recorded animations" (Sec. 5.6)."""
    train: Clips = {}
    test: Clips = {}
    for subject, rows in clips.items():
        for row, motion in rows:
            cut = rest_cut(motion, motion.n_frames - int(round(fraction * motion.n_frames)), search_s)
            for out, (a, b) in ((train, (0, cut)), (test, (cut, motion.n_frames))):
                part = row.copy()
                part["clip_id"] = f"{row['clip_id']}[{a}:{b}]"
                if a > 0 and "idle_postures" in part:  # the ground truth's times count from the recording's start
                    part["idle_postures"] = ""
                out.setdefault(subject, []).append((part, motion.slice(a, b)))
    return train, test


def split_idle(clips: Clips, settings: Egges2004Settings) -> tuple[Clips, Clips]:
    """(training, held-out) idle clips per subject, by ``settings.held_out_by``:
    :func:`split_clips` or :func:`split_recordings`."""
    if settings.held_out_by == "time":
        return split_recordings(clips, settings.held_out_fraction, settings.held_out_search_s)
    return split_clips(clips, settings.held_out_clips)


def clip_part(clip_id: str) -> tuple[str, slice]:
    """(clip_id of the recording, frames) of a model's clip id (:func:`split_recordings`'s
    ``<clip_id>[<start>:<stop>]``, or a whole clip)."""
    m = _SPAN.match(clip_id)
    if m is None:
        return clip_id, slice(None)
    return m["clip"], slice(int(m["start"]), int(m["stop"]))


def fit_idle_model(
    train: dict[str, list[tuple[pd.Series, Motion]]],
    test: dict[str, list[tuple[pd.Series, Motion]]],
    joint_map: JointMap,
    settings: Egges2004Settings,
) -> tuple[IdleModel, dict[str, list[Recording]]]:
    """Fit the PCA on every training clip (root translation times
    ``settings.translation_scale``, Sec. 3.2), then one database per subject
    (``settings.analysis``, ``settings.seed``). Returns the model and the analysed training
    recordings (PC values, support ratio) per subject."""
    first = next(iter(train.values()))[0][1]
    joint_map.validate(first.skeleton, source="idle: joint map")
    motions = [m for clips in train.values() for _, m in clips]
    pca = PosturePCA(settings.translation_scale).fit(motions)
    recordings, databases = {}, {}
    for subject, clips in train.items():
        recordings[subject] = [analyse_recording(m, pca, joint_map, str(row["clip_id"])) for row, m in clips]
        try:
            databases[subject] = build_database(recordings[subject], pca, settings.analysis, subject, settings.seed)
        except ValueError as exc:
            raise ValueError(f"idle database of subject {subject}: {exc}") from exc
    model = IdleModel(
        pca=pca,
        databases=databases,
        skeletons={s: c[0][1].skeleton for s, c in train.items()},
        train_clips={s: [str(r["clip_id"]) for r, _ in c] for s, c in train.items()},
        test_clips={s: [str(r["clip_id"]) for r, _ in c] for s, c in test.items()},
    )
    return model, recordings


def model_recordings(
    model: IdleModel, dataset: MotionDataset, joint_map: JointMap, source: str
) -> tuple[dict[str, list[Recording]], dict[str, list[Recording]]]:
    """The model's training and held-out clips of ``dataset``, analysed (PC values and
    support ratio), per subject; ValueError when the dataset lacks a clip of the model."""
    clips = {str(row["clip_id"]): m for rows in idle_clips(dataset, source).values() for row, m in rows}

    def motion(clip_id: str) -> Motion:
        clip, frames = clip_part(clip_id)
        m = clips[clip]
        return m if frames == slice(None) else m.slice(frames.start, frames.stop)

    def analyse(ids: dict[str, list[str]]) -> dict[str, list[Recording]]:
        missing = [c for cs in ids.values() for c in cs if clip_part(c)[0] not in clips]
        if missing:
            raise ValueError(
                f"{source}: idle clips {missing[:5]} of the model are not in the dataset; rerun egges2004_model"
            )
        return {s: [analyse_recording(motion(c), model.pca, joint_map, c) for c in cs] for s, cs in ids.items()}

    return analyse(model.train_clips), analyse(model.test_clips)
