"""Procedural locomotion: walks (7 styles, straight or turning), runs and side-steps.

A kinematically consistent model, not noise around a template (docs/design.md, "Datasets"):
footsteps are planned first (:mod:`.footsteps`), the pelvis follows a smooth path with the
gait's rotation, obliquity, tilt, lateral sway and vertical bob (:mod:`.upper`), the root
height is kept within reach of every planted foot, and the legs are solved by analytic
two-bone IK so that planted feet do not slide (:mod:`.legs`); the trunk, head and arms
follow the gait phase (:mod:`.upper`). Subject habits and labelled styles enter through
:class:`~.gait_params.Manner` (:mod:`.gait_params`, :mod:`.styles`).

Each generator returns the Motion (120 fps by default, cm, y up, starting at
``params.start_xz`` facing ``params.heading_deg``) and its ground truth: the metadata
fields of the shared contract (variant, stride_length_cm, speed_cm_s, step_width_cm,
turn_deg, segments, left_contacts, right_contacts, NaN targets) plus cadence, stance
fraction, number of steps, placement and ``stance_ik_error_cm`` (the largest distance
between a planted ankle and its target; 0 up to rounding).

Definitions of the truth:
- contacts: frames [start, stop) in which the foot is pinned — the ankle from heel strike
  to heel-off, the toe base from heel-off to toe-off (flat-footed side-steps: both);
- stride_length_cm: mean horizontal distance between successive same-foot footprints
  (ankle positions of the flat foot), over the steady strides (walks: without the half
  steps of gait initiation and the closing step); walks list each of those strides, in
  time order (heel strikes 1-3, 2-4, ...), in ``footfall_strides_cm``;
- speed_cm_s: the root's steady progression speed along its path (stride / stride time).
"""

from __future__ import annotations

import numpy as np

from ..core.motion import Motion
from ..core.quaternions import qfix
from ..io.intervals import format_named, format_ranges
from .footsteps import SIDES, BodyGeometry, Plan, plan_run, plan_sidestep, plan_walk
from .gait_params import Manner, RunParams, SidestepParams, WalkParams
from .legs import legs_along, solve_leg_tracks
from .stance import hip_offsets, identity_rotations, to_world
from .subjects import Subject
from .upper import pelvis_rotation, pose_upper_body

MAX_WALK_STRIDE_PER_LEG = 2.0  # longer strides are not walkable with a straight-boned leg
MAX_RUN_STRIDE_PER_LEG = 4.5


def _check_stride(subject: Subject, owner: str, stride: float, limit: float) -> None:
    leg = subject.leg_length_cm
    if stride > limit * leg:
        raise ValueError(
            f"{owner}.stride_length_cm={stride:.1f} is too long for subject {subject.subject_id} "
            f"(leg length {leg:.1f} cm; at most {limit} leg lengths)"
        )


def _realise(
    subject: Subject, plan: Plan, manner: Manner, start_xz: tuple[float, float], heading_deg: float
) -> tuple[Motion, dict]:
    """Pose the body along ``plan``, crop, place it on the floor; Motion and truth."""
    sk = subject.skeleton
    geo = BodyGeometry.from_skeleton(sk)
    rot = identity_rotations(plan.n_frames, sk)
    rot[:, 0] = pelvis_rotation(plan.heading, plan.phase, plan.envelope, manner)
    hips = hip_offsets(sk, rot[:, 0])
    root_pos, feet = legs_along(geo, plan, plan.root_xz, hips)
    reached = solve_leg_tracks(sk, geo, rot, root_pos, feet)
    pose_upper_body(sk, rot, root_pos, plan.heading, plan.phase, plan.envelope, manner)

    c0, c1 = plan.crop
    n = c1 - c0
    root_w, rot_w = to_world(root_pos[c0:c1], rot[c0:c1], float(np.radians(heading_deg)), start_xz)
    motion = Motion(skeleton=sk, root_pos=root_w, rotations=qfix(rot_w, axis=0), fps=plan.fps)

    contacts = {s: [] for s in SIDES}
    err = 0.0
    for c in feet.contacts:
        a, b = max(c.start, c0), min(c.stop, c1)
        if b > a:
            contacts[c.side].append((a - c0, b - c0))
            i = SIDES.index(c.side)
            err = max(err, float(np.abs(reached[a:b, i] - feet.ankle[a:b, i]).max()))
    truth = dict(plan.truth)
    truth.update(
        {
            "target_x": float("nan"),
            "target_y": float("nan"),
            "target_z": float("nan"),
            "segments": format_named((name, a - c0, b - c0) for name, a, b in plan.segments),
            "left_contacts": format_ranges(contacts["left"]),
            "right_contacts": format_ranges(contacts["right"]),
            "heading_deg": float(heading_deg),
            "start_x": float(start_xz[0]),
            "start_z": float(start_xz[1]),
            "stance_ik_error_cm": err,
        }
    )
    assert motion.n_frames == n
    return motion, truth


def _gait(subject: Subject, params: WalkParams | RunParams, planner, limit: float) -> tuple[Motion, dict]:
    params.validate()
    _check_stride(subject, type(params).__name__, params.stride_length_cm, limit)
    plan = planner(BodyGeometry.from_skeleton(subject.skeleton), params)
    motion, truth = _realise(subject, plan, params.manner, params.start_xz, params.heading_deg)
    truth["variant"] = params.variant
    return motion, truth


def generate_walk(subject: Subject, params: WalkParams) -> tuple[Motion, dict]:
    """A walk of ``subject``: stand, gait cycles on a straight or turning path, stand.

    Deterministic in its arguments (draw params with
    :func:`~.gait_params.sample_walk_params`). Segments: walk_start, walk_leftStance /
    walk_rightStance (heel strike to the other foot's heel strike), walk_end.
    """
    return _gait(subject, params, plan_walk, MAX_WALK_STRIDE_PER_LEG)


def generate_run(subject: Subject, params: RunParams) -> tuple[Motion, dict]:
    """A steady run with flight phases; segments run_leftStance / run_rightStance (landing
    to the other foot's landing, flight included). Deterministic in its arguments."""
    return _gait(subject, params, plan_run, MAX_RUN_STRIDE_PER_LEG)


def generate_sidestep(subject: Subject, params: SidestepParams) -> tuple[Motion, dict]:
    """Side-steps facing forward; segments ``sidestep`` (a trailing-foot landing to its next
    landing). Deterministic in its arguments."""
    params.validate()
    leg = subject.leg_length_cm
    if params.stance_width_cm + params.step_cm > 1.2 * leg:
        raise ValueError(
            f"SidestepParams.step_cm={params.step_cm:.1f} with stance_width_cm={params.stance_width_cm:.1f} "
            f"spreads the feet wider than 1.2 leg lengths ({1.2 * leg:.1f} cm) for subject {subject.subject_id}"
        )
    plan = plan_sidestep(BodyGeometry.from_skeleton(subject.skeleton), params)
    motion, truth = _realise(subject, plan, params.manner, params.start_xz, params.heading_deg)
    truth["variant"] = params.variant
    return motion, truth
