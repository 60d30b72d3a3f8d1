"""Legs from a footstep plan: root height, foot trajectories and two-bone IK.

Order of construction (each step vectorised over frames, loops over contacts only):

1. :func:`root_height` — the designed height (plan.height_offset above a reference) is
   lowered where a planted foot would be out of reach: each contact imposes a ceiling on
   the root (the hip no farther from the ankle than the leg with the knee at
   ``KNEE_MIN_DEG``) from just before touchdown until the hip passes over the foot; a
   smooth minimum (``SOFTMIN_CM``) joins design and ceilings without kinks.
2. :func:`foot_tracks` — stance: the ankle stays on its footprint while the foot turns from
   the heel-strike angle to flat about the ankle (heel rocker); once the hip has passed over
   the foot, the foot rolls about the toe base whenever the leg would otherwise be
   overstretched (knee straighter than ``KNEE_MIN_DEG``; solved in closed form, capped
   at ``ROLL_MAX_DEG``), and at least along a smooth heel rise from heel-off to the push-off
   angle at toe-off, so the knee flexes in pre-swing (Perry & Burnfield 2010); the toes stay
   flat on the floor. Swing: cubic Hermite curves from the toe-off state (position, velocity, foot
   pitch and its rate) to touchdown, plus a lift whose height makes the knee reach the
   planned peak swing flexion (docs/gait.md: 60-65° in early swing; running 90-130°).
3. :func:`solve_leg_tracks` — analytic two-bone IK (:func:`motionvar.synth.ik.two_bone_ik`)
   puts each ankle on its track exactly; the knee bends towards the foot's heading.

Pinned points: the ankle from touchdown to heel-off, the toe base (``*ToeBase`` joint) from
heel-off to toe-off; both are exact to floating-point precision while reachable.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np
from scipy.ndimage import gaussian_filter1d, minimum_filter1d
from scipy.special import logsumexp

from ..core.quaternions import qinv, qmul, qrot, quat_about_axis
from ..core.skeleton import Skeleton
from .footsteps import SIDES, BodyGeometry, Contact, Plan
from .ik import two_bone_ik
from .signals import minimum_jerk

_X, _Y, _Z = np.eye(3)
KNEE_MIN_DEG = 5.0  # the straightest a loaded knee gets (Perry: ≈ 5° at initial contact and in
# terminal stance; a nearly locked knee is also where its angle is most sensitive to the hip height)
SOFTMIN_CM = 0.4  # smoothness of the root-height minimum
SETTLE_S = 0.12  # the root starts to lower this long before a ceiling binds (lower smooth envelope)
CEILING_RAMP_S = 0.04  # a contact's ceiling fades in / out over this time
ROLL_MAX_DEG = 75.0  # heel rise cap (foot-floor angle at toe-off ≈ 50-65° in walking)
LIFT_RANGE_CM = (1.5, 40.0)  # range of the swing lift
LAND_SPEED_FRAC = 0.2  # horizontal foot speed at touchdown / mean swing speed
LAND_MIN_CM_S = 70.0  # ... but at least this (heel speed at initial contact ≈ 0.4-1 m/s), so that
# short steps (gait initiation, closing step, slow walks) still touch down rather than creep in
LAND_DROP_CM_S = 15.0  # vertical foot speed at touchdown
DORSI_MAX_DEG = 20.0  # swing: ankle dorsiflexion limit (neutral to ≈ 10-20° in swing)
PLANTAR_MAX_DEG = 35.0  # swing: ankle plantarflexion limit (≈ 15-30° after toe-off)
TOE_CLEAR_CM = 1.2  # swing: the toe base stays at least this far above the floor (minimum toe
# clearance in mid-swing is ≈ 1-2 cm in adult walking)
LIMIT_FADE = 0.2  # swing fraction over which the two limits above fade in after toe-off


def leg_reach(geo: BodyGeometry, side: int, knee_deg: np.ndarray | float) -> np.ndarray:
    """Hip-to-ankle distance of a straight-boned leg with the knee flexed by ``knee_deg``."""
    a, b = geo.thigh[side], geo.shin[side]
    return np.sqrt(a**2 + b**2 + 2.0 * a * b * np.cos(np.radians(knee_deg)))


def _yaw_pitch(yaw: np.ndarray, pitch: np.ndarray) -> np.ndarray:
    """Foot rotations: heading ``yaw`` about +y, then ``pitch`` about the foot's x (toes down > 0)."""
    return qmul(quat_about_axis(_Y, yaw), quat_about_axis(_X, pitch))


