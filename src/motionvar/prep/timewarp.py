"""Dynamic time warping to a canonical timeline (Du 2022 Sec. 4.4.1: "Every motion clip
in one motion primitive is warped to a canonical timeline. The warping function, which is
a monotonically increasing function, represents the temporal variations. We use the
median-length motion clip as a canonical timeline.").

The DTW itself is dtaidistance's C implementation on pose features (joint positions
relative to the root's floor projection, so that clips of one primitive compare pose by
pose whatever their stride). A warping function here is a (n_ref,) float array: for each
canonical frame, the source frame it corresponds to (the mean of the source frames the
DTW path matches to it), non-decreasing by construction. Ma 2010's incremental time
warping lives with the Ma 2010 code, not here.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
from dtaidistance import dtw

from ..core.motion import Motion
from .resample import clip_name, sample_motion


def pose_features(motion: Motion) -> np.ndarray:
    """(T, 3J) joint positions minus the root's floor projection (x, z) at each frame."""
    pos = motion.positions()
    pos = pos - (motion.root_pos * np.array([1.0, 0.0, 1.0]))[:, None, :]
    return pos.reshape(motion.n_frames, -1)


def _features(x: Motion | np.ndarray, what: str, clip_id: str | None = None) -> np.ndarray:
    name = what if clip_id is None else f"{what} clip {clip_id}"
    if isinstance(x, Motion) and x.n_frames < 2:
        raise ValueError(f"dtw_warp: {name} has {x.n_frames} frame(s); need at least 2")
    f = pose_features(x) if isinstance(x, Motion) else np.asarray(x, dtype=float)
    if f.ndim == 1:
        f = f[:, None]
    if f.ndim != 2 or f.shape[0] < 2:
        raise ValueError(f"dtw_warp: {name} must be a Motion or (T, D) features with T >= 2; got shape {f.shape}")
    if not np.all(np.isfinite(f)):
        raise ValueError(f"dtw_warp: {name} features contain NaN or inf")
    return np.ascontiguousarray(f, dtype=np.double)


def dtw_path(
    source: Motion | np.ndarray,
    reference: Motion | np.ndarray,
    window: int | None = None,
    clip_id: str | None = None,
    reference_id: str | None = None,
) -> np.ndarray:
    """(L, 2) DTW path of (source frame, reference frame) pairs, from (0, 0) to the
    last frames of both (dtaidistance, C implementation, multivariate Euclidean);
    ``clip_id`` and ``reference_id`` name the two clips in errors."""
    src, ref = _features(source, "source", clip_id), _features(reference, "reference", reference_id)
    if src.shape[1] != ref.shape[1]:
        raise ValueError(
            f"dtw_warp: source{'' if clip_id is None else ' clip ' + str(clip_id)} has {src.shape[1]} "
            f"features per frame, reference{'' if reference_id is None else ' clip ' + str(reference_id)} "
            f"{ref.shape[1]}"
        )
    kwargs = {}
    if window is not None:
        need = abs(len(src) - len(ref)) + 1
        if not (isinstance(window, (int, np.integer)) and window >= need):
            which = "" if clip_id is None else f", clip {clip_id}"
            raise ValueError(
                f"dtw_warp: window must be an integer >= {need} for these lengths "
                f"({len(src)} and {len(ref)} frames{which}); got {window!r}"
            )
        kwargs["window"] = int(window)
    if src.shape[1] == 1:
        path = dtw.warping_path_fast(src[:, 0].copy(), ref[:, 0].copy(), **kwargs)
    else:
        path = dtw.warping_path_fast(src, ref, **kwargs)
    return np.asarray(path, dtype=np.int64).reshape(-1, 2)


