"""Standing-body kinematics shared by the reach and idle generators (CMU rig).

Everything is built in a *body frame* (x left, y up from the floor, z forward, origin on
the floor) and moved onto the floor with :func:`to_world` at the end. The feet are planted:
each ankle has one fixed position and each foot one fixed flat orientation for the whole
clip, the root height follows from the legs (:func:`root_height`) and the legs are posed by
analytic two-bone IK (:mod:`motionvar.synth.ik`), so planted feet cannot slide.

Joint conventions of :func:`motionvar.core.cmu_skeleton` (zero rotations = neutral standing
with T-pose arms): flexion (forward bending, knee: backward bending) is a positive rotation
about +x, axial rotation is about +y, lateral bending about +z (towards the right side).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..core.kinematics import fk
from ..core.quaternions import qidentity, qinv, qmul, qrot, quat_about_axis
from ..core.skeleton import Skeleton
from .ik import rotate_about, two_bone_ik
from .signals import subject_rng
from .subjects import Subject

SIDES = ("left", "right")
_X, _Y, _Z = np.eye(3)

# Winter (2009), Table 4.1: segment mass fractions and centre-of-mass location from the
# proximal joint; the trunk's COM is midway between hip-joint centre and shoulders.
_SEGMENTS = (  # (proximal, distal, mass fraction, COM fraction from proximal)
    ("{s}UpLeg", "{s}Leg", 0.100, 0.433),
    ("{s}Leg", "{s}Foot", 0.0465, 0.433),
    ("{s}Foot", "{s}ToeBase", 0.0145, 0.5),
    ("{s}Arm", "{s}ForeArm", 0.028, 0.436),
    ("{s}ForeArm", "{s}Hand", 0.016, 0.430),
    ("{s}Hand", "{s}HandIndex1", 0.006, 0.5),
)
_TRUNK_MASS, _HEAD_MASS = 0.497, 0.081


@dataclass(frozen=True)
class Rig:
    """Joint indices of the CMU rig used by the standing-body builder."""

    skeleton: Skeleton

    def __getitem__(self, name: str) -> int:
        return self.skeleton.index(name)

    def side(self, side: str, part: str) -> int:
        """``side`` in left/right, ``part`` e.g. "UpLeg", "Arm", "HipJoint", "Shoulder"."""
        if part == "HipJoint":
            return self.skeleton.index(("L" if side == "left" else "R") + "HipJoint")
        return self.skeleton.index(side.capitalize() + part)

    def offset(self, name: str) -> np.ndarray:
        return self.skeleton.offsets[self.skeleton.index(name)]


@dataclass(frozen=True)
class Feet:
    """Planted feet in the body frame: ankle positions (2, 3) and flat foot rotations (2, 4),
    left first."""

    ankles: np.ndarray
    rotations: np.ndarray

    @property
    def forward(self) -> np.ndarray:
        """(2, 3) each foot's forward direction (its toe line)."""
        return qrot(self.rotations, np.broadcast_to(_Z, (2, 3)))


@dataclass(frozen=True)
class StanceHabit:
    """How a subject stands (personal, from :func:`stance_habit`).

    - width_cm: ankle spacing, 15-28 cm × height scale; toe_out_deg: 3-12° per foot.
      Self-selected quiet stance: heels ≈ 17 cm apart, feet ≈ 14° apart (McIlroy & Maki 1997).
    - com_ahead_cm: root ahead of the ankle line, 2-5 cm × height scale (the centre of
      mass lies a few cm in front of the ankles in quiet standing, Winter 2009).
    - lock_knee_deg: flexion of a "straight" standing knee, 1-5° (docs/gait.md: loaded leg straight).
    - arm_abduction_deg: relaxed arms hang 4-12° out from vertical, clear of the hips.
    """

    width_cm: float
    toe_out_deg: float
    com_ahead_cm: float
    lock_knee_deg: float
    arm_abduction_deg: float


