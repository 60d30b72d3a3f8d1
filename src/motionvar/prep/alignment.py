"""Alignment, the space warping of Ma et al. 2010 Sec. 4.2 (Eq. 5-6) and Du 2022 Sec. 4.3:
rotate each clip about the vertical (y) axis so that its direction is +x, and translate
it on the floor so that its root starts above the origin.

The direction is either the body's facing at the clip's start, from the hip joints of
the :class:`JointMap` (facing = up x (left hip -> right hip)), or Ma's overall movement
direction (first to last root position on the floor). The rotation acts on the root
position and the root rotation only; the rotation angle solving Eq. 5 exactly is
theta* = atan2(d_z, d_x). Works on a batch: all clips are transformed in one vectorised
pass over their concatenated frames.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace

import numpy as np

from ..core.joint_map import JointMap
from ..core.kinematics import fk
from ..core.motion import Motion
from ..core.quaternions import qmul, qrot, quat_about_axis
from .options import PrepOptions

_UP = np.array([0.0, 1.0, 0.0])
_MIN_TRAVEL_CM = 1.0  # below this the movement direction is undefined: use the hips


def facing_directions(positions: np.ndarray, left_hip: int, right_hip: int) -> np.ndarray:
    """(..., 3) horizontal facing directions (not normalised) of positions (..., J, 3):
    up x (left hip -> right hip). A CMU body with its left side at +x faces +z."""
    across = positions[..., right_hip, :] - positions[..., left_hip, :]
    f = np.cross(_UP, across)
    f[..., 1] = 0.0
    return f


def yaw_to_x(direction: np.ndarray) -> np.ndarray:
    """Angles (...) about +y that rotate horizontal ``direction`` (..., 3) onto +x (Eq. 5)."""
    return np.arctan2(direction[..., 2], direction[..., 0])


def clip_labels(n: int, clip_ids: Sequence[str] | None) -> list[str]:
    """Names of ``n`` clips for messages: "clip <id>", or "motion <i>" without ids."""
    if clip_ids is None:
        return [f"motion {i}" for i in range(n)]
    if len(clip_ids) != n:
        raise ValueError(f"{len(clip_ids)} clip ids for {n} motions")
    return [f"clip {c}" for c in clip_ids]


def _check_batch(motions: Sequence[Motion], joint_map: JointMap, clip_ids: Sequence[str] | None = None) -> None:
    if len(motions) == 0:
        raise ValueError("alignment: no motions given")
    names = clip_labels(len(motions), clip_ids)
    sk0 = motions[0].skeleton
    for m, name in zip(motions, names):  # loop over clips
        if not m.skeleton.same_topology(sk0):
            raise ValueError(f"alignment: {name} has another skeleton topology than {names[0]}")
        if m.n_frames == 0:
            raise ValueError(f"alignment: {name} has no frames")
        if not (np.isfinite(m.root_pos).all() and np.isfinite(m.rotations).all()):
            raise ValueError(f"alignment: {name} has NaN or inf root positions or rotations")
    missing = [s for s in ("left_hip", "right_hip") if s not in joint_map.joints]
    if missing:
        raise ValueError(f"alignment: the joint map lacks semantic joints {missing}")


def start_facing(
    motions: Sequence[Motion], joint_map: JointMap, n_frames: int = 1, clip_ids: Sequence[str] | None = None
) -> np.ndarray:
    """(N, 3) facing direction of each clip, averaged over its first ``n_frames`` frames
    (one FK over all clips at once); ``clip_ids`` name the clips in errors."""
    _check_batch(motions, joint_map, clip_ids)
    sk = motions[0].skeleton
    idx = [np.minimum(np.arange(n_frames), m.n_frames - 1) for m in motions]
    rot = np.stack([m.rotations[i] for m, i in zip(motions, idx)])  # (N, k, J, 4)
    root = np.stack([m.root_pos[i] for m, i in zip(motions, idx)])  # (N, k, 3)
    offsets = np.stack([m.skeleton.offsets for m in motions])[:, None]  # (N, 1, J, 3)
    tr = None
    if any(m.translations is not None for m in motions):
        nan = np.full(rot.shape[2:3] + (3,), np.nan)
        tr = np.stack(
            [
                np.broadcast_to(nan, (n_frames, *nan.shape)) if m.translations is None else m.translations[i]
                for m, i in zip(motions, idx)
            ]
        )
    pos = fk(rot, root, offsets, sk.parents, tr)
    lh, rh = joint_map.indices(sk, ["left_hip", "right_hip"])
    return facing_directions(pos, lh, rh).mean(axis=1)


def clip_directions(
    motions: Sequence[Motion],
    joint_map: JointMap,
    options: PrepOptions | None = None,
    clip_ids: Sequence[str] | None = None,
) -> np.ndarray:
    """(N, 3) direction of each clip per ``options.heading``: "hips" (start facing) or
    "movement" (first to last root position; clips travelling less than 1 cm, such as
    idle standing, fall back to the hips); ``clip_ids`` name the clips in errors."""
    opt = options or PrepOptions()
    facing = start_facing(motions, joint_map, opt.heading_frames, clip_ids)
    if opt.heading == "hips":
        return facing
    travel = np.stack([m.root_pos[-1] - m.root_pos[0] for m in motions]) * np.array([1.0, 0.0, 1.0])
    moved = np.linalg.norm(travel, axis=1) * opt.units_cm >= _MIN_TRAVEL_CM
    return np.where(moved[:, None], travel, facing)


def transform_on_floor(motions: Sequence[Motion], yaw: np.ndarray, origin: np.ndarray) -> list[Motion]:
    """Move each clip i rigidly on the floor: root' = R(yaw[i]) (root - origin[i]) and
    root rotation' = R(yaw[i]) root rotation, R a rotation about +y. One vectorised pass
    over the frames of all clips."""
    lengths = np.array([m.n_frames for m in motions])
    q = np.repeat(quat_about_axis(_UP, np.asarray(yaw, dtype=float)), lengths, axis=0)
    o = np.repeat(np.asarray(origin, dtype=float), lengths, axis=0)
    root = qrot(q, np.concatenate([m.root_pos for m in motions]) - o)
    root_rot = qmul(q, np.concatenate([m.rotations[:, 0] for m in motions]))
    cuts = np.cumsum(lengths)[:-1]
    out = []
    for m, r, rr in zip(motions, np.split(root, cuts), np.split(root_rot, cuts)):
        rot = m.rotations.copy()
        rot[:, 0] = rr
        tr = None if m.translations is None else m.translations.copy()
        out.append(replace(m, root_pos=r, rotations=rot, translations=tr))
    return out


def align_motions(
    motions: Sequence[Motion],
    joint_map: JointMap,
    options: PrepOptions | None = None,
    clip_ids: Sequence[str] | None = None,
) -> list[Motion]:
    """Aligned copies of ``motions`` (Ma 2010 Eq. 5-6): each starts with its root above
    the origin (height kept) and its direction (``options.heading``) along +x.
    ``clip_ids`` name the clips in errors (empty or non-finite clips)."""
    d = clip_directions(motions, joint_map, options, clip_ids)
    origin = np.stack([m.root_pos[0] for m in motions]) * np.array([1.0, 0.0, 1.0])
    return transform_on_floor(motions, yaw_to_x(d), origin)


def align_motion(
    motion: Motion, joint_map: JointMap, options: PrepOptions | None = None, clip_id: str | None = None
) -> Motion:
    """One clip aligned as in :func:`align_motions`."""
    return align_motions([motion], joint_map, options, None if clip_id is None else [clip_id])[0]
