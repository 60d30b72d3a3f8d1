"""Analytic two-bone inverse kinematics of a leg (hip - knee - ankle) on global positions
and rotations, vectorised over frames: the IK step of footskate cleanup (Kovar, Schreiner
& Gleicher 2002, "Footskate cleanup for motion capture editing", [KSG02] in Ma et al. 2010).

Unlike :mod:`motionvar.synth.ik` (the generator's legs, built from a rest pose with a known
hinge axis) this works on any posed leg of any rig: it needs only where the three joints
are and how the hip and the knee joint are turned. The knee angle follows from the law of
cosines on the hip-target distance; the knee stays in the plane spanned by the hip-target
line and a *pole*, by default the current knee direction across the hip-ankle line (the
leg's swivel plane is kept).
The hip and the knee joint are then turned by the rotations that carry the old thigh and
shin, with the old bend plane, onto the new ones, so the knee's local rotation changes only
about the bend plane's normal (flexion, no twist). Nothing is iterated: a reachable target
is met to rounding error; an unreachable one gives a straight leg pointing at it.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.spatial.transform import Rotation

from .quaternions import qmul

#: A pole closer than this (cm) to the hip-target line does not set a plane: the fallback does.
DEGENERATE_CM = 1e-6


def _unit(v: np.ndarray) -> np.ndarray:
    n = np.linalg.norm(v, axis=-1, keepdims=True)
    return v / np.maximum(n, 1e-300)


def _perp(v: np.ndarray, u: np.ndarray) -> np.ndarray:
    """The part of v (..., 3) perpendicular to the unit vectors u (..., 3)."""
    return v - np.sum(v * u, axis=-1, keepdims=True) * u


def _any_perpendicular(u: np.ndarray) -> np.ndarray:
    """A unit vector perpendicular to each unit u (..., 3) (the last resort for a plane)."""
    ref = np.where(np.abs(u[..., :1]) < 0.9, np.array([1.0, 0.0, 0.0]), np.array([0.0, 0.0, 1.0]))
    return _unit(_perp(ref, u))


def bend_direction(line: np.ndarray, pole: np.ndarray, fallback: np.ndarray | None = None) -> np.ndarray:
    """Unit direction (..., 3) perpendicular to ``line`` towards ``pole`` (the side of the
    line the knee lies on); where ``pole`` is (nearly) along the line, towards ``fallback``,
    and where that fails too, any perpendicular."""
    u = _unit(line)
    w = _perp(pole, u)
    bad = np.linalg.norm(w, axis=-1) < DEGENERATE_CM
    if fallback is not None and bad.any():
        w = np.where(bad[..., None], _perp(np.broadcast_to(fallback, w.shape), u), w)
        bad = np.linalg.norm(w, axis=-1) < DEGENERATE_CM
    if bad.any():
        w = np.where(bad[..., None], _any_perpendicular(u), w)
    return _unit(w)


def knee_and_ankle(
    hip: np.ndarray,
    target: np.ndarray,
    thigh: np.ndarray,
    shin: np.ndarray,
    pole: np.ndarray,
    fallback: np.ndarray | None = None,
) -> tuple[np.ndarray, np.ndarray]:
    """Knee and ankle positions (..., 3) of a leg with bone lengths ``thigh`` and ``shin``
    (...,) whose ankle reaches ``target`` from ``hip``, the knee bent towards ``pole`` (a
    direction, see :func:`bend_direction`). Law of cosines: the angle a at the hip between
    the thigh and the hip-ankle line has cos a = (l1^2 + r^2 - l2^2) / (2 l1 r), r the
    hip-target distance clamped to [|l1 - l2|, l1 + l2]; out of reach the leg is straight
    and points at the target."""
    d = target - hip
    u = _unit(d)
    w = bend_direction(d, pole, fallback)
    l1, l2 = np.asarray(thigh, dtype=float), np.asarray(shin, dtype=float)
    r = np.clip(np.linalg.norm(d, axis=-1), np.abs(l1 - l2), l1 + l2)
    cos_a = np.clip((l1**2 + r**2 - l2**2) / np.maximum(2.0 * l1 * r, 1e-300), -1.0, 1.0)
    sin_a = np.sqrt(np.maximum(1.0 - cos_a**2, 0.0))
    knee = hip + l1[..., None] * (cos_a[..., None] * u + sin_a[..., None] * w)
    ankle = hip + r[..., None] * u
    return knee, ankle


def _frame(bone: np.ndarray, normal: np.ndarray) -> np.ndarray:
    """Rotation matrices (..., 3, 3) whose columns are the bone direction, the plane normal
    (made perpendicular to the bone) and their cross product."""
    e1 = _unit(bone)
    e2 = _unit(_perp(normal, e1))
    return np.stack([e1, e2, np.cross(e1, e2)], axis=-1)


def _quat(m: np.ndarray) -> np.ndarray:
    return Rotation.from_matrix(m.reshape(-1, 3, 3)).as_quat(scalar_first=True).reshape(m.shape[:-2] + (4,))


@dataclass(frozen=True)
class LegIK:
    """The solved leg: global rotations (..., 4) of the hip joint (it turns the thigh) and
    of the knee joint (it turns the shin), and where the knee and the ankle now are (..., 3)."""

    hip_rotation: np.ndarray
    knee_rotation: np.ndarray
    knee: np.ndarray
    ankle: np.ndarray


def two_bone_ik(
    hip: np.ndarray,
    knee: np.ndarray,
    ankle: np.ndarray,
    hip_rotation: np.ndarray,
    knee_rotation: np.ndarray,
    target: np.ndarray,
    pole: np.ndarray | None = None,
    fallback_pole: np.ndarray | None = None,
) -> LegIK:
    """Turn a leg so that its ankle reaches ``target``, per frame.

    Args:
        hip, knee, ankle: (..., 3) global positions of the three joints.
        hip_rotation, knee_rotation: (..., 4) global rotations (w, x, y, z) of the hip
            joint (whose child is the knee) and of the knee joint (whose child is the ankle).
        target: (..., 3) where the ankle should go.
        pole: (..., 3) direction the knee should point to, away from the hip-target line;
            default the current bend: the current knee's side of the hip-ankle line
            (the swivel plane is kept, and a nearly straight knee keeps bending to the
            side it bent to: straightening it never flips it backwards).
        fallback_pole: (..., 3) used where the pole lies along the hip-target line (a
            straight leg, e.g. the foot's forward direction: the knee bends over the toes).

    Returns a :class:`LegIK`. Bone lengths are the current ones, so they are kept. The
    rotations carry the old thigh (shin) with the old bend plane's normal onto the new
    thigh (shin) with the new normal; the normals are taken on the same side (hip-ankle
    line x pole), so the knee keeps its bending sense, and the knee's local rotation
    changes by a rotation about the bend plane's normal only. The ankle's own rotation is
    not touched: to keep the foot's global orientation, set the ankle's local rotation to
    ``knee_rotation^-1 * (its old global rotation)``.
    """
    hip, knee, ankle, target = (np.asarray(a, dtype=float) for a in (hip, knee, ankle, target))
    thigh, shin = knee - hip, ankle - knee
    # The current bend: the knee's side of the hip-ankle line (a unit vector across it).
    bend = bend_direction(ankle - hip, thigh, fallback_pole)
    pole = bend if pole is None else np.broadcast_to(np.asarray(pole, dtype=float), hip.shape)
    knee_new, ankle_new = knee_and_ankle(
        hip, target, np.linalg.norm(thigh, axis=-1), np.linalg.norm(shin, axis=-1), pole, fallback_pole
    )
    # The bend plane's normal, old and new, on the same side: (hip -> ankle) x (towards the knee).
    n_old = np.cross(_unit(ankle - hip), bend)
    n_new = np.cross(_unit(target - hip), bend_direction(target - hip, pole, fallback_pole))
    turn_hip = _frame(knee_new - hip, n_new) @ np.swapaxes(_frame(thigh, n_old), -1, -2)
    turn_knee = _frame(ankle_new - knee_new, n_new) @ np.swapaxes(_frame(shin, n_old), -1, -2)
    return LegIK(
        hip_rotation=qmul(_quat(turn_hip), hip_rotation),
        knee_rotation=qmul(_quat(turn_knee), knee_rotation),
        knee=knee_new,
        ankle=ankle_new,
    )
