"""From packed datasets to the training data of Du 2022 ch. 5 (no file I/O here: the rule
scripts load the datasets).

- :func:`training_windows`: the autoencoder's sliding windows over all clips of the
  unsegmented data (Sec. 5.4.1).
- :func:`primitive_clips` / :func:`primitive_features`: the clips of one motion primitive
  and style, resampled to the canonical timeline (60 frames, Sec. 4.4.1).
- :func:`select_style_example`: the one style example of a CVAE. "All the style examples
  are selected to walk in a straight line" (Sec. 5.4.3): among the style's clips of the
  primitive we take a forward-variant clip (when the metadata has a ``variant`` column)
  with the smallest absolute ``turn_deg`` (when it has one), ties broken by clip id.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from ...core.joint_map import JointMap
from ...io.dataset import MotionDataset
from ...prep.resample import resample_motion
from .features import FeatureLayout, motion_features, motions_features, sliding_windows, style_joints


def dataset_layout(dataset: MotionDataset, joint_map: JointMap) -> FeatureLayout:
    """The feature joints (:func:`style_joints`) of a dataset's rig."""
    if len(dataset) == 0:
        raise ValueError("style: the dataset has no clips")
    return style_joints(dataset.motion(0).skeleton, joint_map)


def training_windows(dataset: MotionDataset, layout: FeatureLayout, size: int = 60, stride: int = 30) -> np.ndarray:
    """(W, size, C) windows of all clips' features (clips shorter than a window skipped)."""
    return sliding_windows([motion_features(dataset.motion(i), layout) for i in range(len(dataset))], size, stride)


def primitive_mask(metadata: pd.DataFrame, primitive: str, style: str | None = None) -> np.ndarray:
    """Rows of one primitive (and style); ValueError naming them when there are none."""
    for col in ["primitive"] + (["style"] if style is not None else []):
        if col not in metadata:
            raise ValueError(f"style: the preprocessed metadata has no column {col!r}")
    mask = metadata["primitive"].to_numpy() == primitive
    if style is not None:
        mask &= metadata["style"].to_numpy() == style
    if not mask.any():
        what = f"primitive {primitive!r}" + (f" with style {style!r}" if style is not None else "")
        have = sorted(set(metadata["primitive"]))
        raise ValueError(f"style: no clips of {what} in the preprocessed data (primitives: {have})")
    return mask


def primitive_clips(dataset: MotionDataset, primitive: str, style: str | None, n_frames: int) -> tuple[pd.DataFrame, list]:
    """(metadata rows, Motions resampled to ``n_frames``) of one primitive and style."""
    idx = np.flatnonzero(primitive_mask(dataset.metadata, primitive, style))
    ids = dataset.metadata["clip_id"].astype(str).to_numpy()
    return dataset.metadata.iloc[idx].reset_index(drop=True), [
        resample_motion(dataset.motion(int(i)), n_frames, clip_id=ids[i]) for i in idx]


def primitive_features(
    dataset: MotionDataset, layout: FeatureLayout, primitive: str, style: str | None, n_frames: int,
) -> tuple[pd.DataFrame, np.ndarray]:
    """(metadata rows, features (N, n_frames, C)) of one primitive and style."""
    rows, motions = primitive_clips(dataset, primitive, style, n_frames)
    return rows, motions_features(motions, layout)


def select_style_example(metadata: pd.DataFrame, primitive: str, style: str) -> str:
    """The clip id of the straightest forward clip of ``style`` and ``primitive``."""
    rows = metadata[primitive_mask(metadata, primitive, style)].copy()
    if "variant" in rows and (rows["variant"] == "forward").any():
        rows = rows[rows["variant"] == "forward"]
    rows["_turn"] = rows["turn_deg"].abs() if "turn_deg" in rows else 0.0
    rows = rows.sort_values(["_turn", "clip_id"], kind="stable")
    return str(rows["clip_id"].iloc[0])


def example_features(dataset: MotionDataset, layout: FeatureLayout, clip_id: str, n_frames: int) -> np.ndarray:
    """(n_frames, C) features of one clip, by id, on the canonical timeline."""
    return motion_features(resample_motion(dataset.by_id(clip_id), n_frames, clip_id=clip_id), layout)