def _window(f: np.ndarray, on: float, off: float, ramp: float) -> np.ndarray:
    return minimum_jerk((f - on + ramp) / ramp) * (1.0 - minimum_jerk((f - off) / ramp))


def root_height(geo: BodyGeometry, plan: Plan, hips: np.ndarray, extra: np.ndarray | None = None) -> np.ndarray:
    """(T,) root height: the plan's design, kept within reach of the planted feet.

    Args:
        hips: (T, 2, 3) hip-joint offsets from the root (root rotation applied), left first.
        extra: optional (T,) further ceilings on the root (+inf where none).
    """
    f = np.arange(plan.n_frames, dtype=float)
    ramp = CEILING_RAMP_S * plan.fps

    def ceiling(c: Contact, knee_deg: float, frames: np.ndarray | slice, ankle: np.ndarray | None = None) -> np.ndarray:
        i = SIDES.index(c.side)
        ankle = c.ankle if ankle is None else ankle
        horiz = np.linalg.norm(plan.root_xz[frames] + hips[frames, i][..., [0, 2]] - ankle[[0, 2]], axis=-1)
        vert2 = leg_reach(geo, i, knee_deg) ** 2 - horiz**2
        return ankle[1] + np.sqrt(np.maximum(vert2, 0.0)) - hips[frames, i, 1]

    ref = min(float(ceiling(plan.contacts[j], plan.ref_knee_deg, max(plan.contacts[j].start, 0))) for j in plan.ref)
    terms = []
    for c in plan.contacts:
        w = _window(f, c.reach_from, min(c.mid, c.stop - 1), ramp)
        if w.max() > 0:
            terms.append(-(ceiling(c, KNEE_MIN_DEG, slice(None)) + 100.0 * (1.0 - w)) / SOFTMIN_CM)
        if c.roll and c.mid < c.stop - 1:  # rolling: within reach of the ankle at full heel rise
            w = _window(f, c.mid, c.stop - 1, ramp)
            terms.append(
                -(ceiling(c, KNEE_MIN_DEG, slice(None), rolled_ankle(geo, c)) + 100.0 * (1.0 - w)) / SOFTMIN_CM
            )
    if extra is not None:
        terms.append(-np.minimum(extra, ref + 100.0) / SOFTMIN_CM)
    design = -(ref + plan.height_offset) / SOFTMIN_CM
    if terms:
        reach = lower_envelope(-SOFTMIN_CM * logsumexp(np.stack(terms), axis=0), SETTLE_S * plan.fps)
        return -SOFTMIN_CM * np.logaddexp(design, -reach / SOFTMIN_CM)
    return -SOFTMIN_CM * design


def lower_envelope(h: np.ndarray, width: float) -> np.ndarray:
    """A smooth curve that nowhere exceeds ``h``: the minimum over ±``width`` frames, then a
    Gaussian whose support (±width) lies inside that window, so every average is over
    values <= h(t)."""
    w = max(int(round(width)), 1)
    low = minimum_filter1d(h, size=2 * w + 1, mode="nearest")
    return gaussian_filter1d(low, sigma=w / 2.0, mode="nearest", truncate=2.0)


def _yaw_vec(yaw: float, v: np.ndarray) -> np.ndarray:
    """The vector v (3,) turned by ``yaw`` about +y."""
    c, s = np.cos(yaw), np.sin(yaw)
    return np.array([c * v[0] + s * v[2], v[1], c * v[2] - s * v[0]])


def rolled_ankle(geo: BodyGeometry, c: Contact, alpha_deg: float = ROLL_MAX_DEG) -> np.ndarray:
    """(3,) ankle of contact ``c``'s foot turned heel-up by ``alpha_deg`` about its toe base."""
    ox, oy, oz = geo.toe[SIDES.index(c.side)]
    a = np.radians(alpha_deg)
    pitched = np.array([ox, oy * np.cos(a) - oz * np.sin(a), oy * np.sin(a) + oz * np.cos(a)])
    return c.ankle + _yaw_vec(c.yaw, np.array([ox, oy, oz]) - pitched)