def dtw_warp(
    source: Motion | np.ndarray,
    reference: Motion | np.ndarray,
    window: int | None = None,
    clip_id: str | None = None,
    reference_id: str | None = None,
) -> np.ndarray:
    """Warping function (n_ref,) from canonical (reference) frames to source frames.

    Args:
        source: the clip to warp, a Motion (pose features are computed) or (T, D) features.
        reference: the canonical clip (Du: the median-length clip of the primitive), same kind.
        window: optional Sakoe-Chiba band in frames (at least the length difference + 1).
        clip_id, reference_id: name the source and the reference clip in errors.
    Returns:
        warp[j] = mean source frame matched to reference frame j, except that the ends
        are pinned (warp[0] = 0, warp[-1] = T_source - 1: the clips start and end
        together); non-decreasing.
    """
    path = dtw_path(source, reference, window, clip_id, reference_id)
    n_ref = int(path[:, 1].max()) + 1
    counts = np.bincount(path[:, 1], minlength=n_ref)
    warp = np.bincount(path[:, 1], weights=path[:, 0].astype(float), minlength=n_ref) / counts
    warp[0], warp[-1] = 0.0, float(path[-1, 0])
    return warp


def check_warp(warp: np.ndarray, n_source: int) -> np.ndarray:
    """The warp as a float array; ValueError unless it is 1-D, finite, non-decreasing and
    within [0, n_source - 1]."""
    w = np.asarray(warp, dtype=float)
    if w.ndim != 1 or len(w) == 0:
        raise ValueError(f"warp must be a non-empty 1-D array; got shape {w.shape}")
    if not np.all(np.isfinite(w)):
        raise ValueError("warp contains NaN or inf")
    if np.any(np.diff(w) < -1e-9):
        k = int(np.argmax(np.diff(w) < -1e-9))
        raise ValueError(f"warp must be non-decreasing; it falls from {w[k]} to {w[k + 1]} at frame {k + 1}")
    if w[0] < -1e-9 or w[-1] > n_source - 1 + 1e-9:
        raise ValueError(f"warp must stay within the source frames [0, {n_source - 1}]; got [{w[0]}, {w[-1]}]")
    return w


def apply_warp(motion: Motion, warp: np.ndarray, fps: float | None = None, clip_id: str | None = None) -> Motion:
    """The clip on the canonical timeline: frame j is the source at fractional frame
    warp[j] (linear root, slerp rotations); frame rate ``fps`` (default the clip's);
    ``clip_id`` names the clip in errors."""
    try:
        w = check_warp(warp, motion.n_frames)
    except ValueError as exc:
        raise ValueError(f"apply_warp: {clip_name(clip_id)}: {exc}") from exc
    return sample_motion(motion, w, fps=fps, clip_id=clip_id)


def median_length_index(motions: Sequence[Motion]) -> int:
    """Index of the median-length clip (Du 2022 Sec. 4.4.1's canonical timeline); of two
    middle lengths the shorter, of equal lengths the first."""
    if len(motions) == 0:
        raise ValueError("median_length_index: no motions given")
    lengths = np.array([m.n_frames for m in motions])
    order = np.argsort(lengths, kind="stable")
    return int(order[(len(order) - 1) // 2])


def warp_to_median(
    motions: Sequence[Motion], window: int | None = None, clip_ids: Sequence[str] | None = None
) -> tuple[int, list[np.ndarray]]:
    """Warp every clip of one primitive to the median-length clip: (reference index,
    one warping function per clip, each of the reference's length). ``clip_ids`` name
    the clips in errors (else "#<index>")."""
    ids = [f"#{i}" for i in range(len(motions))] if clip_ids is None else [str(c) for c in clip_ids]
    if len(ids) != len(motions):
        raise ValueError(f"warp_to_median: {len(ids)} clip ids for {len(motions)} motions")
    short = [f"{c} ({m.n_frames} frame(s))" for c, m in zip(ids, motions) if m.n_frames < 2]
    if short:
        raise ValueError(f"warp_to_median: clips {', '.join(short)} have fewer than 2 frames; DTW needs at least 2")
    ref = median_length_index(motions)
    ref_feat = pose_features(motions[ref])
    return ref, [dtw_warp(pose_features(m), ref_feat, window, c, ids[ref]) for m, c in zip(motions, ids)]
