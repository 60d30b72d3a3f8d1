"""The preprocessing stage as one call: cut every clip of a dataset into primitives
(detected, or the metadata's ground truth) and align each primitive (Ma 2010 Sec. 4.2;
Du 2022 Sec. 4.3, Fig. 4.4: "decomposed into small clips ... rotate ... and translate
them on the ground to make sure they have the same starting position and orientation").
"""

from __future__ import annotations

import warnings

import pandas as pd

from ..core.joint_map import JointMap
from ..core.motion import Motion
from ..io.dataset import MotionDataset
from .alignment import align_motions
from .intervals import Segment, parse_segments
from .options import PrepOptions
from .segmentation import segment_motion

SEGMENT_COLUMNS = ("clip_id", "source_clip", "primitive", "start_frame", "stop_frame")


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


def preprocess_dataset(
    dataset: MotionDataset, joint_map: JointMap, options: PrepOptions | None = None
) -> tuple[list[Motion], pd.DataFrame]:
    """Segment and align every clip of ``dataset``.

    Returns one aligned Motion per primitive and its metadata: the source clip's row
    with ``clip_id`` = "{source}_{k:02d}" (k counts the clip's primitives from 0),
    ``source_clip``, ``primitive``, ``start_frame``, ``stop_frame`` (stop exclusive) and,
    where the source has it, ``n_frames`` set to the primitive's length.
    """
    opt = options or PrepOptions()
    if len(dataset) == 0:
        raise ValueError("preprocess_dataset: the dataset has no clips")
    _check_metadata(dataset.metadata, opt)
    first = dataset.motion(0)
    joint_map.validate(first.skeleton, source="preprocess_dataset: joint map")
    pieces: list[Motion] = []
    rows: list[dict] = []
    for i in range(len(dataset)):
        row = dataset.metadata.iloc[i]
        motion = first if i == 0 else dataset.motion(i)
        segs = clip_segments(motion, row, joint_map, opt)
        if not segs:
            msg = f"clip {row['clip_id']}: no {row['behaviour']} primitives found"
            if not opt.skip_unsegmentable:
                raise ValueError(msg + " (set PrepOptions.skip_unsegmentable to drop such clips)")
            warnings.warn(msg + "; skipped", stacklevel=2)
            continue
        for k, s in enumerate(segs):
            pieces.append(motion.slice(s.start, s.stop))
            meta = row.to_dict()
            meta.update(
                clip_id=f"{row['clip_id']}_{k:02d}", source_clip=row["clip_id"], primitive=s.name,
                start_frame=s.start, stop_frame=s.stop,
            )
            if "n_frames" in meta:
                meta["n_frames"] = s.stop - s.start
            rows.append(meta)
    if not pieces:
        raise ValueError("preprocess_dataset: no primitives found in any clip")
    return align_motions(pieces, joint_map, opt), pd.DataFrame(rows).reset_index(drop=True)