def _roll_angle(hip: np.ndarray, toe: np.ndarray, yaw: float, o_toe: np.ndarray, reach: np.ndarray) -> np.ndarray:
    """Heel-rise angle α (T,) >= 0 about the toe base at ``toe`` (3,) that puts the ankle at
    distance ``reach`` (T,) from ``hip`` (T, 3); 0 where the flat foot is already close enough.

    Ankle(α) = toe − R_y(yaw) R_x(α) o_toe; |hip − ankle|² = |G|² + |o|² + 2 G·R_x(α) o with
    G = R_y(yaw)ᵀ (hip − toe), i.e. C cos α + S sin α = K, solved in closed form.
    """
    c, s = np.cos(yaw), np.sin(yaw)
    d = hip - toe
    g = np.stack([c * d[:, 0] - s * d[:, 2], d[:, 1], s * d[:, 0] + c * d[:, 2]], axis=-1)
    ox, oy, oz = o_toe
    cc = g[:, 1] * oy + g[:, 2] * oz
    ss = g[:, 2] * oy - g[:, 1] * oz
    k = 0.5 * (reach**2 - np.sum(g**2, axis=-1) - o_toe @ o_toe) - g[:, 0] * ox
    r = np.hypot(cc, ss)
    alpha = np.arctan2(ss, cc) + np.arccos(np.clip(k / np.maximum(r, 1e-9), -1.0, 1.0))
    return np.where(k >= cc, 0.0, np.clip(alpha, 0.0, np.radians(ROLL_MAX_DEG)))


def _hermite(u: np.ndarray, p0, p1, v0, v1) -> np.ndarray:
    """Cubic Hermite curve at u (T,) between values p0, p1 with end derivatives v0, v1 (per unit u)."""
    u = u.reshape(u.shape + (1,) * np.ndim(p0))
    u2, u3 = u * u, u * u * u
    return (2 * u3 - 3 * u2 + 1) * p0 + (u3 - 2 * u2 + u) * v0 + (-2 * u3 + 3 * u2) * p1 + (u3 - u2) * v1


def _lift_profile(u: np.ndarray) -> np.ndarray:
    """u² (1 − u)⁵ scaled to peak 1 at u = 2/7: early in the swing (the knee flexes most in
    initial swing), with zero height and slope at both ends (no velocity jump at toe-off)."""
    return u**2 * (1.0 - u) ** 5 / ((2 / 7) ** 2 * (5 / 7) ** 5)


def knee_from_distance(geo: BodyGeometry, side: int, dist: np.ndarray) -> np.ndarray:
    """Knee flexion (degrees) that puts the ankle ``dist`` from the hip (clipped to reach)."""
    a, b = geo.thigh[side], geo.shin[side]
    return np.degrees(np.arccos(np.clip((dist**2 - a * a - b * b) / (2 * a * b), -1.0, 1.0)))


def _lift_for_knee(
    path: np.ndarray, u: np.ndarray, hip: np.ndarray, geo: BodyGeometry, side: int, peak_deg: float
) -> float:
    """The smallest swing lift (cm) at which the knee flexes to ``peak_deg`` somewhere in the
    swing (the most flexing lift when none does): all candidate lifts are evaluated at once
    (candidates × frames)."""
    lifts = np.linspace(*LIFT_RANGE_CM, 40)
    ankle = path[None] + (lifts[:, None] * _lift_profile(u)[None])[..., None] * _Y
    knee = knee_from_distance(geo, side, np.linalg.norm(ankle - hip[None], axis=-1)).max(axis=1)
    enough = np.flatnonzero(knee >= peak_deg)
    if not enough.size:
        return float(lifts[np.argmax(knee)])
    i = enough[0]
    if i == 0:
        return float(lifts[0])
    frac = (peak_deg - knee[i - 1]) / max(knee[i] - knee[i - 1], 1e-9)  # linear between candidates
    return float(lifts[i - 1] + np.clip(frac, 0.0, 1.0) * (lifts[i] - lifts[i - 1]))


class _FootTrack:
    """Per-frame state of one foot: ankle (T, 3), pitch, yaw, toe flexion (T,)."""

    def __init__(self, n: int) -> None:
        self.ankle = np.zeros((n, 3))
        self.pitch = np.zeros(n)
        self.yaw = np.zeros(n)
        self.toe = np.zeros(n)
        self.u = np.full(n, np.nan)  # swing fraction, NaN in stance
        self.done = np.zeros(n, dtype=bool)