def stance_habit(subject: Subject) -> StanceHabit:
    """The subject's :class:`StanceHabit`; the same for all of the subject's clips."""
    r = subject_rng(subject, "stance")
    h = subject.height_scale
    return StanceHabit(
        width_cm=float(r.uniform(15.0, 28.0) * h),
        toe_out_deg=float(r.uniform(3.0, 12.0)),
        com_ahead_cm=float(r.uniform(2.0, 5.0) * h),
        lock_knee_deg=float(r.uniform(1.0, 5.0)),
        arm_abduction_deg=float(r.uniform(4.0, 12.0)),
    )


def euler_q(
    flex: np.ndarray | float = 0.0, axial: np.ndarray | float = 0.0, lateral: np.ndarray | float = 0.0
) -> np.ndarray:
    """Local rotation (..., 4) from flexion (about x), axial rotation (about y) and lateral
    bending (about z) in radians, applied as axial * flex * lateral."""
    flex, axial, lateral = np.broadcast_arrays(*(np.asarray(a, dtype=float) for a in (flex, axial, lateral)))
    return qmul(qmul(quat_about_axis(_Y, axial), quat_about_axis(_X, flex)), quat_about_axis(_Z, lateral))


def plant_feet(skeleton: Skeleton, width_cm: float, toe_out_deg: float, ahead_cm: float = 0.0) -> Feet:
    """Ankles ``width_cm`` apart (x = ±width/2, z = ``ahead_cm``), feet flat with the toe base on
    the floor (y = 0) and turned out by ``toe_out_deg`` each."""
    rig = Rig(skeleton)
    ankles, rots = [], []
    for sign, side in ((1.0, "left"), (-1.0, "right")):
        q = quat_about_axis(_Y, sign * np.radians(toe_out_deg))
        toe = rig.offset(side.capitalize() + "ToeBase")
        ankles.append([sign * width_cm / 2.0, -toe[1], ahead_cm])
        rots.append(q)
    return Feet(ankles=np.array(ankles), rotations=np.array(rots))


def leg_reach(skeleton: Skeleton, side: str, knee_deg: np.ndarray | float) -> np.ndarray:
    """Hip-to-ankle distance of a leg whose knee is flexed by ``knee_deg``."""
    rig = Rig(skeleton)
    a = rig.offset(side.capitalize() + "Leg")
    b = rig.offset(side.capitalize() + "Foot")
    k = np.radians(np.asarray(knee_deg, dtype=float))
    return np.linalg.norm(a + rotate_about(_X, k, b), axis=-1)


def hip_offsets(skeleton: Skeleton, root_rot: np.ndarray) -> np.ndarray:
    """(T, 2, 3) hip-joint positions relative to the root for root rotations (T, 4), left first."""
    rig = Rig(skeleton)
    out = []
    for side in SIDES:
        off = rig.offset(("L" if side == "left" else "R") + "HipJoint") + rig.offset(side.capitalize() + "UpLeg")
        out.append(qrot(root_rot, np.broadcast_to(off, root_rot.shape[:-1] + (3,))))
    return np.stack(out, axis=-2)


def root_height(
    skeleton: Skeleton, root_xz: np.ndarray, root_rot: np.ndarray, feet: Feet, knee_deg: np.ndarray | float
) -> np.ndarray:
    """(T,) root height at which no knee is straighter than ``knee_deg`` (scalar, (T,) or (T, 2)).

    Each leg allows the hip at most ``leg_reach(knee)`` from its ankle; the root takes the
    lowest of the two heights, so the more extended leg has exactly that knee flexion and the
    other one bends more. This keeps both feet on their planted positions.
    """
    hips = hip_offsets(skeleton, root_rot)
    knee = np.asarray(knee_deg, dtype=float)
    if knee.ndim < 2:
        knee = np.stack([knee, knee], axis=-1)
    knee = np.broadcast_to(knee, root_rot.shape[:-1] + (2,))
    heights = []
    for i, side in enumerate(SIDES):
        reach = leg_reach(skeleton, side, knee[..., i])
        dx = root_xz[..., 0] + hips[..., i, 0] - feet.ankles[i, 0]
        dz = root_xz[..., 1] + hips[..., i, 2] - feet.ankles[i, 2]
        vert = np.sqrt(np.maximum(reach**2 - dx**2 - dz**2, 0.0))
        heights.append(feet.ankles[i, 1] + vert - hips[..., i, 1])
    return np.minimum(heights[0], heights[1])


