"""Post-processing (Ma et al. 2010, Sec. 6.3): transitions by displacement mapping
(Eq. 14-15) and footskate cleanup, which computes the root motion.

Poses here are local rotations (T, J, 4) plus, optionally, a root height curve (T,);
the root position is set by :func:`reconstruct_root` at the end. Footskate cleanup comes
in two forms (:data:`CLEANUPS`): "root", the paper's (the support foot is fixed and
treated as the root, [TLP07]; the other foot of a double support is not held and slides),
and "root+feet", that root followed by [KSG02] in its simplest form (:func:`pin_feet`:
every foot in contact is held where its contact began by analytic leg IK).
"""

from __future__ import annotations

import numpy as np
from scipy.signal import find_peaks

from ..core.kinematics import fk
from ..core.leg_ik import two_bone_ik
from ..core.quaternions import qdistance_sinusoidal, qexp, qinv, qlog, qmul, qrot, quat_about_axis
from ..core.skeleton import Skeleton
from ..prep.intervals import mask_to_intervals


def pose_distance(pose: np.ndarray, poses: np.ndarray) -> np.ndarray:
    """Distance of one pose (J, 4) to each of poses (T, J, 4): the sum over joints of the
    sinusoidal rotational distance (Sec. 4, [PSS02])."""
    return qdistance_sinusoidal(pose[None], poses).sum(axis=-1)


LANDING_RULES = ("significant_maximum", "first_maximum")
#: Significant maximum: prominence of at least this fraction of the distance's range. Into a
#: walking cycle the pose distance to the previous clip's last pose (the same phase) rises
#: to the opposite phase and falls back: that maximum's prominence is ~the whole range; the
#: wiggles that make the first local maximum 3-5 frames in are a few per cent of it.
LANDING_PROMINENCE = 0.25


def landing_frame(last_pose: np.ndarray, clip: np.ndarray, rule: str = "significant_maximum") -> int:
    """Landing frame t of a transition into ``clip`` (T, J, 4), 1-based (Sec. 6.3), from
    the pose distance to ``last_pose``, the last frame of the preceding clip.

    ``rule`` "first_maximum": the paper's rule read literally, the frame that reaches the
    first local maximum of the distance (it fires on wiggles a few frames into the clip,
    and the displacement is then blended away within those frames). "significant_maximum":
    the first local maximum whose prominence is at least :data:`LANDING_PROMINENCE` of the
    distance's range over the clip. Either way at least 2, and the clip's length if no
    maximum qualifies."""
    if rule not in LANDING_RULES:
        raise ValueError(f"landing_frame: rule must be one of {list(LANDING_RULES)}; got {rule!r}")
    d = pose_distance(last_pose, clip)
    if rule == "first_maximum":
        interior = np.flatnonzero((d[1:-1] >= d[:-2]) & (d[1:-1] > d[2:])) + 1
    else:
        interior, _ = find_peaks(d, prominence=LANDING_PROMINENCE * max(float(np.ptp(d)), 1e-12))
    t = int(interior[0]) + 1 if len(interior) else len(d)
    return max(t, 2)


def blend_weights(t: int) -> np.ndarray:
    """Eq. 15: rho_i = 2 u^3 - 3 u^2 + 1 with u = (i - 1) / (t - 1), i = 1..t; rho_1 = 1, rho_t = 0."""
    u = np.arange(t) / max(t - 1, 1)
    return 2 * u**3 - 3 * u**2 + 1


def heading_angle(q: np.ndarray, forward: np.ndarray) -> np.ndarray:
    """Yaw (radians about +y) of the direction ``forward`` rotated by root rotations q (..., 4)."""
    f = qrot(q, np.broadcast_to(forward, q.shape[:-1] + (3,)))
    return np.arctan2(-f[..., 2], f[..., 0])


