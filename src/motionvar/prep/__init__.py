"""Preprocessing: foot contacts, segmentation into primitives, alignment (space warping,
Ma 2010 Sec. 4.2), canonical-length resampling and DTW time warping (Du 2022 Sec. 4.4.1)."""

from .alignment import align_motion, align_motions, clip_directions, facing_directions, start_facing
from .contacts import FootContacts, detect_foot_contacts, joint_speeds
from .intervals import (
    Segment,
    clean_mask,
    format_intervals,
    format_segments,
    intervals_to_mask,
    mask_to_intervals,
    parse_intervals,
    parse_segments,
)
from .options import PrepOptions
from .pipeline import DROPPED_COLUMNS, Preprocessed, drop_summary, preprocess_dataset
from .resample import resample_motion, sample_motion
from .segmentation import SEGMENTERS, contact_onsets, segment_motion
from .timewarp import apply_warp, dtw_path, dtw_warp, median_length_index, pose_features, warp_to_median

__all__ = [
    "DROPPED_COLUMNS",
    "SEGMENTERS",
    "FootContacts",
    "PrepOptions",
    "Preprocessed",
    "Segment",
    "align_motion",
    "align_motions",
    "apply_warp",
    "clean_mask",
    "clip_directions",
    "contact_onsets",
    "detect_foot_contacts",
    "drop_summary",
    "dtw_path",
    "dtw_warp",
    "facing_directions",
    "format_intervals",
    "format_segments",
    "intervals_to_mask",
    "joint_speeds",
    "mask_to_intervals",
    "median_length_index",
    "parse_intervals",
    "parse_segments",
    "pose_features",
    "preprocess_dataset",
    "resample_motion",
    "sample_motion",
    "segment_motion",
    "start_facing",
    "warp_to_median",
]