def _stance(track: _FootTrack, c: Contact, side: int, geo: BodyGeometry, hip: np.ndarray, fps: float) -> None:
    """Pin the foot of contact ``c``; if the heel rise would saturate at ``ROLL_MAX_DEG`` before
    the planned toe-off, the foot leaves the floor just before (``c.stop`` is moved forward)."""
    n = len(track.pitch)
    lo, hi = max(c.start, 0), min(c.stop, n)
    if hi <= lo:
        return
    f = np.arange(lo, hi)
    heel = -np.radians(c.heel_deg) * (1.0 - minimum_jerk((f - c.start) / c.flat_frames))
    ankle = np.broadcast_to(c.ankle, (hi - lo, 3)).copy()
    alpha = np.zeros(hi - lo)
    if c.roll:
        o_toe = geo.toe[side]
        toe = c.ankle + _yaw_vec(c.yaw, o_toe)
        # The heel rises smoothly from heel-off to the push-off angle at toe-off, and earlier or
        # higher wherever the leg would otherwise be overstretched (knee straighter than KNEE_MIN_DEG).
        needed = _roll_angle(hip[f], toe, c.yaw, o_toe, np.full(len(f), leg_reach(geo, side, KNEE_MIN_DEG)))
        # accelerating (fastest at toe-off, where the swing takes the motion over)
        design = np.radians(c.push_off_deg) * np.clip((f - c.roll_from) / max(c.stop - 1 - c.roll_from, 1), 0, 1) ** 2
        alpha = np.where(f >= c.mid, np.maximum(needed, design), 0.0)
        saturated = np.flatnonzero((alpha >= np.radians(ROLL_MAX_DEG) - 1e-9) & (f >= c.roll_from))
        if saturated.size and f[saturated[0]] - lo >= 3:  # toe-off on the last unsaturated frame
            hi = c.stop = int(f[saturated[0]])
            f, heel, ankle, alpha = f[: hi - lo], heel[: hi - lo], ankle[: hi - lo], alpha[: hi - lo]
        rolled = alpha > 0
        rot = _yaw_pitch(np.full(rolled.sum(), c.yaw), alpha[rolled])
        ankle[rolled] = toe - qrot(rot, np.broadcast_to(o_toe, (rolled.sum(), 3)))
    track.ankle[lo:hi] = ankle
    track.pitch[lo:hi] = np.where(alpha > 0, alpha, heel)
    track.yaw[lo:hi] = c.yaw
    track.toe[lo:hi] = -alpha
    track.done[lo:hi] = True


def _swing(
    track: _FootTrack, a: Contact, b: Contact, side: int, geo: BodyGeometry, hip: np.ndarray, fps: float
) -> None:
    """Frames strictly between contact ``a``'s last pinned frame and ``b``'s first."""
    n = len(track.pitch)
    f0, f1 = a.stop - 1, b.start
    lo, hi = max(f0 + 1, 0), min(f1, n)
    if hi <= lo:
        return
    dur = (f1 - f0) / fps
    if 1 <= f0 < n and track.done[f0] and track.done[f0 - 1]:
        p0, v0 = track.ankle[f0], (track.ankle[f0] - track.ankle[f0 - 1]) * fps
        q0, w0 = track.pitch[f0], (track.pitch[f0] - track.pitch[f0 - 1]) * fps
        toe0 = track.toe[f0]
    else:  # a virtual contact outside the plan (runs start and end in the air)
        p0, v0, q0, w0, toe0 = a.ankle, np.zeros(3), 0.0, 0.0, 0.0
    p1 = b.ankle
    step = (p1 - p0) * np.array([1.0, 0.0, 1.0])
    mean_speed = np.linalg.norm(step) / dur
    land_speed = min(max(LAND_SPEED_FRAC * mean_speed, LAND_MIN_CM_S), 0.8 * mean_speed)
    v1 = step / max(np.linalg.norm(step), 1e-9) * land_speed
    v1[1] = -LAND_DROP_CM_S
    u = (np.arange(lo, hi) - f0) / (f1 - f0)
    path = _hermite(u, p0, p1, v0 * dur, v1 * dur)
    lift = a.lift_cm if np.isnan(a.knee_peak_deg) else _lift_for_knee(path, u, hip[lo:hi], geo, side, a.knee_peak_deg)
    path[:, 1] += lift * _lift_profile(u)
    track.ankle[lo:hi] = path
    track.pitch[lo:hi] = _hermite(u, q0, -np.radians(b.heel_deg), w0 * dur, 0.0)
    track.yaw[lo:hi] = a.yaw + (b.yaw - a.yaw) * minimum_jerk(u)
    track.toe[lo:hi] = toe0 * (1.0 - minimum_jerk(u / 0.3))
    track.u[lo:hi] = u
    track.done[lo:hi] = True


