"""Analytic two-bone inverse kinematics (thigh-shin, upper arm-forearm), vectorised over frames.

A chain A -> B -> C (hip, knee, ankle or shoulder, elbow, wrist) is solved in closed form:
the middle joint is a hinge about a fixed axis ``hinge`` of A's rest frame, its angle θ
follows from the law of cosines on |C - A|, and A's rotation (including its twist) is
fixed by two directions: A -> C points at the target and the middle joint bends towards
a ``pole`` direction (knee forwards over the toes, elbow down and back). Nothing is
iterated, so the end joint lands on a reachable target to machine precision.
"""

from __future__ import annotations

import numpy as np
from scipy.spatial.transform import Rotation

from ..core.quaternions import qinv, qmul, quat_about_axis

_EPS = 1e-9


def _unit(v: np.ndarray) -> np.ndarray:
    return v / np.maximum(np.linalg.norm(v, axis=-1, keepdims=True), _EPS)


def rotate_about(axis: np.ndarray, theta: np.ndarray, v: np.ndarray) -> np.ndarray:
    """Rodrigues: rotate the fixed vector v (3,) about the fixed unit axis (3,) by θ (T,)."""
    c, s = np.cos(theta)[..., None], np.sin(theta)[..., None]
    return v * c + np.cross(axis, v) * s + axis * np.dot(axis, v) * (1.0 - c)


def hinge_angle(off_mid: np.ndarray, off_end: np.ndarray, hinge: np.ndarray, length: np.ndarray) -> np.ndarray:
    """Hinge angle θ (T,) at which |off_mid + R(hinge, θ) off_end| equals ``length`` (T,).

    |off_mid + R off_end|² = l1² + l2² + 2 off_mid·R off_end, and off_mid·R(h, θ) off_end =
    a + b cos θ + c sin θ; of the two solutions the one with the larger θ (bending in the
    positive sense of ``hinge``) is returned. Lengths out of reach are clamped.
    """
    h = _unit(np.asarray(hinge, dtype=float))
    l1, l2 = np.linalg.norm(off_mid), np.linalg.norm(off_end)
    a = np.dot(off_mid, h) * np.dot(off_end, h)
    b = np.dot(off_mid, off_end) - a
    c = np.dot(off_mid, np.cross(h, off_end))
    k = 0.5 * (np.asarray(length, dtype=float) ** 2 - l1**2 - l2**2) - a
    r = np.hypot(b, c)
    return np.arctan2(c, b) + np.arccos(np.clip(k / r, -1.0, 1.0))


def two_bone_ik(
    p_upper: np.ndarray,
    target: np.ndarray,
    parent_rot: np.ndarray,
    off_mid: np.ndarray,
    off_end: np.ndarray,
    hinge: np.ndarray,
    pole: np.ndarray,
    max_extension: float = 1.0 - 1e-9,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Local rotations of the upper and middle joint of a two-bone chain, per frame.

    Args:
        p_upper: (T, 3) global position of the upper joint A.
        target: (T, 3) where the end joint C should go.
        parent_rot: (T, 4) global rotation of A's parent.
        off_mid: (3,) rest offset of B from A (A's frame); off_end: (3,) of C from B.
        hinge: (3,) the hinge axis of B in the rest frame, perpendicular to both bones.
        pole: (T, 3) or (3,) global direction the middle joint should bend towards.
        max_extension: targets farther than this fraction of l1 + l2 are clamped.

    Returns:
        q_upper (T, 4) local rotation of A, q_mid (T, 4) local rotation of B, and
        (T, 3) the end joint's global position reached (equal to ``target`` when reachable).
    """
    off_mid = np.asarray(off_mid, dtype=float)
    off_end = np.asarray(off_end, dtype=float)
    h = _unit(np.asarray(hinge, dtype=float))
    l1, l2 = np.linalg.norm(off_mid), np.linalg.norm(off_end)
    d = np.asarray(target, dtype=float) - p_upper
    dist = np.linalg.norm(d, axis=-1)
    length = np.clip(dist, abs(l1 - l2) + 1e-6, (l1 + l2) * max_extension)
    theta = hinge_angle(off_mid, off_end, h, length)

    # Frame of the chain in A's rest coordinates: u along A->C, n the hinge, w = u x n.
    e_loc = off_mid + rotate_about(h, theta, off_end)
    u_l = _unit(e_loc)
    n_l = _unit(h - np.sum(u_l * h, axis=-1, keepdims=True) * u_l)
    w_l = np.cross(u_l, n_l)
    # On which side of A->C the middle joint lies (sign along w), from a clearly bent chain.
    e_ref = off_mid + rotate_about(h, np.array(hinge_angle(off_mid, off_end, h, 0.7 * (l1 + l2))), off_end)
    u_ref = _unit(e_ref)
    side = np.sign(np.dot(off_mid - np.dot(off_mid, u_ref) * u_ref, np.cross(u_ref, h)))

    # The same frame in the world: u at the target, the middle joint towards the pole.
    u_w = _unit(d)
    pole = np.broadcast_to(np.asarray(pole, dtype=float), d.shape)
    p_perp = pole - np.sum(pole * u_w, axis=-1, keepdims=True) * u_w
    w_w = side * _unit(p_perp)
    n_w = np.cross(w_w, u_w)

    world = np.stack([u_w, n_w, w_w], axis=-1)  # columns
    local = np.stack([u_l, n_l, w_l], axis=-1)
    g_upper = world @ np.swapaxes(local, -1, -2)
    q_glob = Rotation.from_matrix(g_upper.reshape(-1, 3, 3)).as_quat(scalar_first=True).reshape(d.shape[:-1] + (4,))
    q_upper = qmul(qinv(parent_rot), q_glob)
    q_mid = quat_about_axis(h, theta)
    reached = p_upper + u_w * length[..., None]
    return q_upper, q_mid, reached
