"""The preprocessing stage as one call: cut every clip of a dataset into primitives
(detected, or the metadata's ground truth) and align each primitive (Ma 2010 Sec. 4.2;
Du 2022 Sec. 4.3, Fig. 4.4: "decomposed into small clips ... rotate ... and translate
them on the ground to make sure they have the same starting position and orientation").

Primitives shorter than ``PrepOptions.min_primitive_s`` (slivers cut by noisy contacts)
are dropped, and so are clips with no primitive left (``skip_unsegmentable``); every
drop is listed in :attr:`Preprocessed.dropped` and counted by :func:`drop_summary`.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
import pandas as pd

from ..core.joint_map import JointMap
from ..core.motion import Motion
from ..io.dataset import MotionDataset
from .alignment import align_motions
from .intervals import Segment, parse_segments
from .options import PrepOptions
from .segmentation import SEGMENT_NEEDS, segment_motion

DROPPED_COLUMNS = ("clip_id", "behaviour", "primitive", "start_frame", "stop_frame", "n_frames", "duration_s", "reason")
"""Columns of :attr:`Preprocessed.dropped`: the source clip, its behaviour, the dropped
primitive (empty when the clip had none) with its frames [start, stop) and duration, and why."""
TOO_SHORT = "too short"
NONE_FOUND = "no primitive found"


class Preprocessed(NamedTuple):
    """What :func:`preprocess_dataset` returns: the aligned primitives, their metadata
    and what was dropped (one row per dropped primitive or primitive-less clip,
    :data:`DROPPED_COLUMNS`)."""

    motions: list[Motion]
    metadata: pd.DataFrame
    dropped: pd.DataFrame


def _check_metadata(metadata: pd.DataFrame, options: PrepOptions) -> None:
    need = ["clip_id", "behaviour"] + (["segments"] if options.use_ground_truth_segments else [])
    missing = [c for c in need if c not in metadata.columns]
    if missing:
        why = " (PrepOptions.use_ground_truth_segments needs 'segments')" if "segments" in missing else ""
        raise ValueError(f"preprocess_dataset: metadata lacks columns {missing}{why}")


def clip_segments(motion: Motion, row: pd.Series, joint_map: JointMap, options: PrepOptions) -> list[Segment]:
    """The primitives of one clip: the ground truth of ``row['segments']`` or detected
    from ``row['behaviour']``; ValueError naming the clip when they are unusable."""
    cid = row["clip_id"]
    try:
        if options.use_ground_truth_segments:
            segs = parse_segments(row["segments"], what=f"segments of clip {cid}")
        else:
            segs = segment_motion(motion, str(row["behaviour"]), joint_map, options)
    except ValueError as exc:
        raise ValueError(f"clip {cid}: {exc}") from exc
    beyond = [s for s in segs if s.stop > motion.n_frames]
    if beyond:
        raise ValueError(f"clip {cid}: segments {beyond} end beyond the clip's {motion.n_frames} frames")
    return segs


def too_short(segments: list[Segment], fps: float, min_seconds: float) -> np.ndarray:
    """(K,) bool: which segments last less than ``min_seconds`` ((stop - start) / fps) or
    have fewer than 2 frames (no later step can warp or resample a single frame)."""
    n = np.array([s.stop - s.start for s in segments], dtype=np.int64)
    return (n < 2) | (n / fps < min_seconds - 1e-9)


def _dropped_rows(cid: str, behaviour: str, segments: list[Segment], fps: float, reason: str) -> list[dict]:
    return [
        {
            "clip_id": cid,
            "behaviour": behaviour,
            "primitive": s.name,
            "start_frame": s.start,
            "stop_frame": s.stop,
            "n_frames": s.stop - s.start,
            "duration_s": (s.stop - s.start) / fps,
            "reason": reason,
        }
        for s in segments
    ]


def _nothing_left(label: str, n_clips: int, dropped: pd.DataFrame, min_seconds: float) -> str:
    """The error when no primitive is left: the dataset and the most common reason."""
    short = dropped[dropped["reason"] == TOO_SHORT]
    n_none = int((dropped["reason"] == NONE_FOUND).sum())
    n_short_clips = short["clip_id"].nunique()
    if n_short_clips >= n_none:
        reason = (
            f"most common reason: in {n_short_clips} clips every primitive was shorter than "
            f"prep.min_primitive_s = {min_seconds:g} s (median {short['duration_s'].median():.3g} s); "
            "check the frame rate and the contact thresholds, or lower prep.min_primitive_s"
        )
    else:
        kinds = dropped.loc[dropped["reason"] == NONE_FOUND, "behaviour"].value_counts()
        top = str(kinds.index[0])
        need = f"; a {top} primitive needs {SEGMENT_NEEDS[top]}" if top in SEGMENT_NEEDS else ""
        reason = (
            f"most common reason: no primitive found in {n_none} clips ("
            + ", ".join(f"{b}: {k}" for b, k in kinds.items())
            + f"){need}. Clips that are each one "
            "primitive already need a 'segments' column ('name:start:stop') and "
            "prep.use_ground_truth_segments: true"
        )
    return f"preprocess_dataset: no primitive left in {label} ({n_clips} clips); {reason}"


def preprocess_dataset(
    dataset: MotionDataset, joint_map: JointMap, options: PrepOptions | None = None, name: str | None = None
) -> Preprocessed:
    """Segment and align every clip of ``dataset`` (``name`` names it in messages).

    Returns one aligned Motion per primitive and its metadata: the source clip's row
    with ``clip_id`` = "{source}_{k:02d}" (k counts the clip's kept primitives from 0),
    ``source_clip``, ``primitive``, ``start_frame``, ``stop_frame`` (stop exclusive) and,
    where the source has it, ``n_frames`` set to the primitive's length; and the dropped
    primitives and clips (:data:`DROPPED_COLUMNS`). ValueError naming the dataset when no
    primitive is left, or naming the clips without one when ``skip_unsegmentable`` is off.
    """
    opt = options or PrepOptions()
    label = f"dataset {name}" if name else "the dataset"
    if len(dataset) == 0:
        raise ValueError(f"preprocess_dataset: {label} has no clips")
    _check_metadata(dataset.metadata, opt)
    first = dataset.motion(0)
    joint_map.validate(first.skeleton, source="preprocess_dataset: joint map")
    pieces: list[Motion] = []
    rows: list[dict] = []
    dropped: list[dict] = []
    empty: list[str] = []
    for i in range(len(dataset)):
        row = dataset.metadata.iloc[i]
        motion = first if i == 0 else dataset.motion(i)
        cid, behaviour = str(row["clip_id"]), str(row["behaviour"])
        segs = clip_segments(motion, row, joint_map, opt)
        short = too_short(segs, motion.fps, opt.min_primitive_s)
        dropped += _dropped_rows(cid, behaviour, [s for s, x in zip(segs, short) if x], motion.fps, TOO_SHORT)
        kept = [s for s, x in zip(segs, short) if not x]
        if not segs:
            dropped += _dropped_rows(cid, behaviour, [Segment("", 0, motion.n_frames)], motion.fps, NONE_FOUND)
        if not kept:
            why = (
                f"no {behaviour} primitive found"
                if not segs
                else f"all {len(segs)} {behaviour} primitives shorter than {opt.min_primitive_s:g} s"
            )
            empty.append(f"clip {cid}: {why}")
        for k, s in enumerate(kept):
            pieces.append(motion.slice(s.start, s.stop))
            meta = row.to_dict()
            meta.update(
                clip_id=f"{cid}_{k:02d}",
                source_clip=row["clip_id"],
                primitive=s.name,
                start_frame=s.start,
                stop_frame=s.stop,
            )
            if "n_frames" in meta:
                meta["n_frames"] = s.stop - s.start
            rows.append(meta)
    dropped_table = pd.DataFrame(dropped, columns=list(DROPPED_COLUMNS))
    if not pieces:
        raise ValueError(_nothing_left(label, len(dataset), dropped_table, opt.min_primitive_s))
    if empty and not opt.skip_unsegmentable:
        raise ValueError(
            f"preprocess_dataset: {len(empty)} of {len(dataset)} clips of {label} have no primitive "
            f"left ({'; '.join(empty[:5])}{'; ...' if len(empty) > 5 else ''}); set "
            "prep.skip_unsegmentable: true to drop such clips"
        )
    metadata = pd.DataFrame(rows).reset_index(drop=True)
    motions = align_motions(pieces, joint_map, opt, clip_ids=metadata["clip_id"].tolist())
    return Preprocessed(motions, metadata, dropped_table)


def drop_summary(result: Preprocessed, n_clips: int, name: str | None = None, min_seconds: float | None = None) -> str:
    """One line for the log: clips in, primitives out per primitive name, and what was
    dropped, counted per primitive (too short: under ``min_seconds``) and per behaviour
    (clips left empty)."""
    meta, dropped = result.metadata, result.dropped
    label = f"dataset {name}" if name else "the dataset"
    kept = meta["primitive"].value_counts().sort_index()
    text = (
        f"{label}: {n_clips} clips -> {len(meta)} primitives from {meta['source_clip'].nunique()} clips ("
        + ", ".join(f"{p} {k}" for p, k in kept.items())
        + ")"
    )
    short = dropped[dropped["reason"] == TOO_SHORT]
    if len(short):
        per = short["primitive"].value_counts().sort_index()
        limit = "the minimum duration" if min_seconds is None else f"{min_seconds:g} s"
        text += (
            f"; dropped {len(short)} primitives shorter than {limit} ("
            + ", ".join(f"{p} {k}" for p, k in per.items())
            + ")"
        )
    gone = sorted(set(dropped["clip_id"]) - set(meta["source_clip"].astype(str)))
    if gone:
        beh = dropped.drop_duplicates("clip_id").set_index("clip_id").loc[gone, "behaviour"].value_counts().sort_index()
        n_none = int((dropped["reason"] == NONE_FOUND).sum())
        text += (
            f"; dropped {len(gone)} clips with no primitive left ({n_none} with none found, "
            f"{len(gone) - n_none} with all too short; " + ", ".join(f"{b} {k}" for b, k in beh.items()) + ")"
        )
    return text
