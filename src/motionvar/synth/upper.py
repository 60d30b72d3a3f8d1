"""Pelvis, trunk, head and arms over the gait cycle (docs/gait.md; Perry & Burnfield 2010).

All oscillations are functions of the left leg's gait phase φ (0 at a left heel strike)
times the gait envelope (0 standing, 1 in steady gait):

- pelvis rotation (transverse): the side of the leading leg forward, −A cos 2πφ;
- pelvic obliquity: the swing side drops, most at the end of loading response (φ = 0.2);
- pelvic tilt: a mean anterior tilt while moving plus two oscillations per stride, most
  anterior in terminal stance;
- the thorax counter-rotates (world yaw −ratio × pelvic rotation) and bends against the
  obliquity; the trunk leans by ``torso_lean_deg`` over the three spine joints;
- the head keeps 70 % of the trunk lean and all of the thorax rotation out of the gaze
  and adds the ``head_pitch_deg`` habit;
- arms swing out of phase with the same-side leg (left arm most forward at right heel
  strike), the elbow flexes more when the arm is forward; they are posed by two-bone IK
  to hanging-arm wrist targets (the rig of :mod:`motionvar.synth.stance`).
Angles use :func:`motionvar.synth.stance.euler_q` (flexion about +x, axial about +y,
lateral bending about +z towards the right).
"""

from __future__ import annotations

import numpy as np

from ..core.kinematics import fk
from ..core.quaternions import qmul, qrot
from ..core.skeleton import Skeleton
from .gait_params import Manner
from .stance import Rig, elbow_pole, euler_q, hanging_hand_offsets, heading_quat, solve_arm

SPINE_SHARES = (("LowerBack", 0.4), ("Spine", 0.35), ("Spine1", 0.25))
HEAD_KEEPS_LEAN = 0.3  # fraction of the trunk lean the head keeps (the rest is corrected)
TRUNK_OBLIQUITY_COMP = 0.8  # fraction of the pelvic obliquity the trunk bends back


def pelvis_angles(phase: np.ndarray, env: np.ndarray, m: Manner) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(rotation, obliquity, tilt) in radians over frames (the root's oscillations)."""
    rot = -np.radians(m.pelvis_rotation_deg) * np.cos(2 * np.pi * phase) * env
    obl = np.radians(m.pelvis_obliquity_deg) * np.sin(2 * np.pi * (phase + 0.05)) * env
    tilt = (
        np.radians(m.pelvis_tilt_mean_deg) + np.radians(m.pelvis_tilt_deg) * np.cos(4 * np.pi * (phase - 0.4))
    ) * env
    return rot, obl, tilt


def pelvis_rotation(heading: np.ndarray, phase: np.ndarray, env: np.ndarray, m: Manner) -> np.ndarray:
    """(T, 4) global root rotation: travel heading plus the pelvis's gait oscillations."""
    rot, obl, tilt = pelvis_angles(phase, env, m)
    return euler_q(flex=tilt, axial=heading + rot, lateral=obl)


def pose_upper_body(
    sk: Skeleton,
    rotations: np.ndarray,
    root_pos: np.ndarray,
    heading: np.ndarray,
    phase: np.ndarray,
    env: np.ndarray,
    m: Manner,
) -> None:
    """Spine, neck, head, clavicles and arms in place (the root and legs must be set)."""
    rig = Rig(sk)
    rot, obl, tilt = pelvis_angles(phase, env, m)
    lean = np.radians(m.torso_lean_deg)
    thorax_yaw = -m.thorax_rotation_ratio * rot  # world yaw of the thorax relative to the heading
    for name, share in SPINE_SHARES:
        rotations[:, rig[name]] = euler_q(
            flex=share * (lean - tilt),
            axial=share * (thorax_yaw - rot),
            lateral=-share * TRUNK_OBLIQUITY_COMP * obl,
        )
    head_flex = np.radians(m.head_pitch_deg) - (1.0 - HEAD_KEEPS_LEAN) * lean
    residual_lateral = -(1.0 - TRUNK_OBLIQUITY_COMP) * obl
    for name in ("Neck1", "Head"):
        rotations[:, rig[name]] = euler_q(flex=0.5 * head_flex, axial=-0.5 * thorax_yaw, lateral=0.5 * residual_lateral)
    lift = np.radians(m.shoulder_lift_deg)
    for sign, side in ((1.0, "left"), (-1.0, "right")):
        rotations[:, rig.side(side, "Shoulder")] = euler_q(lateral=np.full(len(phase), sign * lift))

    frames = fk(rotations, root_pos, sk.offsets, sk.parents, return_rotations=True)  # shared by both arms
    pos = frames[0]
    turn = heading_quat(heading + thorax_yaw)
    for i, side in enumerate(("left", "right")):
        forward = np.cos(2 * np.pi * (phase - (0.5 if side == "left" else 0.0))) * env  # +1: arm most forward
        flex = np.radians(m.arm_mean_deg + m.arm_swing_deg * forward)
        elbow = m.elbow_flex_deg + m.elbow_swing_deg * 0.5 * (1.0 + forward) * env
        hang = hanging_hand_offsets(sk, elbow, m.arm_abduction_deg)[:, i]
        target = pos[:, rig.side(side, "Arm")] + qrot(qmul(turn, euler_q(flex=-flex)), hang)
        solve_arm(sk, rotations, root_pos, side, target, elbow_pole(turn, side), frames=frames)