def land(
    last_pose: np.ndarray,
    second: np.ndarray,
    last_extra: np.ndarray | None = None,
    second_extra: np.ndarray | None = None,
    landing: int | None = None,
    align_heading: bool = True,
    forward: np.ndarray = np.array([1.0, 0.0, 0.0]),
    landing_rule: str = "significant_maximum",
) -> tuple[np.ndarray, np.ndarray | None]:
    """M2 edited for a transition from a clip ending in ``last_pose`` (Eq. 14-15):
    {q_1..q_t, p^2_(t+1)..p^2_T} with q_i = p^2_i exp(rho_i log((p^2_1)^-1 p^1_T)) per
    joint, so that q_1 = p^1_T; per-frame channels ``second_extra`` get
    q_i = p^2_i + rho_i (p^1_T - p^2_1). Landing frame: ``landing``, else
    :func:`landing_frame` by ``landing_rule``. See :func:`transition`."""
    second = second.copy()
    if align_heading:
        yaw = heading_angle(last_pose[0], forward) - heading_angle(second[0, 0], forward)
        second[:, 0] = qmul(quat_about_axis([0.0, 1.0, 0.0], yaw), second[:, 0])
    t = landing_frame(last_pose, second, landing_rule) if landing is None else int(np.clip(landing, 2, len(second)))
    rho = blend_weights(t)
    delta = qlog(qmul(qinv(second[0]), last_pose))  # (J, 3)
    second[:t] = qmul(second[:t], qexp(rho[:, None, None] * delta[None]))
    extra = None
    if last_extra is not None and second_extra is not None:
        extra = np.array(second_extra, dtype=float, copy=True)
        extra[:t] += rho.reshape((-1,) + (1,) * (extra.ndim - 1)) * (last_extra - extra[0])
    return second, extra


def transition(
    first: np.ndarray,
    second: np.ndarray,
    first_extra: np.ndarray | None = None,
    second_extra: np.ndarray | None = None,
    landing: int | None = None,
    align_heading: bool = True,
    forward: np.ndarray = np.array([1.0, 0.0, 0.0]),
    landing_rule: str = "significant_maximum",
) -> tuple[np.ndarray, np.ndarray | None]:
    """M = M1 (+) M2 (Eq. 14): {p^1_1..p^1_(T-1), q_1..q_t, p^2_(t+1)..p^2_T} with
    q_i = p^2_i + rho_i dp, dp = p^1_T - p^2_1. Only M2 is edited (:func:`land`).

    For rotations the displacement is taken in the tangent space of each joint:
    q_i = p^2_i exp(rho_i log((p^2_1)^-1 p^1_T)), so q_1 = p^1_T exactly. With
    ``align_heading`` M2's root is first turned about the vertical so that its first
    frame heads where M1's last frame heads (our addition: it lets turns accumulate over a
    sequence instead of being blended back; a no-op for clips that already agree).

    Args:
        first, second: (T1, J, 4) and (T2, J, 4) local rotations.
        first_extra, second_extra: optional per-frame channels (T, ...) displaced alike
            (e.g. the root height curve).
        landing: landing frame t (1-based); default :func:`landing_frame` by ``landing_rule``.
        forward: the root's forward axis after space warping (+x).
    """
    last_extra = None if first_extra is None else first_extra[-1]
    edited, extra = land(first[-1], second, last_extra, second_extra, landing, align_heading, forward, landing_rule)
    rotations = np.concatenate([first[:-1], edited], axis=0)
    if extra is not None:
        extra = np.concatenate([first_extra[:-1], extra], axis=0)
    return rotations, extra


def support_foot(foot_low: np.ndarray, min_frames: int = 0) -> np.ndarray:
    """Index (T,) of the supporting foot from the feet's heights above their planted
    heights ``foot_low`` (T, 2): the lower foot, with a minimum contact time.

    The lower foot of each frame (argmin) changes in runs. With ``min_frames`` <= 1 these
    are returned as they are (a foot supports in every frame it is lower: the literal
    rule). Otherwise a run of the other foot shorter than ``min_frames`` frames does not
    take the support (in double support both feet are down and the lower one flickers
    every few frames): the support switches only to a foot that stays lower for at least
    ``min_frames`` frames, and from the first frame of that run (the cleanup sees the whole
    motion, so it need not wait for the run to end). Every support phase then lasts at
    least ``min_frames`` frames, except when no run is that long: then the foot lower in
    most frames supports throughout. Vectorised run-length logic, no loop over frames.
    """
    low = np.asarray(foot_low, dtype=float)
    if low.ndim != 2 or low.shape[1] != 2:
        raise ValueError(f"support_foot: foot_low must be (T, 2); got {low.shape}")
    lower = np.argmin(low, axis=1)
    if min_frames <= 1 or len(lower) == 0:
        return lower
    cuts = np.flatnonzero(np.diff(lower)) + 1
    starts = np.concatenate([[0], cuts])
    lengths = np.diff(np.concatenate([starts, [len(lower)]]))
    long = lengths >= min_frames
    if not long.any():
        return np.full(len(lower), int(np.bincount(lower, minlength=2).argmax()))
    owner = np.maximum.accumulate(np.where(long, np.arange(len(starts)), -1))  # last long run so far
    owner[owner < 0] = int(np.argmax(long))  # short runs before the first long run join it
    return np.repeat(lower[starts][owner], lengths)


