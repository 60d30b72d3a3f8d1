"""Sampling a clip at fractional frames: linear interpolation of root positions (and
BVH translation channels), slerp of rotations, vectorised over frames and joints.
Used for canonical-length resampling (the common frame count of Ma 2010 Sec. 4.2's
"scale them to be of the same duration") and for applying DTW warps (Du 2022 Sec. 4.4.1).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from ..core.motion import Motion
from ..core.quaternions import qfix, qnormalize, qslerp


def clip_name(clip_id: str | None) -> str:
    """Name of a clip in messages: ``clip <id>``, or ``the clip`` without an id."""
    return "the clip" if clip_id is None else f"clip {clip_id}"


def sample_motion(motion: Motion, frames: np.ndarray, fps: float | None = None, clip_id: str | None = None) -> Motion:
    """The clip evaluated at fractional frame indices ``frames`` (1-D, within
    [0, T - 1]); the result has ``len(frames)`` frames at ``fps`` (default: the clip's).
    ``clip_id`` names the clip in errors."""
    t = np.asarray(frames, dtype=float)
    T = motion.n_frames
    if T == 0:
        raise ValueError(f"sample_motion: {clip_name(clip_id)} has no frames")
    if not (np.isfinite(motion.root_pos).all() and np.isfinite(motion.rotations).all()):
        raise ValueError(f"sample_motion: {clip_name(clip_id)} has NaN or inf root positions or rotations")
    if t.ndim != 1 or len(t) == 0:
        raise ValueError(
            f"sample_motion: frames must be a non-empty 1-D array; got shape {t.shape}"
            + ("" if clip_id is None else f" (clip {clip_id})")
        )
    if not np.all(np.isfinite(t)) or t.min() < -1e-9 or t.max() > T - 1 + 1e-9:
        raise ValueError(
            f"sample_motion: frames must lie in [0, {T - 1}] ({clip_name(clip_id)} has {T} frames); "
            f"got [{np.nanmin(t)}, {np.nanmax(t)}]"
        )
    t = np.clip(t, 0.0, T - 1)
    i0 = np.minimum(np.floor(t).astype(np.int64), max(T - 2, 0))
    i1 = np.minimum(i0 + 1, T - 1)
    w = t - i0
    rot = qfix(qnormalize(motion.rotations), axis=0)
    rotations = qslerp(rot[i0], rot[i1], w[:, None])
    root = motion.root_pos[i0] + w[:, None] * (motion.root_pos[i1] - motion.root_pos[i0])
    tr = None
    if motion.translations is not None:
        a, b = motion.translations[i0], motion.translations[i1]
        tr = a + w[:, None, None] * (b - a)
    return replace(motion, root_pos=root, rotations=rotations, translations=tr, fps=motion.fps if fps is None else fps)


def resample_motion(motion: Motion, n_frames: int, keep_duration: bool = True, clip_id: str | None = None) -> Motion:
    """The clip resampled to ``n_frames`` evenly spaced frames from its first to its last.

    With ``keep_duration`` the frame rate becomes fps * (n_frames - 1) / (T - 1) so that
    the clip lasts as long as before; otherwise the frame rate is kept (time-normalised).
    ``clip_id`` names the clip in errors.
    """
    if not (isinstance(n_frames, (int, np.integer)) and n_frames >= 2):
        raise ValueError(f"resample_motion: n_frames must be an integer >= 2; got {n_frames!r}")
    if motion.n_frames < 2:
        raise ValueError(f"resample_motion: {clip_name(clip_id)} has {motion.n_frames} frame(s); need at least 2")
    fps = motion.fps * (n_frames - 1) / (motion.n_frames - 1) if keep_duration else motion.fps
    return sample_motion(motion, np.linspace(0.0, motion.n_frames - 1, int(n_frames)), fps=fps, clip_id=clip_id)
