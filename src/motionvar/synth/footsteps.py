"""Footstep plans: where and when each foot is planted, and the root's path between them.

A plan is built first, in the *body frame* of the clip's start (root above the origin,
facing +z, left +x, floor y = 0); :mod:`motionvar.synth.legs` then poses the legs so that
every planted foot stays exactly on its footprint. Times are snapped to frames: a contact
is the frame range [start, stop) during which the foot is pinned (its ankle from heel
strike to heel-off, its toe base from heel-off to toe-off); the swing frames lie strictly
between two contacts of the same foot.

Timing facts (docs/gait.md; Perry & Burnfield 2010, Novacheck 1998):
- walking: stride time = stride / speed, stance ≈ 60 % of the cycle (the caller's
  ``stance_fraction``), double support = stance − 50 %; at heel strike the front ankle is
  half way between the hip and a point one foot length (ankle to toe base) further, i.e. the
  hip sits midway between the front heel and the trailing forefoot;
- running: stance 30-40 % (two flight phases), the foot lands ``LAND_AHEAD`` of the contact
  sweep ahead of the hip;
- side-stepping: lead foot out, then trail foot in, double support between the two.
Gait initiation and termination use a quintic speed ramp of ``RAMP_CYCLES`` stride times
(the body starts moving before the first toe-off, as in anticipatory postural
adjustments, and comes to rest shortly after the closing step).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from scipy.interpolate import PchipInterpolator

from ..core.skeleton import Skeleton
from .gait_params import RunParams, SidestepParams, WalkParams
from .signals import minimum_jerk

SIDES = ("left", "right")
RAMP_CYCLES = 0.8  # speed ramp duration at gait initiation / termination, in stride times
LAND_AHEAD = 0.3  # running: fraction of the stance sweep (speed × contact time) ahead of the hip
TURN_GRID = 4001  # samples of the numerically integrated curved path


@dataclass(frozen=True)
class BodyGeometry:
    """Leg geometry of a skeleton (CMU rig), left first: hip-joint offsets from the root (2, 3),
    toe-base offsets from the ankle (2, 3), thigh and shin lengths (2,)."""

    hip: np.ndarray
    toe: np.ndarray
    thigh: np.ndarray
    shin: np.ndarray

    @classmethod
    def from_skeleton(cls, sk: Skeleton) -> "BodyGeometry":
        off = sk.offsets
        hip = np.stack(
            [off[sk.index(h)] + off[sk.index(u)] for h, u in (("LHipJoint", "LeftUpLeg"), ("RHipJoint", "RightUpLeg"))]
        )
        toe = np.stack([off[sk.index(f"{s}ToeBase")] for s in ("Left", "Right")])
        thigh = np.array([np.linalg.norm(off[sk.index(f"{s}Leg")]) for s in ("Left", "Right")])
        shin = np.array([np.linalg.norm(off[sk.index(f"{s}Foot")]) for s in ("Left", "Right")])
        return cls(hip=hip, toe=toe, thigh=thigh, shin=shin)

    @property
    def hip_forward(self) -> float:
        """How far the hip joints sit in front of the root (cm)."""
        return float(self.hip[:, 2].mean())

    @property
    def foot_length(self) -> float:
        """Horizontal ankle-to-toe-base distance (cm)."""
        return float(np.hypot(self.toe[:, 0], self.toe[:, 2]).mean())

    @property
    def ankle_height(self) -> np.ndarray:
        """(2,) ankle height above the floor with the foot flat (toe base on the floor)."""
        return -self.toe[:, 1]


@dataclass
class Contact:
    """One planted foot.

    Attributes:
        side: "left" or "right".
        start, stop: pinned frames [start, stop) of the plan.
        ankle: (3,) ankle position with the foot flat (toe base on the floor).
        yaw: the foot's heading (radians about +y from +z).
        heel_deg: foot-floor angle at touchdown (heel rocker about the ankle), 0: flat landing.
        flat_frames: frames from touchdown to foot-flat.
        mid: frame at which the hip passes over the foot; the reach constraint on the root
            height holds until then (the whole contact for flat-footed steps).
        roll: whether the heel may rise (roll over the toe base) from ``roll_from`` on.
        roll_from: first frame of terminal stance (heel-off), not before ``mid``: from here the
            heel rises smoothly to ``push_off_deg`` at toe-off.
        push_off_deg: foot-floor angle at toe-off (heel rise about the toe base).
        reach_from: frame from which the root height must let the leg reach this footprint
            (the ceiling fades in over the frames just before).
        knee_peak_deg: peak knee flexion aimed for in the swing that *leaves* this contact;
            NaN: a fixed foot lift of ``lift_cm`` instead.
        lift_cm: foot lift of that swing when ``knee_peak_deg`` is NaN.
    """

    side: str
    start: int
    stop: int
    ankle: np.ndarray
    yaw: float
    heel_deg: float = 0.0
    flat_frames: int = 1
    mid: int = 0
    roll: bool = False
    roll_from: int = 0
    push_off_deg: float = 0.0
    reach_from: int = 0
    knee_peak_deg: float = float("nan")
    lift_cm: float = 5.0


@dataclass
class Plan:
    """Everything the leg and upper-body builders need, over the plan's frames.

    ``root_xz`` (T, 2) is the root's floor position (x, z); ``heading`` (T,) the travel
    heading of the pelvis; ``phase`` (T,) the left leg's gait phase in cycles (0 at a left
    heel strike / landing, 0.5 at a right one); ``envelope`` (T,) 0 when standing, 1 in
    steady gait; ``height_offset`` (T,) the designed root height relative to the reference
    height (the lowest reach of the ``ref`` contacts with knees at ``ref_knee_deg``);
    ``crop`` the frames [start, stop) that make the clip; ``segments`` (name, start, stop)
    in plan frames; ``truth`` the plan's ground truth (stride, speed, ...).
    """

    fps: float
    contacts: list[Contact]
    root_xz: np.ndarray
    heading: np.ndarray
    phase: np.ndarray
    envelope: np.ndarray
    height_offset: np.ndarray
    ref: list[int]
    ref_knee_deg: float
    segments: list[tuple[str, int, int]]
    crop: tuple[int, int]
    truth: dict = field(default_factory=dict)

    @property
    def n_frames(self) -> int:
        return len(self.heading)


def heading_vectors(psi: np.ndarray | float) -> tuple[np.ndarray, np.ndarray]:
    """Forward (…, 2) and left (…, 2) floor vectors (x, z) of headings ``psi`` (radians)."""
    psi = np.asarray(psi, dtype=float)
    fwd = np.stack([np.sin(psi), np.cos(psi)], axis=-1)
    left = np.stack([np.cos(psi), -np.sin(psi)], axis=-1)
    return fwd, left


@dataclass(frozen=True)
class Path:
    """The root's floor path by arc length s: heading turns by ``turn`` radians between
    ``s0`` and ``s1`` (quintic in s), straight before and after; starts at the origin facing +z."""

    turn: float = 0.0
    s0: float = 0.0
    s1: float = 1.0

    def heading(self, s: np.ndarray) -> np.ndarray:
        return self.turn * minimum_jerk((np.asarray(s, dtype=float) - self.s0) / (self.s1 - self.s0))

    def position(self, s: np.ndarray) -> np.ndarray:
        """(…, 2) floor position (x, z) at arc length s (any sign)."""
        s = np.asarray(s, dtype=float)
        if self.turn == 0.0:
            return s[..., None] * np.array([0.0, 1.0])
        lo, hi = min(float(s.min()), 0.0), max(float(s.max()), 0.0)
        grid = np.linspace(lo, hi, TURN_GRID)
        fwd, _ = heading_vectors(self.heading(grid))
        step = np.diff(grid)[:, None] * 0.5 * (fwd[1:] + fwd[:-1])
        cum = np.concatenate([np.zeros((1, 2)), np.cumsum(step, axis=0)])
        cum -= np.array([np.interp(0.0, grid, cum[:, k]) for k in range(2)])
        return np.stack([np.interp(s, grid, cum[:, k]) for k in range(2)], axis=-1)


def ramp_progress(t: np.ndarray, speed: float, t_a: float, t_b: float, tau: float) -> np.ndarray:
    """Distance travelled at time t: speed ramps up over [t_a, t_a + tau] and down over
    [t_b, t_b + tau] with quintic smoothsteps (closed-form integral, t_b >= t_a + tau)."""

    def integral(x: np.ndarray) -> np.ndarray:  # ∫0^x smoothstep, x in units of tau
        xc = np.clip(x, 0.0, 1.0)
        return np.where(x > 1.0, 0.5 + (x - 1.0), xc**6 - 3.0 * xc**5 + 2.5 * xc**4)

    return speed * tau * (integral((t - t_a) / tau) - integral((t - t_b) / tau))


def _frame(t: float, fps: float) -> int:
    return int(round(t * fps))


def _envelope(t: np.ndarray, on0: float, on1: float, off0: float, off1: float) -> np.ndarray:
    """0 before on0, rising to 1 at on1, falling from off0 to 0 at off1 (quintic)."""
    return minimum_jerk((t - on0) / (on1 - on0)) - minimum_jerk((t - off0) / (off1 - off0))


def _foot_on_path(path: Path, s: float, lateral: float, geo: BodyGeometry, side: int) -> tuple[np.ndarray, float]:
    """Flat-foot ankle position (3,) and yaw of a footprint at arc length s, ``lateral`` cm to
    the left of the path, under the hip joints' forward offset."""
    psi = float(path.heading(np.array(s)))
    fwd, left = heading_vectors(psi)
    xz = path.position(np.array([s]))[0] + lateral * left + geo.hip_forward * fwd
    return np.array([xz[0], geo.ankle_height[side], xz[1]]), psi


