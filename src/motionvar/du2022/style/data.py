"""From packed datasets to the training data of Du 2022 ch. 5 (no file I/O here: the rule
scripts load the datasets).

- :func:`training_windows`: the autoencoder's sliding windows over all clips of the
  unsegmented data (Sec. 5.4.1), or a subset of them (:func:`window_counts` numbers them),
  computing only the frames the subset holds.
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
from ...core.kinematics import fk
from ...core.motion import Motion
from ...io.dataset import MotionDataset
from ...prep.resample import resample_motion
from .features import (
    FeatureLayout,
    motion_features,
    motions_features,
    positions_to_features,
    sliding_windows,
    style_joints,
)


def dataset_layout(dataset: MotionDataset, joint_map: JointMap) -> FeatureLayout:
    """The feature joints (:func:`style_joints`) of a dataset's rig."""
    if len(dataset) == 0:
        raise ValueError("style: the dataset has no clips")
    return style_joints(dataset.motion(0).skeleton, joint_map)


def window_counts(dataset: MotionDataset, size: int, stride: int) -> np.ndarray:
    """(clips,) number of windows of ``size`` frames every ``stride`` frames in each clip (0
    for a clip shorter than a window), without loading the clips."""
    if size < 1 or stride < 1:
        raise ValueError(f"window_counts: size and stride must be >= 1; got {size}, {stride}")
    lengths = np.diff(dataset.arrays["starts"])
    return np.where(lengths >= size, (lengths - size) // stride + 1, 0)


def training_windows(
    dataset: MotionDataset,
    layout: FeatureLayout,
    size: int,
    stride: int,
    subset: np.ndarray | None = None,
) -> np.ndarray:
    """(W, size, C) windows of all clips' features (clips shorter than a window skipped),
    or with ``subset`` (sorted indices into those windows, numbered clip by clip) only these,
    equal bit for bit to ``training_windows(...)[subset]``: the features of a window's frames
    need the positions of the frame after it (forward-difference velocities), or at a
    clip's end repeat the last velocity, so each window is computed from its own frames
    plus the next one (:func:`_clip_windows`), and clips without a chosen window are not read."""
    if subset is None:
        return sliding_windows([motion_features(dataset.motion(i), layout) for i in range(len(dataset))], size, stride)
    counts = window_counts(dataset, size, stride)
    ends = np.cumsum(counts)  # window k lies in clip searchsorted(ends, k, "right")
    subset = np.asarray(subset, dtype=np.int64)
    if subset.ndim != 1 or len(subset) == 0 or np.any(np.diff(subset) <= 0) or subset[0] < 0 or subset[-1] >= ends[-1]:
        raise ValueError(f"training_windows: subset must be non-empty increasing indices below the {ends[-1]} windows")
    clip = np.searchsorted(ends, subset, side="right")
    first = ends - counts
    out = [
        _clip_windows(dataset.motion(int(i)), layout, stride * (subset[clip == i] - first[i]), size)
        for i in np.unique(clip)
    ]
    return np.concatenate(out).astype(np.float32)


def _clip_windows(motion: Motion, layout: FeatureLayout, starts: np.ndarray, size: int) -> np.ndarray:
    """(len(starts), size, C) features of one clip's windows at ``starts``, from one
    vectorised FK over their frames only: frames s .. s + size of a window inside the clip
    (the last one gives the window's last velocity), the last ``size`` frames of a window
    that ends with the clip (its last frame repeats the velocity before, as on the whole clip)."""
    T = motion.n_frames
    at_end = starts + size == T  # at most one window
    inner = starts[~at_end]
    frames = (inner[:, None] + np.arange(size + 1)).ravel()
    if at_end.any():
        frames = np.concatenate([frames, np.arange(T - size, T)])
    tr = None if motion.translations is None else motion.translations[frames]
    pos = fk(motion.rotations[frames], motion.root_pos[frames], motion.skeleton.offsets, motion.skeleton.parents, tr)[
        :, layout.joints
    ]
    n = len(inner) * (size + 1)
    windows = []
    if len(inner):
        windows.append(positions_to_features(pos[:n].reshape(len(inner), size + 1, *pos.shape[1:]), layout)[:, :size])
    if at_end.any():
        windows.append(positions_to_features(pos[n:], layout)[None])
    return np.concatenate(windows)


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


def primitive_clips(
    dataset: MotionDataset, primitive: str, style: str | None, n_frames: int
) -> tuple[pd.DataFrame, list]:
    """(metadata rows, Motions resampled to ``n_frames``) of one primitive and style."""
    idx = np.flatnonzero(primitive_mask(dataset.metadata, primitive, style))
    ids = dataset.metadata["clip_id"].astype(str).to_numpy()
    return dataset.metadata.iloc[idx].reset_index(drop=True), [
        resample_motion(dataset.motion(int(i)), n_frames, clip_id=ids[i]) for i in idx
    ]


def primitive_features(
    dataset: MotionDataset,
    layout: FeatureLayout,
    primitive: str,
    style: str | None,
    n_frames: int,
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