def _virtual(c: Contact, step: np.ndarray, frames: int, before: bool) -> Contact:
    """A contact one stride ``step`` before (or after) ``c``, ``frames`` of swing away."""
    if before:
        return Contact(
            side=c.side,
            start=c.start - frames - 2,
            stop=c.start - frames,
            ankle=c.ankle - step,
            yaw=c.yaw,
            knee_peak_deg=c.knee_peak_deg,
            lift_cm=c.lift_cm,
        )
    return Contact(
        side=c.side,
        start=c.stop + frames,
        stop=c.stop + frames + 2,
        ankle=c.ankle + step,
        yaw=c.yaw,
        heel_deg=c.heel_deg,
    )


@dataclass
class FeetTracks:
    """Foot trajectories over frames, left first: ankle targets (T, 2, 3), foot heading and
    pitch (T, 2; radians, pitch > 0 toes down), toe flexion (T, 2), the swing fraction (T, 2;
    NaN in stance) and the contacts as realised (a toe-off may come earlier than planned, see
    :func:`_stance`)."""

    ankle: np.ndarray
    yaw: np.ndarray
    pitch: np.ndarray
    toe: np.ndarray
    swing_u: np.ndarray
    contacts: list[Contact]


def foot_tracks(geo: BodyGeometry, plan: Plan, root_pos: np.ndarray, hips: np.ndarray) -> FeetTracks:
    """Both feet's trajectories from the plan (stance poses first, then the swings between)."""
    n = plan.n_frames
    realised = [replace(c) for c in plan.contacts]
    out = FeetTracks(np.zeros((n, 2, 3)), *(np.zeros((n, 2)) for _ in range(4)), realised)
    for side, name in enumerate(SIDES):
        cs = [c for c in realised if c.side == name]
        hip = root_pos + hips[:, side]
        track = _FootTrack(n)
        for c in cs:
            _stance(track, c, side, geo, hip, plan.fps)
        step = cs[1].ankle - cs[0].ankle if len(cs) > 1 else np.zeros(3)
        swing = cs[1].start - cs[0].stop if len(cs) > 1 else int(0.4 * plan.fps)
        if cs[0].start > 0:
            cs = [_virtual(cs[0], step, max(swing, cs[0].start + 1), before=True)] + cs
        if cs[-1].stop < n:
            cs = cs + [_virtual(cs[-1], step, max(swing, n - cs[-1].stop + 1), before=False)]
        for a, b in zip(cs[:-1], cs[1:]):
            _swing(track, a, b, side, geo, hip, plan.fps)
        if not track.done.all():
            raise RuntimeError(f"foot_tracks: {name} foot has no pose in frames {np.flatnonzero(~track.done)[:5]}...")
        out.ankle[:, side], out.yaw[:, side], out.pitch[:, side] = track.ankle, track.yaw, track.pitch
        out.toe[:, side], out.swing_u[:, side] = track.toe, track.u
    return out


def _swing_pitch(
    geo: BodyGeometry,
    side: int,
    pitch: np.ndarray,
    u: np.ndarray,
    shank: np.ndarray,
    fwd: np.ndarray,
    ankle_y: np.ndarray,
) -> np.ndarray:
    """Swing foot pitch kept (smoothly) between ``DORSI_MAX_DEG`` of dorsiflexion and
    ``PLANTAR_MAX_DEG`` of plantarflexion relative to the shank, and low enough that the toe
    base stays ``TOE_CLEAR_CM`` above the floor; both limits fade in over the first
    ``LIMIT_FADE`` of the swing ``u`` so that the foot leaves the floor without a jump.

    A neutral ankle gives the foot the shank's sagittal tilt θ (ankle behind the knee: θ > 0,
    toes down), so dorsiflexion is θ − pitch."""
    theta = np.arctan2(-np.sum(shank * fwd, axis=-1), -shank[:, 1])
    tau = np.radians(2.0)
    low, high = theta - np.radians(DORSI_MAX_DEG), theta + np.radians(PLANTAR_MAX_DEG)
    limited = -tau * np.logaddexp(-tau * np.logaddexp(pitch / tau, low / tau) / tau, -high / tau)
    fade = minimum_jerk(u / LIMIT_FADE)
    limited = pitch + fade * (limited - pitch)
    oy, oz = geo.toe[side, 1], geo.toe[side, 2]  # toe height = ankle_y + oy cos p − oz sin p
    r, phi = np.hypot(oy, oz), np.arctan2(-oz, oy)
    highest = phi + np.arccos(np.clip((TOE_CLEAR_CM * fade - ankle_y) / r, -1.0, 1.0))
    return np.minimum(limited, highest)