def _passes_over(progress: np.ndarray, s: float, lo: int) -> int:
    """First frame >= lo at which the root's path coordinate reaches s (last frame if never)."""
    idx = np.flatnonzero(progress[lo:] >= s - 1e-9)
    return lo + int(idx[0]) if idx.size else len(progress) - 1


def _strides(contacts: list[Contact], full: list[int]) -> list[float]:
    """Distances between successive same-foot footprints, for the contact indices ``full``
    (each paired with the same foot's previous contact)."""
    dist = []
    for i in full:
        c = contacts[i]
        prev = [j for j in range(i) if contacts[j].side == c.side]
        if prev:
            dist.append(float(np.linalg.norm(c.ankle[[0, 2]] - contacts[prev[-1]].ankle[[0, 2]])))
    return dist


def _stride_truth(contacts: list[Contact], full: list[int]) -> float:
    """Mean of :func:`_strides` (NaN when there is none)."""
    dist = _strides(contacts, full)
    return float(np.mean(dist)) if dist else float("nan")


def _side_index(side: str) -> int:
    return SIDES.index(side)


@dataclass(frozen=True)
class _WalkTiming:
    """Event times of a walk plan in seconds (module docstring): heel strikes ``hs`` 1 .. K+1
    and the toe-offs ``lift`` before them; the speed ramps up over [t_a, t_a + tau] and down
    from ``t_b`` to rest at ``t_stop``; ``t`` holds the times of the plan's ``n`` frames."""

    half_stride: float
    t_stride: float
    tau: float
    t_a: float
    t_b: float
    t_stop: float
    hs: np.ndarray
    lift: np.ndarray
    n: int
    t: np.ndarray