def foot_heights(
    rotations: np.ndarray, skeleton: Skeleton, feet: np.ndarray, planted: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The feet with the root at the origin: positions (T, 2, F, 3) of each foot's joints
    ``feet`` (2, F), the index (T, 2) of each foot's lowest joint above its planted height
    ``planted`` (2, F), and that height (T, 2), the foot's height."""
    T = len(rotations)
    feet = np.asarray(feet, dtype=np.int64).reshape(2, -1)
    planted = np.asarray(planted, dtype=float).reshape(feet.shape)
    local = fk(rotations, np.zeros((T, 3)), skeleton.offsets, skeleton.parents)  # root at the origin
    p = local[:, feet]  # (T, 2, F, 3)
    above = p[..., 1] - planted  # (T, 2, F): height above planted, root at height 0
    joint = np.argmin(above, axis=2)  # lowest joint of each foot
    foot_low = np.take_along_axis(above, joint[..., None], axis=2)[..., 0]  # (T, 2)
    return p, joint, foot_low


def _planted_carrier(p: np.ndarray, joint: np.ndarray, support: np.ndarray) -> np.ndarray:
    """(T,) the foot that carries the root's step into each frame (:func:`reconstruct_root` with
    ``planted_carrier``): the support foot, except in a frame where the support passes to the
    other foot, where it is the foot whose lowest joint moved (relative to the root) most like the
    support's did the frame before. ``p`` (T, 2, F, 3) foot joint positions relative to the root,
    ``joint`` (T, 2) each foot's lowest joint, ``support`` (T,) the support foot."""
    t = np.arange(len(p))
    feet = np.arange(2)[None, :]
    moved = np.zeros((len(p), 2, 3))
    moved[1:] = p[t[1:, None], feet, joint[1:]] - p[t[:-1, None], feet, joint[1:]]  # each foot's step
    carrier = support.copy()
    switch = np.flatnonzero(support[1:] != support[:-1]) + 1
    switch = switch[switch >= 2]
    before = moved[switch - 1, support[switch - 1]]  # (S, 3): the root's step the frame before
    carrier[switch] = np.argmin(np.linalg.norm((moved[switch] - before[:, None])[..., [0, 2]], axis=-1), axis=1)
    return carrier


def reconstruct_root(
    rotations: np.ndarray,
    skeleton: Skeleton,
    feet: np.ndarray,
    planted: np.ndarray,
    root_height: np.ndarray | None = None,
    flight_threshold: float | None = None,
    min_support_frames: int = 0,
    planted_carrier: bool = False,
) -> np.ndarray:
    """Footskate cleanup (Sec. 6.3): the root trajectory (T, 3) that keeps the lower foot
    planted ("fixing this foot on the ground and treating it as the root", [TLP07]).

    A foot's height is that of its lowest joint above the joint's planted height (ankle
    and toe: a foot rolling over its toes stands on the toe, a foot landing on its heel
    on the ankle). The supporting foot's lowest joint is pinned: horizontally the root
    moves opposite to that joint's motion relative to the root, vertically the root sits
    so that the joint is at its planted height. Which foot supports: with
    ``min_support_frames`` <= 1 the lower foot of every frame (the paper's rule read
    literally, "comparing the height of the two feet"); otherwise the lower foot with a
    minimum contact time (:func:`support_foot`), so that the support does not flicker
    between the feet while both are down in double support.

    In the frame where the support passes to the other foot, the new support carries the
    root's step; a foot that becomes the lower one in the frame it lands is still moving into
    it, and the root absorbs that last approach (up to 0.7 cm of a stride on generator walks).
    With ``planted_carrier`` that step is carried instead by whichever foot keeps the root's
    velocity closest to the frame before's: the foot that is planted over the step (the
    stride measure, :func:`.examples.stride_root`).

    Behaviours with flight phases (running): pass the predicted root height curve
    ``root_height`` (T,) and ``flight_threshold`` (cm). A frame is in flight when both
    feet, placed with the predicted root height, are higher than ``flight_threshold``;
    there the predicted curve sets the root height and the root moves horizontally at
    constant speed (the velocity of the last supported frame).

    Args:
        rotations: (T, J, 4) local rotations.
        feet: (2, F) joint indices of the left and the right foot (e.g. ankle and toe).
        planted: (2, F) height (cm) of each of those joints when its foot is planted.
        min_support_frames: minimum contact time of the support foot, in frames.
    """
    T = len(rotations)
    p, joint, foot_low = foot_heights(rotations, skeleton, feet, planted)
    support = support_foot(foot_low, min_support_frames)
    t = np.arange(T)
    carrier = _planted_carrier(p, joint, support) if planted_carrier else support
    pin = joint[t, carrier]
    now = p[t, carrier, pin]
    prev = p[np.maximum(t - 1, 0), carrier, pin]
    step = np.zeros((T, 3))
    step[1:, [0, 2]] = -(now[1:, [0, 2]] - prev[1:, [0, 2]])
    height = -foot_low[t, support]
    if root_height is not None and flight_threshold is not None:
        root_height = np.asarray(root_height, dtype=float)
        flight = np.all(root_height[:, None] + foot_low > flight_threshold, axis=1)
        flight[0] = False
        last_supported = np.maximum.accumulate(np.where(flight, 0, t))
        step[flight] = step[last_supported[flight]]
        height = np.where(flight, root_height, height)
    root = np.cumsum(step, axis=0)
    root[:, 1] = height
    return root


#: Footskate cleanups: "root" (Sec. 6.3 as published: :func:`reconstruct_root`) and
#: "root+feet" (that root, then every foot in contact pinned by leg IK, :func:`pin_feet`).
CLEANUPS = ("root", "root+feet")


#: Where a pinned foot is held during a contact (:func:`contact_offsets`).
ANCHORS = ("median", "start")


def contact_offsets(
    foot_positions: np.ndarray, contacts: np.ndarray, planted: np.ndarray, blend_frames: int, anchor: str = "median"
) -> np.ndarray:
    """Horizontal displacement (T, S, 3; y = 0) that holds each of S feet still during its
    contacts, blended in before and out after each contact.

    Within a contact the foot's contact point is the joint nearest its planted height,
    taken per frame pair as :func:`..metrics.foot_skating.contact_point_speeds` takes it
    (the ankle while the heel is down, the toe as the foot rolls over it); its horizontal
    travel since the contact's first frame is accumulated, and the displacement is the
    anchor minus that travel, so that moving the whole foot by it (its orientation kept)
    leaves the contact point still while the foot rolls. ``anchor`` "median": the median
    travel over the contact (per axis), i.e. where the foot stands in most of the contact:
    after :func:`reconstruct_root`, where the root holds it as the support foot, so the
    support foot's leg needs no correction and only the double-support frames at the
    contact's ends do (a foot that is never the support is held near its middle position).
    "start": where the contact began (the displacement then stays through the support
    phase, where a nearly straight leg may not reach it).

    Towards a contact the displacement is blended in over the ``blend_frames`` frames
    before its first frame and out over those after its last frame (Eq. 15's weights,
    within the gap to the foot's neighbouring contacts), so the swinging foot takes it
    up and back smoothly. Loops over contacts, not frames.

    Args:
        foot_positions: (T, S, F, 3) global positions of F joints of S feet (ankle first).
        contacts: (T, S) contact masks.
        planted: (S, F) planted height of each joint.
        blend_frames: frames over which the displacement is blended in and out.
        anchor: "median" or "start" (:data:`ANCHORS`).
    """
    if anchor not in ANCHORS:
        raise ValueError(f"contact_offsets: anchor must be one of {list(ANCHORS)}; got {anchor!r}")
    p = np.asarray(foot_positions, dtype=float)
    c = np.asarray(contacts, dtype=bool)
    T, S = p.shape[:2]
    if c.shape != (T, S):
        raise ValueError(f"contact_offsets: contacts must be (T, S) = {(T, S)}; got {c.shape}")
    above = np.maximum(p[1:, ..., 1], p[:-1, ..., 1]) - np.asarray(planted, dtype=float)  # (T-1, S, F)
    point = np.argmin(above, axis=2)
    step = np.take_along_axis(np.diff(p, axis=0), point[..., None, None], axis=2)[:, :, 0]  # (T-1, S, 3)
    step[..., 1] = 0.0
    step[~(c[1:] & c[:-1])] = 0.0
    travel = np.concatenate([np.zeros((1, S, 3)), np.cumsum(step, axis=0)])  # (T, S, 3)
    out = np.zeros((T, S, 3))
    for f in range(S):  # loop over feet and their contacts
        runs = mask_to_intervals(c[:, f])
        prev = np.concatenate([[0], runs[:-1, 1]])
        nxt = np.append(runs[1:, 0], T)
        for (s, e), a, b in zip(runs, prev, nxt):
            ref = np.median(travel[s:e, f], axis=0) if anchor == "median" else travel[s, f]
            out[s:e, f] = ref - travel[s:e, f]
            k_in, k_out = min(int(blend_frames), s - a), min(int(blend_frames), b - e)
            if k_in > 0:
                out[s - k_in : s, f] += blend_weights(k_in + 2)[-2:0:-1, None] * out[s, f]
            if k_out > 0:
                out[e : e + k_out, f] += blend_weights(k_out + 2)[1:-1, None] * out[e - 1, f]
    return out


def leg_chains(skeleton: Skeleton, feet: np.ndarray) -> np.ndarray:
    """(2, 3) hip, knee and ankle joints of each leg: the ankle (``feet[:, 0]``), its
    parent (the knee) and that one's parent (the hip joint, which turns the thigh)."""
    ankles = np.asarray(feet, dtype=np.int64).reshape(2, -1)[:, 0]
    knees = skeleton.parents[ankles]
    hips = skeleton.parents[knees]
    if np.any(knees < 0) or np.any(hips < 0) or np.any(skeleton.parents[np.maximum(hips, 0)] < 0):
        raise ValueError(
            f"leg_chains: the ankles {[skeleton.names[a] for a in ankles]} need a knee, a hip and the "
            "hip's parent above them"
        )
    return np.stack([hips, knees, ankles], axis=1)


#: Time (s) over which a pinned foot's displacement is blended in before and out after its
#: contact: a quarter of a walking swing (~0.4 s, docs/gait.md), as the foot lands or lifts off.
FOOT_BLEND_S = 0.1


def pin_feet(
    rotations: np.ndarray,
    root: np.ndarray,
    skeleton: Skeleton,
    feet: np.ndarray,
    planted: np.ndarray,
    contacts: np.ndarray,
    blend_frames: int,
    anchor: str = "median",
) -> np.ndarray:
    """Footskate cleanup of [KSG02] in its simplest form, after :func:`reconstruct_root`:
    each foot in contact is held still (:func:`contact_offsets`: where it stands in most of
    the contact, ``anchor``; blended in and out over ``blend_frames`` at the contact's
    ends) by analytic two-bone IK of its leg
    (:func:`motionvar.core.leg_ik.two_bone_ik`: law of cosines for the knee, the knee's
    swivel plane kept, the foot's global orientation kept). The root is not moved. The
    support foot, which the root already holds, needs (next to) no correction; the other
    foot of a double support, which slides under the paper's cleanup, is pinned.

    Args:
        rotations: (T, J, 4) local rotations; root: (T, 3) root positions.
        feet: (2, F) joints of the left and right foot (ankle first), planted: (2, F)
            their planted heights (as :func:`reconstruct_root`).
        contacts: (T, 2) contact masks of the two feet (the project's contact detection).
        blend_frames, anchor: see :func:`contact_offsets`.

    Returns the new local rotations (T, J, 4); only the legs' hip, knee and ankle joints
    change, and only on frames with a displacement (a copy of ``rotations`` otherwise).
    Vectorised over frames: the loop is over the two legs.
    """
    feet = np.asarray(feet, dtype=np.int64).reshape(2, -1)
    legs = leg_chains(skeleton, feet)
    pos, grot = fk(rotations, root, skeleton.offsets, skeleton.parents, return_rotations=True)
    offset = contact_offsets(pos[:, feet], contacts, planted, blend_frames, anchor)
    out = np.array(rotations, dtype=float, copy=True)
    for f, (hip, knee, ankle) in enumerate(legs):  # loop over the two legs
        t = np.flatnonzero(np.any(offset[:, f] != 0.0, axis=-1))
        if not len(t):
            continue
        # a straight knee bends over the toes
        forward = pos[t, feet[f, 1]] - pos[t, ankle] if feet.shape[1] > 1 else None
        ik = two_bone_ik(
            pos[t, hip],
            pos[t, knee],
            pos[t, ankle],
            grot[t, hip],
            grot[t, knee],
            pos[t, ankle] + offset[t, f],
            fallback_pole=forward,
        )
        new = np.stack(
            [
                qmul(qinv(grot[t, skeleton.parents[hip]]), ik.hip_rotation),
                qmul(qinv(ik.hip_rotation), ik.knee_rotation),
                qmul(qinv(ik.knee_rotation), grot[t, ankle]),  # the foot keeps its orientation
            ],
            axis=1,
        )  # (n, 3, 4)
        old = out[t[:, None], [hip, knee, ankle]]
        out[t[:, None], [hip, knee, ankle]] = np.where(np.sum(new * old, axis=-1, keepdims=True) < 0, -new, new)
    return out
