"""Motion correspondence (Ma et al. 2010, Sec. 4 and 4.2): a standard skeleton, space
warping (Eq. 5-6) and incremental time warping to a common duration [PSS02].

Time warping here is piecewise linear between corresponding key frames: the key frames
of every clip are mapped onto common reference key times, so the warp is monotonically
increasing by construction. The inverse warp of a synthesized clip runs through its
predicted key times (see :func:`retime`). Those are interpolated as the logarithms of the
intervals between key frames (``key_timing="log_intervals"``, :func:`encode_key_times`), so
every interval a synthesis predicts is positive and its progression increases, as [PSS02]'s
incremental time warping guarantees; interpolating the absolute key times (``"absolute"``)
can predict a key before the one it follows, and such a synthesis counts as failed
(:func:`key_times_increase`).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace

import numpy as np

from ..core.joint_map import JointMap
from ..core.motion import Motion
from ..core.quaternions import qnormalize, qslerp
from ..core.skeleton import Skeleton
from ..prep.alignment import align_motion, clip_directions
from ..prep.options import PrepOptions
from ..prep.resample import sample_motion
from .settings import KEY_TIMINGS


def standard_skeleton(skeletons: Sequence[Skeleton]) -> Skeleton:
    """The standard kinematic skeleton all examples are normalized to (Sec. 1, 3): the
    mean bone offsets (and end sites) of the given skeletons, which share one topology."""
    if not skeletons:
        raise ValueError("standard_skeleton: no skeletons given")
    first = skeletons[0]
    for i, sk in enumerate(skeletons):
        if not sk.same_topology(first):
            raise ValueError(f"standard_skeleton: skeleton {i} has another topology than skeleton 0")
    offsets = np.mean([sk.offsets for sk in skeletons], axis=0)
    ends = {j: np.mean([sk.end_sites[j] for sk in skeletons], axis=0) for j in first.end_sites}
    return replace(first, offsets=offsets, end_sites=ends)


def movement_direction(motion: Motion, joint_map: JointMap) -> np.ndarray:
    """dir(M) of Eq. 5: the unit horizontal direction from the first to the last root
    position (the hips' facing for a clip that does not travel)."""
    d = clip_directions([motion], joint_map, PrepOptions(heading="movement"))[0]
    return d / np.linalg.norm(d)


def space_warp(motion: Motion, joint_map: JointMap) -> Motion:
    """Eq. 5-6: rotate the clip about the vertical so that its movement direction is +x
    (theta* = atan2 of the direction, exactly) and put its first root above the origin;
    :func:`motionvar.prep.alignment.align_motion` with Ma's movement heading."""
    return align_motion(motion, joint_map, PrepOptions(heading="movement"))


def sample_rotations(rotations: np.ndarray, frames: np.ndarray) -> np.ndarray:
    """Rotations (T, J, 4) sampled at fractional frame indices (U,) by slerp (the array
    counterpart of :func:`motionvar.prep.resample.sample_motion`, for the synthesis hot
    path, where clips are arrays without a skeleton)."""
    T = rotations.shape[0]
    frames = np.clip(np.asarray(frames, dtype=float), 0.0, T - 1.0)
    if T == 1:
        return np.repeat(rotations, len(frames), axis=0)
    i0 = np.minimum(np.floor(frames).astype(np.int64), T - 2)
    alpha = np.broadcast_to((frames - i0)[:, None], (len(frames), rotations.shape[1]))
    return qslerp(rotations[i0], rotations[i0 + 1], alpha)


def sample_linear(values: np.ndarray, frames: np.ndarray) -> np.ndarray:
    """Any array (T, ...) sampled at fractional frame indices (U,) by linear interpolation."""
    values = np.asarray(values, dtype=float)
    frames = np.clip(np.asarray(frames, dtype=float), 0.0, values.shape[0] - 1.0)
    i0 = np.minimum(np.floor(frames).astype(np.int64), max(values.shape[0] - 2, 0))
    i1 = np.minimum(i0 + 1, values.shape[0] - 1)
    a = (frames - i0).reshape((-1,) + (1,) * (values.ndim - 1))
    return values[i0] * (1 - a) + values[i1] * a


def reference_key_positions(key_frames: Sequence[np.ndarray], lengths: Sequence[int], n_frames: int) -> np.ndarray:
    """Common key-frame positions (K,) on a timeline of ``n_frames`` frames: the mean of
    every clip's key frames as a fraction of its length. Starts at 0, ends at n_frames-1."""
    keys = np.array([np.asarray(k, dtype=float) / (n - 1) for k, n in zip(key_frames, lengths)])
    if keys.ndim != 2:
        raise ValueError("reference_key_positions: every clip needs the same number of key frames")
    ref = keys.mean(axis=0) * (n_frames - 1)
    ref[0], ref[-1] = 0.0, n_frames - 1.0
    if np.any(np.diff(ref) <= 0):
        raise ValueError(f"reference_key_positions: key frames out of order {ref.tolist()}")
    return ref


def time_warp(motion: Motion, key_frames: np.ndarray, reference: np.ndarray) -> Motion:
    """Warp a clip onto the common timeline: its key frames land on ``reference`` (K,)
    and the frames between them are spaced linearly (a monotonic warp). The result has
    ``round(reference[-1]) + 1`` frames; its fps is kept (frames are then "normalized
    time", and the clip's real key times travel separately)."""
    key_frames = np.asarray(key_frames, dtype=float)
    if len(key_frames) != len(reference) or np.any(np.diff(key_frames) <= 0):
        raise ValueError(f"time_warp: key frames {key_frames.tolist()} must increase and match the reference")
    n = int(round(reference[-1])) + 1
    src = np.interp(np.arange(n, dtype=float), reference, key_frames)
    return replace(sample_motion(motion, src), translations=None)


def _absolute(key_timing: str) -> bool:
    """Whether ``key_timing`` (one of :data:`.settings.KEY_TIMINGS`) keeps the times as they are."""
    if key_timing not in KEY_TIMINGS:
        raise ValueError(f"key_timing must be one of {KEY_TIMINGS}; got {key_timing!r}")
    return key_timing == "absolute"


def encode_key_times(key_times: np.ndarray, key_timing: str) -> np.ndarray:
    """Features (N, K) of key times (N, K), s: the first key time and the logarithms of the K - 1
    intervals (``"log_intervals"``; every interval must be positive), or the times themselves."""
    kt = np.atleast_2d(np.asarray(key_times, dtype=float))
    if _absolute(key_timing):
        return kt
    intervals = np.diff(kt, axis=1)
    if np.any(intervals <= 0):
        raise ValueError("encode_key_times: key times must increase within every clip")
    return np.concatenate([kt[:, :1], np.log(intervals)], axis=1)


def decode_key_times(features: np.ndarray, key_timing: str) -> np.ndarray:
    """Key times (M, K) of features (M, K) written by :func:`encode_key_times`."""
    f = np.atleast_2d(np.asarray(features, dtype=float))
    if _absolute(key_timing):
        return f
    return np.concatenate([f[:, :1], f[:, :1] + np.cumsum(np.exp(f[:, 1:]), axis=1)], axis=1)


def key_times_increase(key_times: np.ndarray) -> np.ndarray:
    """Whether each clip's key times (..., K) increase strictly: a synthesis whose keys do not
    would run backwards and is failed."""
    return np.all(np.diff(np.asarray(key_times, dtype=float), axis=-1) > 0, axis=-1)


def retime_frames(reference: np.ndarray, key_times: np.ndarray, fps: float) -> np.ndarray:
    """Source frames (U,) on the normalized timeline (key frames at ``reference``) of the
    real-time frames of a clip whose key frames fall at ``key_times`` (seconds from its
    start). Key times are made strictly increasing first: the progression through the
    clip is monotonic ([PSS02]'s incremental time warping)."""
    kt = np.asarray(key_times, dtype=float) - float(key_times[0])
    kt = np.maximum.accumulate(np.maximum(kt, 0.0) + np.arange(len(kt)) * 1e-6)
    n_out = int(np.floor(kt[-1] * fps + 1e-9)) + 1
    return np.interp(np.arange(n_out) / fps, kt, reference)


def retime(
    rotations: np.ndarray,
    reference: np.ndarray,
    key_times: np.ndarray,
    fps: float,
    extra: np.ndarray | None = None,
) -> tuple[np.ndarray, np.ndarray | None]:
    """Inverse time warp of a synthesized clip: from the normalized timeline (key frames
    at ``reference``) to real time, where its key frames fall at ``key_times`` (seconds
    from the clip's start), see :func:`retime_frames`.

    Returns rotations (U, J, 4) at ``fps`` and ``extra`` (T, ...) resampled alike.
    """
    src = retime_frames(reference, key_times, fps)
    rot = qnormalize(sample_rotations(rotations, src))
    return rot, None if extra is None else sample_linear(extra, src)