def _walk_timing(geo: BodyGeometry, p: WalkParams) -> _WalkTiming:
    """Heel strikes, toe-offs, speed ramp and frame count of a walk: at heel strike the front
    ankle is half way between the hip and a point one foot length further (module docstring)."""
    m, fps = p.manner, p.fps
    L, v, K = p.stride_length_cm / 2.0, p.speed_cm_s, p.n_steps
    t_stride = p.stride_length_cm / v
    t_step, t_swing, tau = t_stride / 2.0, (1.0 - m.stance_fraction) * t_stride, RAMP_CYCLES * t_stride
    d_hs = 0.5 * (L - geo.foot_length)  # front ankle ahead of the hip joints at heel strike
    t_a = p.stand_start_s
    hs = t_a + tau / 2.0 + (L - d_hs) / v + t_step * np.arange(K + 1)  # heel strikes 1 .. K+1
    lift = hs - t_swing
    hs[:K] += p.offsets("strike_offsets_s")
    lift[:K] += p.offsets("toe_off_offsets_s")
    t_b = t_a + K * t_step  # deceleration starts; the root then stops exactly at s = K L
    t_stop = t_b + tau
    n = _frame(max(t_stop, hs[-1]) + p.stand_end_s, fps) + 1
    return _WalkTiming(L, t_stride, tau, t_a, t_b, t_stop, hs, lift, n, np.arange(n) / fps)