def _target_ceiling(geo: BodyGeometry, root_pos: np.ndarray, hips: np.ndarray, ankles: np.ndarray) -> np.ndarray:
    """(T,) highest root at which both ankle targets are within reach (knee at KNEE_MIN_DEG)."""
    hip = root_pos[:, None] + hips
    horiz = np.linalg.norm((hip - ankles)[..., [0, 2]], axis=-1)
    reach = np.stack([leg_reach(geo, i, KNEE_MIN_DEG) for i in range(2)])
    return np.min(ankles[..., 1] + np.sqrt(np.maximum(reach**2 - horiz**2, 0.0)) - hips[..., 1], axis=1)


def legs_along(
    geo: BodyGeometry, plan: Plan, root_xz: np.ndarray, hips: np.ndarray, passes: int = 5
) -> tuple[np.ndarray, FeetTracks]:
    """Root positions (T, 3) and foot tracks for ``plan``.

    The swing tracks depend on the root height and the height on where the feet must be:
    after a first pass, every frame whose ankle target is out of reach adds a ceiling on the
    root (smoothed like the contacts' ceilings), and the tracks are rebuilt, up to ``passes``
    times.
    """
    extra = None
    for _ in range(passes):
        h = root_height(geo, plan, hips, extra)
        root_pos = np.stack([root_xz[:, 0], h, root_xz[:, 1]], axis=-1)
        feet = foot_tracks(geo, plan, root_pos, hips)
        limit = _target_ceiling(geo, root_pos, hips, feet.ankle)
        if np.all(h <= limit + 1e-6):
            break
        limit = np.where(h > limit + 1e-6, limit - 0.2, np.inf)
        extra = limit if extra is None else np.minimum(extra, limit)
    return root_pos, feet


def solve_leg_tracks(
    sk: Skeleton, geo: BodyGeometry, rotations: np.ndarray, root_pos: np.ndarray, feet: FeetTracks
) -> np.ndarray:
    """Pose both legs in place (hip, knee, ankle, toe local rotations) so that the ankles
    follow ``feet.ankle``; the knee bends towards the foot's heading, the foot takes the
    tracked heading and pitch (swing pitch limited by :func:`_swing_pitch`). Returns the
    ankle positions reached (T, 2, 3), equal to the targets wherever they are in reach."""
    root_rot = rotations[:, 0]
    reached = np.zeros_like(feet.ankle)
    for side, (hj, pre) in enumerate((("LHipJoint", "Left"), ("RHipJoint", "Right"))):
        j_hj, j_up, j_knee, j_ankle, j_toe = (
            sk.index(x) for x in (hj, pre + "UpLeg", pre + "Leg", pre + "Foot", pre + "ToeBase")
        )
        g_hj = qmul(root_rot, rotations[:, j_hj])
        p_hip = root_pos + qrot(root_rot, np.broadcast_to(sk.offsets[j_hj], root_pos.shape))
        p_hip = p_hip + qrot(g_hj, np.broadcast_to(sk.offsets[j_up], root_pos.shape))
        yaw = feet.yaw[:, side]
        fwd = np.stack([np.sin(yaw), np.zeros_like(yaw), np.cos(yaw)], axis=-1)
        q_up, q_knee, reached[:, side] = two_bone_ik(
            p_hip,
            feet.ankle[:, side],
            g_hj,
            sk.offsets[j_knee],
            sk.offsets[j_ankle],
            _X,
            fwd,
        )
        rotations[:, j_up], rotations[:, j_knee] = q_up, q_knee
        g_up = qmul(g_hj, q_up)
        shank = reached[:, side] - (p_hip + qrot(g_up, np.broadcast_to(sk.offsets[j_knee], root_pos.shape)))
        pitch = feet.pitch[:, side]
        u = feet.swing_u[:, side]
        swing = ~np.isnan(u)
        pitch = np.where(
            swing, _swing_pitch(geo, side, pitch, np.nan_to_num(u), shank, fwd, feet.ankle[:, side, 1]), pitch
        )
        rotations[:, j_ankle] = qmul(qinv(qmul(g_up, q_knee)), _yaw_pitch(yaw, pitch))
        rotations[:, j_toe] = quat_about_axis(_X, feet.toe[:, side])
    return reached
