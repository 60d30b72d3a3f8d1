"""From a dataset's idle clips to one idle-motion database per person (Egges et al. 2004,
Sec. 5.6): select the idle clips, hold some out per subject, fit the posture PCA on the
training clips of all subjects (Sec. 3.2) and build each subject's database; for a
fitted model, its training and held-out clips analysed again (PC values, support ratio).
The model is saved by :mod:`.storage`; its categories are checked against the ground
truth by :mod:`.evaluations.fig3_categories`.
"""

from __future__ import annotations

from dataclasses import dataclass

import pandas as pd

from ..core.joint_map import JointMap
from ..core.motion import Motion
from ..core.skeleton import Skeleton
from ..io.dataset import MotionDataset
from .database import IdleDatabase, Recording, analyse_recording, build_database
from .pca import PosturePCA
from .settings import Egges2004Settings


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


def split_clips(
    clips: dict[str, list[tuple[pd.Series, Motion]]], held_out: int
) -> tuple[dict[str, list[tuple[pd.Series, Motion]]], dict[str, list[tuple[pd.Series, Motion]]]]:
    """Per subject, the last ``held_out`` clips (by clip_id) for testing, the rest for
    training; ValueError naming the subjects with too few clips."""
    short = [s for s, c in clips.items() if len(c) <= held_out]
    if short:
        raise ValueError(
            f"subjects {short} have {held_out} or fewer idle clips; need more than egges2004.held_out_clips = {held_out}"
        )
    train = {s: c[: len(c) - held_out] for s, c in clips.items()}
    test = {s: c[len(c) - held_out :] for s, c in clips.items()}
    return train, test


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
    pca = PosturePCA.fit(motions, settings.translation_scale)
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

    def analyse(ids: dict[str, list[str]]) -> dict[str, list[Recording]]:
        missing = [c for cs in ids.values() for c in cs if c not in clips]
        if missing:
            raise ValueError(
                f"{source}: idle clips {missing[:5]} of the model are not in the dataset; rerun egges2004_model"
            )
        return {s: [analyse_recording(clips[c], model.pca, joint_map, c) for c in cs] for s, cs in ids.items()}

    return analyse(model.train_clips), analyse(model.test_clips)