def _footfall_offsets(p: WalkParams) -> np.ndarray:
    """(n_steps,) the heel strikes' footprint offsets along the path, 0 for the first and the
    last (gait initiation and termination keep their nominal steps, so that the root, which
    follows the offsets, never moves backwards while it speeds up or slows down)."""
    e = p.offsets("footfall_offsets_cm").copy()
    e[[0, -1]] = 0.0
    return e


def _progress_offset(p: WalkParams, tm: _WalkTiming) -> np.ndarray:
    """(T,) the root's progress ahead of its steady ramp: the footprints' offsets along the path
    (:func:`_footfall_offsets`) at their nominal heel strikes, 0 while standing, joined by a C1
    monotone cubic (PCHIP)."""
    e = _footfall_offsets(p)
    if not np.any(e):
        return np.zeros(tm.n)
    K = p.n_steps
    knots = np.concatenate([[tm.t_a], tm.hs[:K] - p.offsets("strike_offsets_s"), [tm.t_stop]])
    values = np.concatenate([[0.0], e, [0.0]])
    t = np.clip(tm.t, tm.t_a, tm.t_stop)
    return PchipInterpolator(knots, values)(t)


def _closing_laterals(geo: BodyGeometry, p: WalkParams, a: int) -> tuple[float, float]:
    """Lateral offsets (cm left of the path) of the last heel strike's footprint and of the
    closing footprint beside it at standing width (hip-joint spacing); ``a`` is the first foot."""
    K = p.n_steps
    last = a if K % 2 else 1 - a  # the foot of heel strike K; the other one closes beside it
    lat_last = (0.5 if last == 0 else -0.5) * p.step_width_cm
    lat_close = lat_last - (geo.hip[last, 0] - geo.hip[1 - last, 0])  # standing width beside it
    return lat_last, lat_close


def _walk_sway(geo: BodyGeometry, p: WalkParams, tm: _WalkTiming, env: np.ndarray, phase_a: np.ndarray) -> np.ndarray:
    """(T,) lateral root offset: side-to-side sway over the stance foot in steady gait, then a
    settle to the middle of the closing stance."""
    m, K = p.manner, p.n_steps
    a = _side_index(p.first_foot)
    side_a = 1.0 if a == 0 else -1.0
    lat_last, lat_close = _closing_laterals(geo, p, a)
    settle = 0.5 * (lat_last + lat_close) * minimum_jerk((tm.t - tm.hs[K - 1]) / (tm.t_stop - tm.hs[K - 1]))
    return env * m.sway_cm * side_a * np.cos(2 * np.pi * (phase_a - 0.3)) + settle


def _walk_contacts(
    geo: BodyGeometry, p: WalkParams, tm: _WalkTiming, path: Path, progress: np.ndarray
) -> list[Contact]:
    """The walk's contacts in time order: the two standing feet, heel strikes 1 .. K on
    alternate sides of the path, and the closing step beside the last footprint."""
    m, fps, n, K, L = p.manner, p.fps, tm.n, p.n_steps, tm.half_stride
    a = _side_index(p.first_foot)
    _, lat_close = _closing_laterals(geo, p, a)
    flat = max(_frame(0.1 * tm.t_stride, fps), 1)
    roll_len = (m.stance_fraction - 0.3) * tm.t_stride  # terminal stance + pre-swing
    contacts: list[Contact] = []

    def add(side: int, start: int, stop: int, s: float, lateral: float, heel: float, peak: float, roll: bool) -> None:
        ankle, yaw = _foot_on_path(path, s, lateral, geo, side)
        mid = _passes_over(progress, s, start) if roll else n
        contacts.append(
            Contact(
                side=SIDES[side],
                start=start,
                stop=stop,
                ankle=ankle,
                yaw=yaw,
                heel_deg=heel,
                flat_frames=flat,
                mid=mid,
                roll=roll,
                roll_from=max(mid, stop - 1 - _frame(roll_len, fps)),
                push_off_deg=m.push_off_deg,
                reach_from=start,
                knee_peak_deg=peak,
            )
        )

    lateral = lambda side: (0.5 if side == 0 else -0.5) * p.step_width_cm  # noqa: E731
    # along the path: the footprint's offset, and a quarter of the asymmetry forward for the
    # left foot, back for the right (left steps longer by step_asymmetry_cm)
    e = _footfall_offsets(p)
    along = lambda k, side: e[k - 1] + (0.25 if side == 0 else -0.25) * p.step_asymmetry_cm  # noqa: E731
    for side, k_lift in ((a, 0), (1 - a, 1)):  # standing feet, under the hip joints
        add(side, 0, _frame(tm.lift[k_lift], fps) + 1, 0.0, geo.hip[side, 0], 0.0, 0.85 * m.knee_peak_deg, True)
    for k in range(1, K + 2):  # heel strikes 1 .. K, then the closing step
        side = a if k % 2 else 1 - a
        closing = k == K + 1
        stop = _frame(tm.lift[k + 1], fps) + 1 if k + 2 <= K + 1 else n
        peak = 0.75 * m.knee_peak_deg if k + 2 == K + 1 else m.knee_peak_deg
        s_k, lat = (K * L, lat_close) if closing else (k * L + along(k, side), lateral(side))
        heel = (0.5 if closing else 1.0) * m.heel_strike_deg
        add(side, _frame(tm.hs[k - 1], fps), stop, s_k, lat, heel, peak, stop < n)
    return contacts