def solve_legs(skeleton: Skeleton, rotations: np.ndarray, root_pos: np.ndarray, feet: Feet) -> None:
    """Pose both legs in place so that the ankles sit on ``feet.ankles`` with the feet flat.

    The knee bends towards the foot's forward direction (knee over the toes).
    """
    rig = Rig(skeleton)
    root_rot = rotations[:, 0]
    for i, side in enumerate(SIDES):
        hj, up, knee, ankle = (rig.side(side, p) for p in ("HipJoint", "UpLeg", "Leg", "Foot"))
        g_hj = qmul(root_rot, rotations[:, hj])
        p_hip = root_pos + qrot(root_rot, np.broadcast_to(skeleton.offsets[hj], root_pos.shape))
        p_hip = p_hip + qrot(g_hj, np.broadcast_to(skeleton.offsets[up], root_pos.shape))
        q_up, q_knee, _ = two_bone_ik(
            p_hip,
            np.broadcast_to(feet.ankles[i], root_pos.shape),
            g_hj,
            skeleton.offsets[knee],
            skeleton.offsets[ankle],
            _X,
            feet.forward[i],
        )
        rotations[:, up] = q_up
        rotations[:, knee] = q_knee
        g_knee = qmul(qmul(g_hj, q_up), q_knee)
        rotations[:, ankle] = qmul(qinv(g_knee), np.broadcast_to(feet.rotations[i], g_knee.shape))


def solve_arm(
    skeleton: Skeleton,
    rotations: np.ndarray,
    root_pos: np.ndarray,
    side: str,
    target: np.ndarray,
    pole: np.ndarray,
    max_extension: float = 0.999,
    frames: tuple[np.ndarray, np.ndarray] | None = None,
) -> np.ndarray:
    """Pose one arm in place so that the wrist (``*Hand`` joint) reaches ``target`` (T, 3),
    the elbow bending towards ``pole``; returns the wrist positions reached (T, 3).

    ``frames``: global joint positions and rotations of ``rotations`` (``fk(...,
    return_rotations=True)``), to share one forward-kinematics pass between both arms
    (one arm's rotations do not move the other's shoulder); computed when None."""
    rig = Rig(skeleton)
    arm, fore, hand, clav = (rig.side(side, p) for p in ("Arm", "ForeArm", "Hand", "Shoulder"))
    if frames is None:
        frames = fk(rotations, root_pos, skeleton.offsets, skeleton.parents, return_rotations=True)
    pos, grot = frames
    hinge = -_Y if side == "left" else _Y  # elbow flexion brings the T-pose forearm forwards
    q_arm, q_fore, reached = two_bone_ik(
        pos[:, arm],
        target,
        grot[:, clav],
        skeleton.offsets[fore],
        skeleton.offsets[hand],
        hinge,
        pole,
        max_extension=max_extension,
    )
    rotations[:, arm] = q_arm
    rotations[:, fore] = q_fore
    return reached


def arm_reach(skeleton: Skeleton, side: str, elbow_deg: np.ndarray | float) -> np.ndarray:
    """Shoulder-to-wrist distance with the elbow flexed by ``elbow_deg``."""
    rig = Rig(skeleton)
    l1 = np.linalg.norm(rig.offset(side.capitalize() + "ForeArm"))
    l2 = np.linalg.norm(rig.offset(side.capitalize() + "Hand"))
    k = np.radians(np.asarray(elbow_deg, dtype=float))
    return np.sqrt(l1**2 + l2**2 + 2 * l1 * l2 * np.cos(k))