def _walk_segments(contacts: list[Contact], tm: _WalkTiming, K: int, fps: float) -> list[tuple[str, int, int]]:
    """Primitives of a walk: ``walk_start``, one ``walk_<side>Stance`` per step between
    successive heel strikes (named by the foot of the following contact), ``walk_end``."""
    hs_f = [_frame(x, fps) for x in tm.hs]
    segments = [("walk_start", 0, hs_f[0])]
    segments += [(f"walk_{contacts[k + 1].side}Stance", hs_f[k - 1], hs_f[k]) for k in range(1, K + 1)]
    segments.append(("walk_end", hs_f[K], tm.n))
    return segments


def plan_walk(geo: BodyGeometry, p: WalkParams) -> Plan:
    """Stand, ``n_steps`` heel strikes (first with ``first_foot``), a closing step beside the
    last footprint, stand. Footprints lie ``step_width/2`` either side of the path at arc
    lengths k × stride/2; the standing feet sit under the hip joints."""
    m, fps, K = p.manner, p.fps, p.n_steps
    tm = _walk_timing(geo, p)
    t, L, n = tm.t, tm.half_stride, tm.n
    progress = ramp_progress(t, p.speed_cm_s, tm.t_a, tm.t_b, tm.tau) + _progress_offset(p, tm)
    path = Path(turn=np.radians(p.turn_deg), s0=0.5 * L, s1=(K - 0.5) * L)
    heading = path.heading(progress)
    a = _side_index(p.first_foot)
    phase_a = (t - tm.hs[0]) / tm.t_stride
    env = _envelope(t, tm.t_a, tm.hs[0], tm.hs[K - 1], tm.t_stop)
    _, left = heading_vectors(heading)
    root_xz = path.position(progress) + _walk_sway(geo, p, tm, env, phase_a)[:, None] * left
    # Lowest at heel strike (double support), highest at mid-stance.
    height = -env * (0.5 + m.bob_cm * (1.0 + np.cos(4.0 * np.pi * phase_a)))
    contacts = _walk_contacts(geo, p, tm, path, progress)
    strides = _strides(contacts, list(range(4, K + 2)))
    truth = {
        "stride_length_cm": float(np.mean(strides)),
        "footfall_strides_cm": ";".join(f"{x:.4f}" for x in strides),
        "speed_cm_s": p.speed_cm_s,
        "step_width_cm": p.step_width_cm,
        "turn_deg": p.turn_deg,
        "cadence_steps_min": 120.0 / tm.t_stride,
        "stance_fraction": m.stance_fraction,
        "n_steps": K,
    }
    return Plan(
        fps=fps,
        contacts=contacts,
        root_xz=root_xz,
        heading=heading,
        phase=phase_a - (0.0 if a == 0 else 0.5),
        envelope=env,
        height_offset=height,
        ref=[0, 1],
        ref_knee_deg=6.0,
        segments=_walk_segments(contacts, tm, K, fps),
        crop=(0, n),
        truth=truth,
    )


GRAVITY_CM_S2 = 981.0
RUN_LAND_KNEE_DEG = 12.0  # straightest landing knee used to set the running height; with the smoothing
# of the root height the knee lands at ≈ 15-25° and flexes to ≈ 40-45° at mid-stance (Novacheck 1998)


def _run_height(t: np.ndarray, t_land0: float, t_step: float, t_c: float, t_fl: float) -> np.ndarray:
    """(T,) root height offset of a run: a spring-mass stance dip of ``t_c`` s after each
    landing joined to a ballistic flight of ``t_fl`` s with equal take-off and landing speed."""
    v_up = 0.5 * GRAVITY_CM_S2 * t_fl
    dip = v_up * t_c / np.pi
    tau = np.mod(t - t_land0, t_step)
    return np.where(
        tau < t_c,
        -dip * np.sin(np.pi * np.clip(tau / t_c, 0, 1)),
        v_up * (tau - t_c) - 0.5 * GRAVITY_CM_S2 * (tau - t_c) ** 2,
    )


def _run_contacts(
    geo: BodyGeometry,
    p: RunParams,
    path: Path,
    progress: np.ndarray,
    landings: tuple[np.ndarray, np.ndarray, np.ndarray],
    t_c: float,
    n: int,
) -> list[Contact]:
    """One contact per landing (``landings``: indices k, times, path arc lengths), feet
    alternating from ``first_foot`` at landing 1, each lasting ``t_c`` s and rolling over the
    toe base from mid-stance on."""
    m, fps = p.manner, p.fps
    a = _side_index(p.first_foot)  # the foot of landing 1
    flat = max(_frame(0.2 * t_c, fps), 1)
    contacts = []
    for k, tl, s in zip(*landings):
        side = a if (k - 1) % 2 == 0 else 1 - a
        ankle, yaw = _foot_on_path(path, float(s), (0.5 if side == 0 else -0.5) * p.step_width_cm, geo, side)
        start, stop = _frame(tl, fps), min(_frame(tl + t_c, fps) + 1, n)
        mid = _passes_over(progress, float(s), start)
        contacts.append(
            Contact(
                side=SIDES[side],
                start=start,
                stop=stop,
                ankle=ankle,
                yaw=yaw,
                heel_deg=m.heel_strike_deg,
                flat_frames=flat,
                mid=mid,
                roll=True,
                roll_from=mid,
                push_off_deg=m.push_off_deg,
                reach_from=start,
                knee_peak_deg=m.knee_peak_deg,
            )
        )
    return contacts


def plan_run(geo: BodyGeometry, p: RunParams) -> Plan:
    """A steady run: landings every half stride, stance ``stance_fraction`` of the cycle,
    ballistic flight between; the clip runs from mid-flight before the first complete
    stance primitive to mid-stance after the last."""
    m, fps = p.manner, p.fps
    v, N = p.speed_cm_s, p.n_steps
    t_stride = p.stride_length_cm / v
    t_step, t_c = t_stride / 2.0, m.stance_fraction * t_stride
    t_fl = t_step - t_c
    d_land = LAND_AHEAD * v * t_c
    ks = np.arange(-2, N + 3)  # landings; k = 1 .. N+1 bound the clip's primitives
    t_land = t_fl + (ks + 2) * t_step
    n = _frame(t_land[-1] + t_c, fps) + 1
    t = np.arange(n) / fps
    progress = v * t
    s_land = v * t_land + d_land
    path = Path(turn=np.radians(p.turn_deg), s0=float(s_land[3]), s1=float(s_land[N + 3]))
    heading = path.heading(progress)
    a = _side_index(p.first_foot)  # the foot of landing 1
    phase_a = (t - t_land[3]) / t_stride
    _, left = heading_vectors(heading)
    side_a = 1.0 if a == 0 else -1.0
    root_xz = path.position(progress) + (m.sway_cm * side_a * np.cos(2 * np.pi * (phase_a - 0.2)))[:, None] * left
    contacts = _run_contacts(geo, p, path, progress, (ks, t_land, s_land), t_c, n)
    land_f = [c.start for c in contacts]
    crop = (land_f[3] - _frame(0.5 * t_fl, fps), land_f[N + 3] + _frame(0.5 * t_c, fps))
    segments = [(f"run_{contacts[i].side}Stance", land_f[i], land_f[i + 1]) for i in range(3, N + 3)]
    in_clip = [i for i, c in enumerate(contacts) if crop[0] <= c.start < crop[1]]
    truth = {
        "stride_length_cm": _stride_truth(contacts, in_clip[2:]),
        "speed_cm_s": v,
        "step_width_cm": p.step_width_cm,
        "turn_deg": p.turn_deg,
        "cadence_steps_min": 120.0 / t_stride,
        "stance_fraction": m.stance_fraction,
        "flight_s": t_fl,
        "n_steps": N,
    }
    return Plan(
        fps=fps,
        contacts=contacts,
        root_xz=root_xz,
        heading=heading,
        phase=phase_a - (0.0 if a == 0 else 0.5),
        envelope=np.ones(n),
        height_offset=_run_height(t, t_land[0], t_step, t_c, t_fl),
        ref=list(range(len(contacts))),
        ref_knee_deg=RUN_LAND_KNEE_DEG,
        segments=segments,
        crop=crop,
        truth=truth,
    )