def hanging_hand_offsets(skeleton: Skeleton, elbow_deg: np.ndarray | float, abduction_deg: float) -> np.ndarray:
    """(..., 2, 3) wrist offsets from the shoulders of relaxed, gravity-hanging arms in the
    heading frame: the upper arm hangs ``abduction_deg`` out from vertical and the forearm
    points forward-down at ``elbow_deg`` of flexion. Left first."""
    rig = Rig(skeleton)
    k = np.radians(np.asarray(elbow_deg, dtype=float))
    ab = np.radians(abduction_deg)
    out = []
    for sign, side in ((1.0, "left"), (-1.0, "right")):
        l1 = np.linalg.norm(rig.offset(side.capitalize() + "ForeArm"))
        l2 = np.linalg.norm(rig.offset(side.capitalize() + "Hand"))
        down = l1 + l2 * np.cos(k)
        fwd = l2 * np.sin(k)
        out.append(np.stack([sign * down * np.sin(ab), -down * np.cos(ab), fwd], axis=-1))
    return np.stack(out, axis=-2)


def elbow_pole(heading_rot: np.ndarray, side: str) -> np.ndarray:
    """Elbow pole (T, 3): out, down and back in the heading frame; perpendicular enough to
    every arm direction used here (hanging, forward, low, high) to fix the elbow's plane."""
    sign = 1.0 if side == "left" else -1.0
    v = np.array([0.55 * sign, -0.45, -0.70])
    return qrot(heading_rot, np.broadcast_to(v / np.linalg.norm(v), heading_rot.shape[:-1] + (3,)))


def body_com(positions: np.ndarray, skeleton: Skeleton, arms: bool = True) -> np.ndarray:
    """(..., 3) whole-body centre of mass from joint positions (..., J, 3), Winter's segment
    table (module constants); the head's COM is taken half the neck length above the Head
    joint. ``arms=False`` gives the centre of mass of the body without the arms."""
    idx = skeleton.index
    com = np.zeros(positions.shape[:-2] + (3,))
    total = 0.0
    for s in ("Left", "Right"):
        for prox, dist, mass, frac in _SEGMENTS if arms else _SEGMENTS[:3]:
            total += mass
            p, d = positions[..., idx(prox.format(s=s)), :], positions[..., idx(dist.format(s=s)), :]
            com += mass * (p + frac * (d - p))
    hip_mid = 0.5 * (positions[..., idx("LeftUpLeg"), :] + positions[..., idx("RightUpLeg"), :])
    sh_mid = 0.5 * (positions[..., idx("LeftArm"), :] + positions[..., idx("RightArm"), :])
    com += _TRUNK_MASS * 0.5 * (hip_mid + sh_mid)
    neck, head = positions[..., idx("Neck1"), :], positions[..., idx("Head"), :]
    com += _HEAD_MASS * (head + 0.5 * (head - neck))
    return com / (total + _TRUNK_MASS + _HEAD_MASS)


def heading_quat(heading: np.ndarray | float) -> np.ndarray:
    """Rotation about +y by ``heading`` radians (turning the body's +z towards +x)."""
    return quat_about_axis(_Y, heading)


def to_world(
    root_pos: np.ndarray, rotations: np.ndarray, heading: float, start_xz: tuple[float, float]
) -> tuple[np.ndarray, np.ndarray]:
    """Move a body-frame clip onto the floor: rotate by ``heading`` about y, then translate
    the body-frame origin to (x, 0, z) = ``start_xz``. Returns new root positions and rotations."""
    q = heading_quat(heading)
    pos = qrot(np.broadcast_to(q, root_pos.shape[:-1] + (4,)), root_pos)
    pos = pos + np.array([start_xz[0], 0.0, start_xz[1]])
    rot = rotations.copy()
    rot[:, 0] = qmul(np.broadcast_to(q, rot[:, 0].shape), rot[:, 0])
    return pos, rot


def to_body_frame(points: np.ndarray, heading_deg: float, start_xz: tuple[float, float]) -> np.ndarray:
    """World points (..., 3) into the body frame of a clip made by :func:`to_world` with
    ``heading`` = radians(heading_deg) and ``start_xz`` (the inverse of that placement)."""
    q = heading_quat(-np.radians(heading_deg))
    p = np.asarray(points, dtype=float) - np.array([start_xz[0], 0.0, start_xz[1]])
    return qrot(np.broadcast_to(q, p.shape[:-1] + (4,)), p)


def identity_rotations(n_frames: int, skeleton: Skeleton) -> np.ndarray:
    """(T, J, 4) identity rotations."""
    return qidentity((n_frames, skeleton.n_joints))