def plan_sidestep(geo: BodyGeometry, p: SidestepParams) -> Plan:
    """Stand, ``n_cycles`` times (lead foot out by ``step_cm``, trail foot in to
    ``stance_width``), stand; the body keeps facing +z while it travels sideways."""
    m, fps = p.manner, p.fps
    sign = 1.0 if p.direction == "left" else -1.0
    lead = _side_index(p.direction)
    t_step = 60.0 / p.cadence_steps_min
    t_sw = p.swing_fraction * t_step
    t_ds, t_cyc, K = t_step - t_sw, 2.0 * t_step, p.n_cycles
    v, tau = p.step_cm / t_cyc, RAMP_CYCLES * t_cyc
    t_a = p.stand_start_s
    lead_land = t_a + tau / 2.0 + t_cyc / 2.0 - t_ds / 2.0 + t_cyc * np.arange(K)
    lead_lift = lead_land - t_sw
    trail_lift = lead_land + t_ds
    trail_land = trail_lift + t_sw
    t_b = t_a + K * t_cyc
    n = _frame(max(t_b + tau, trail_land[-1]) + p.stand_end_s, fps) + 1
    t = np.arange(n) / fps
    progress = ramp_progress(t, v, t_a, t_b, tau)
    root_xz = np.stack([sign * progress, np.zeros(n)], axis=-1)
    env = _envelope(t, t_a, lead_land[0], trail_land[-1] - t_sw, t_b + tau)
    left_land = lead_land if lead == 0 else trail_land
    phase = (t - left_land[0]) / t_cyc

    contacts = []
    for side, offset, lands, lifts in ((lead, 0.5, lead_land, lead_lift), (1 - lead, -0.5, trail_land, trail_lift)):
        starts = [0] + [_frame(x, fps) for x in lands]
        stops = [_frame(x, fps) + 1 for x in lifts] + [n]
        for j, (start, stop) in enumerate(zip(starts, stops)):
            lateral = sign * (offset * p.stance_width_cm + j * p.step_cm)
            contacts.append(
                Contact(
                    side=SIDES[side],
                    start=start,
                    stop=stop,
                    ankle=np.array([lateral, geo.ankle_height[side], geo.hip_forward]),
                    yaw=0.0,
                    mid=n,
                    reach_from=start,
                    lift_cm=m.lift_cm,
                )
            )
    contacts.sort(key=lambda c: c.start)
    trail_f = [_frame(x, fps) for x in trail_land]
    segments = [("sidestep", trail_f[j], trail_f[j + 1]) for j in range(K - 1)]
    truth = {
        "stride_length_cm": _stride_truth(contacts, list(range(len(contacts)))),
        "speed_cm_s": v,
        "step_width_cm": p.stance_width_cm,
        "turn_deg": 0.0,
        "cadence_steps_min": p.cadence_steps_min,
        "n_steps": 2 * K,
    }
    return Plan(
        fps=fps,
        contacts=contacts,
        root_xz=root_xz,
        heading=np.zeros(n),
        phase=phase,
        envelope=env,
        height_offset=-1.5 * env,
        ref=[0, 1],
        ref_knee_deg=6.0,
        segments=segments,
        crop=(0, n),
        truth=truth,
    )
