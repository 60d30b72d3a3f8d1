"""Two-hand picking and placing while standing with planted feet (Du 2022, Sec. 3.5, 4.6).

A clip is one elementary action made of two primitives (Du 2022, Table 3.1):
``pick_reach`` (standing start until the hands stop at the object) and ``pick_retrieve``
(grasp, then back to standing with the object held in front of the body), or
``place_reach`` (from standing with the object held in front until the hands stop at the
target) and ``place_retrieve`` (release, then back to relaxed standing).

Targets live in the *feet frame*: origin on the floor midway between the (planted) ankles,
z forward along the bisector of the feet, x to the subject's left, y up; cm. The object's
centre is the target; the wrists (``*Hand`` joints) grip it on either side, ``width/2``
along x. Regions (reference body; scaled by the subject's ``height_scale``), after the
three picking clusters of Du 2022 Fig. 3.11 (bottom / forward / top):

=========  ===========  ============  ===========
region     x (cm)       y (cm)        z (cm)
=========  ===========  ============  ===========
low        -12 … 12     40 … 60       25 … 38
forward    -18 … 18     70 … 105      30 … 48
high       -12 … 12     115 … 135     25 … 38
dense      -15 … 15     45 … 135      25 … 35   (regular grid, Du 2022 Fig. 4.11)
=========  ===========  ============  ===========

The lowest targets need the wrists 40 cm above the floor: with the CMU rig's arm length
(shoulder to wrist ≈ 46 cm) and flat feet, lower ones are out of reach.

Body (all parameters written down here, none tuned to a paper's result):
- Lowering for a target follows one scalar s in [0, 1]: trunk flexion grows by
  ``s · (110° − 40° q)`` and knee flexion by ``s · (40° + 80° q)``, where the personal lifting
  strategy q ∈ [0, 1] runs from stoop (trunk, q = 0) to squat (knees, q = 1); people
  differ in it and most lift in between (Burgess-Limerick & Abernethy 1997). A target too
  low for the personal strategy makes the subject squat more (q raised in steps of 0.25). Trunk
  flexion is shared by the pelvis (hip flexion, 50 %) and the lumbar and thoracic spine
  (lumbopelvic rhythm, Esola et al. 1996).
- The hips move back as the body bends so that the centre of mass of legs, trunk and head
  stays over the feet (Winter 2009); the root height follows from the knees
  (:func:`~motionvar.synth.stance.root_height`), so the feet stay planted.
- s is the least lowering that brings both shoulders within the reach distance of an
  elbow flexed ``subject.elbow_flex_deg + 15°`` (± 4° per clip) of their grips; if even
  full lowering cannot, the nearest posture is used when the target is within 99.5 % of
  the arm's length, and a ValueError names the target otherwise.
- Timing: minimum-jerk profiles (Flash & Hogan 1985). The reach lasts
  ``0.55 s + 0.9 s/m × hand travel + 0.4 s × s`` (longer for longer and deeper reaches, in
  the spirit of Fitts' law), times a personal tempo (0.85–1.15) and a per-clip
  ``duration_scale`` (0.8–1.25); the trunk leads the hands by 10 % of the movement.
- Corrective sub-movements: on a share :data:`CORRECTION_SHARE` of clips the hands reach
  the grips in two minimum-jerk sub-movements (Meyer et al. 1988; Novak, Miller & Houk
  2002). The primary falls short by a drawn share :data:`PRIMARY_ERROR` of the hands'
  displacement (primary movements tend to undershoot, Elliott et al. 2001; overshoots are
  left out: the reach posture leaves the arm too little spare extension to go past low
  targets); a smaller secondary one, starting before the primary ends
  (:data:`CORRECTION_ONSET`, :data:`CORRECTION_DURATION`: fractions of the primary's
  duration), takes the hands exactly to the grips. The shortfall lies along the hands'
  displacement in the feet frame (trunk and arm together) and is added to the path below.
  Both sub-movements share the hands' part of the reach time (movement time is that of
  both, Meyer et al. 1988), so the hands stop at the grips at the same time with or
  without a correction; on the other clips one movement lands on the grips. The retrieve
  is a single movement.
- The hands travel on a path fixed to the midpoint of the shoulders, so they move with the
  trunk (as hanging arms do), bowing forward by up to 6 cm on the way; the head turns down
  towards the target.
- Habits persist: torso lean, head pitch, shoulder lift (clavicle elevation) and elbow
  flexion (relaxed arms and reach distance) come from the subject.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..core.kinematics import fk
from ..core.motion import Motion
from ..core.skeleton import Skeleton
from ..io.intervals import format_named, format_ranges
from .signals import minimum_jerk, subject_rng, submovements
from .stance import (
    SIDES,
    Feet,
    Rig,
    StanceHabit,
    arm_reach,
    body_com,
    elbow_pole,
    euler_q,
    hanging_hand_offsets,
    heading_quat,
    identity_rotations,
    plant_feet,
    root_height,
    solve_arm,
    solve_legs,
    stance_habit,
    to_world,
)
from .subjects import Subject

REGIONS: dict[str, tuple[tuple[float, float], tuple[float, float], tuple[float, float]]] = {
    "low": ((-12.0, 12.0), (40.0, 60.0), (25.0, 38.0)),
    "forward": ((-18.0, 18.0), (70.0, 105.0), (30.0, 48.0)),
    "high": ((-12.0, 12.0), (115.0, 135.0), (25.0, 38.0)),
    "dense": ((-15.0, 15.0), (45.0, 135.0), (25.0, 35.0)),
}
"""Target boxes (x, y, z ranges in cm, feet frame) for a reference body (height scale 1)."""
_GRID = np.linspace(0.0, 1.0, 101)  # lowering values searched for the reach posture

# Corrective sub-movements of the reach (module docstring). The literature gives their
# presence and direction, not these numbers: each value is the authors' choice.
CORRECTION_SHARE = 0.5
"""Share of reaches with a secondary sub-movement: corrections follow many but not all aimed
movements ("frequently", Novak, Miller & Houk 2002; Meyer et al. 1988)."""
PRIMARY_ERROR = (0.05, 0.15)
"""Range of the primary sub-movement's shortfall in a corrected reach, as a share of the
hands' displacement: the primary covers most of the distance and a secondary one follows
when it misses the target (Meyer et al. 1988), primary movements tending to undershoot
(Elliott, Helsen & Chua 2001); a near miss (under 5 %) is a reach without a correction."""
CORRECTION_ONSET = (0.7, 0.9)
"""Range of the secondary's onset as a fraction of the primary's duration: it starts before
the primary ends (overlapping sub-movements, Novak, Miller & Houk 2002)."""
CORRECTION_DURATION = (0.2, 0.4)
"""Range of the secondary's duration as a fraction of the primary's: a smaller, shorter
movement with the same bell-shaped speed profile (Novak, Miller & Houk 2002)."""


@dataclass(frozen=True)
class ReachParams:
    """Per-clip settings of :func:`generate_pick` / :func:`generate_place`; None draws a value.

    Attributes:
        region: low | forward | high (uniform in the region's box) or dense (a random node
            of :func:`target_grid`); ignored when ``target`` is given.
        target: object centre (x, y, z) in the feet frame, cm (module docstring); scaled by
            nothing — give it for this subject.
        grid_spacing_cm: node spacing of the dense grid.
        object_width_cm: distance between the two grips, 20–40 cm when drawn.
        duration_scale: per-clip speed factor of the movements, 0.8–1.25 when drawn.
        hold_s: grasp (pick) or release (place) time at the target, 0.2–0.5 s when drawn.
        lead_in_s / settle_s: still standing before / after the action, 0.1–0.4 / 0.1–0.3 s.
        correction: whether the reach has a corrective sub-movement; None draws it, True on a
            share :data:`CORRECTION_SHARE` of clips (the data generator does so with
            ``SynthSpec.captured_variation``); False (the default) draws nothing for it.
        primary_amplitude: the primary's share of the hands' displacement in a corrected
            reach, 1 minus a shortfall uniform in :data:`PRIMARY_ERROR` when drawn.
        correction_onset / correction_duration: the secondary's onset and duration as
            fractions of the primary's duration, uniform in :data:`CORRECTION_ONSET` /
            :data:`CORRECTION_DURATION` when drawn. The three are unused without a correction.
        start_xz: floor position (x, z) of the feet frame's origin; heading_deg: facing
            direction about +y from +z. Drawn in ±300 cm and ±180° when None.
        fps: frames per second.
    """

    region: str = "forward"
    target: tuple[float, float, float] | None = None
    grid_spacing_cm: float = 10.0
    object_width_cm: float | None = None
    duration_scale: float | None = None
    hold_s: float | None = None
    lead_in_s: float | None = None
    settle_s: float | None = None
    start_xz: tuple[float, float] | None = None
    heading_deg: float | None = None
    fps: float = 120.0
    correction: bool | None = False
    primary_amplitude: float | None = None
    correction_onset: float | None = None
    correction_duration: float | None = None

    def validate(self) -> None:
        if self.region not in REGIONS:
            raise ValueError(f"ReachParams.region must be one of {sorted(REGIONS)}; got {self.region!r}")
        if self.target is not None and (np.shape(self.target) != (3,) or not np.all(np.isfinite(self.target))):
            raise ValueError(f"ReachParams.target must be three finite numbers (x, y, z) in cm; got {self.target}")
        if self.target is not None and not (0.0 < self.target[1] < 250.0 and self.target[2] > 0.0):
            raise ValueError(f"ReachParams.target must be above the floor and in front of the feet; got {self.target}")
        if not (np.isfinite(self.grid_spacing_cm) and 1.0 <= self.grid_spacing_cm <= 100.0):
            raise ValueError(f"ReachParams.grid_spacing_cm must be in [1, 100]; got {self.grid_spacing_cm}")
        checks = (
            ("object_width_cm", self.object_width_cm, 5.0, 60.0),
            ("duration_scale", self.duration_scale, 0.3, 3.0),
            ("hold_s", self.hold_s, 0.0, 5.0),
            ("lead_in_s", self.lead_in_s, 0.0, 5.0),
            ("settle_s", self.settle_s, 0.0, 5.0),
            ("primary_amplitude", self.primary_amplitude, 0.5, 1.0),
            ("correction_onset", self.correction_onset, 0.1, 1.0),
            ("correction_duration", self.correction_duration, 0.1, 1.0),
        )
        for name, value, lo, hi in checks:
            if value is not None and not (np.isfinite(value) and lo <= value <= hi):
                raise ValueError(f"ReachParams.{name} must be in [{lo}, {hi}]; got {value}")
        if self.start_xz is not None and (np.shape(self.start_xz) != (2,) or not np.all(np.isfinite(self.start_xz))):
            raise ValueError(f"ReachParams.start_xz must be two finite numbers; got {self.start_xz}")
        if self.heading_deg is not None and not np.isfinite(self.heading_deg):
            raise ValueError(f"ReachParams.heading_deg must be finite; got {self.heading_deg}")
        if not (np.isfinite(self.fps) and 10.0 <= self.fps <= 1000.0):
            raise ValueError(f"ReachParams.fps must be in [10, 1000]; got {self.fps}")
        if self.correction is not None and not isinstance(self.correction, (bool, np.bool_)):
            raise ValueError(f"ReachParams.correction must be True, False or None; got {self.correction!r}")


@dataclass(frozen=True)
class ReachStyle:
    """A subject's personal way of picking and placing (module docstring)."""

    squat_share: float  # lifting strategy: 0 stoop ... 1 squat
    tempo: float  # personal duration factor
    carry_arm_flex_deg: float  # upper arm forward of vertical while holding the object, 10-30°
    carry_elbow_deg: float  # elbow flexion while holding the object, 80-100°


def reach_style(subject: Subject) -> ReachStyle:
    """The subject's :class:`ReachStyle`: same subject, same style."""
    r = subject_rng(subject, "reach")
    return ReachStyle(
        squat_share=float(r.uniform(0.0, 1.0)),
        tempo=float(r.uniform(0.85, 1.15)),
        carry_arm_flex_deg=float(r.uniform(10.0, 30.0)),
        carry_elbow_deg=float(r.uniform(80.0, 100.0)),
    )


def target_grid(region: str = "dense", spacing_cm: float = 10.0, height_scale: float = 1.0) -> np.ndarray:
    """(N, 3) nodes of a regular grid with ``spacing_cm`` over a region's box (feet frame),
    the box scaled by ``height_scale``; nodes are centred in the box."""
    if region not in REGIONS:
        raise ValueError(f"region must be one of {sorted(REGIONS)}; got {region!r}")
    if not (np.isfinite(spacing_cm) and spacing_cm > 0):
        raise ValueError(f"spacing_cm must be positive; got {spacing_cm}")
    axes = []
    for lo, hi in REGIONS[region]:
        lo, hi = lo * height_scale, hi * height_scale
        k = int(np.floor((hi - lo) / spacing_cm + 1e-9))
        mid = 0.5 * (lo + hi)
        axes.append(mid + spacing_cm * (np.arange(k + 1) - k / 2.0))
    gx, gy, gz = np.meshgrid(*axes, indexing="ij")
    return np.stack([gx.ravel(), gy.ravel(), gz.ravel()], axis=-1)


def draw_target(params: ReachParams, subject: Subject, rng: np.random.Generator) -> np.ndarray:
    """The clip's target: ``params.target``, a uniform point of the region's box, or a
    random node of the dense grid."""
    if params.target is not None:
        return np.asarray(params.target, dtype=float)
    if params.region == "dense":
        grid = target_grid("dense", params.grid_spacing_cm, subject.height_scale)
        return grid[rng.integers(len(grid))]
    box = np.array(REGIONS[params.region]) * subject.height_scale
    return rng.uniform(box[:, 0], box[:, 1])


@dataclass(frozen=True)
class _Body:
    """Lowering-dependent body of one clip: a function of the lowering s in [0, 1] and the
    lifting strategy q in [0, 1] (stoop ... squat), both per row."""

    skeleton: Skeleton
    feet: Feet
    lean: float  # habitual trunk flexion, rad
    knee_lock: float  # deg
    com_ahead: float  # cm
    yaw: float  # trunk turn towards the target at s = 1, rad
    side_shift: float  # root shift towards the target at s = 1, cm
    shoulder_lift: float  # rad
    head_pitch: float  # rad

    @staticmethod
    def trunk_range(q: np.ndarray) -> np.ndarray:
        """Added trunk flexion (rad) at s = 1: 110° for a stoop, 70° for a squat."""
        return np.radians(110.0 - 40.0 * q)

    @staticmethod
    def knee_range(q: np.ndarray) -> np.ndarray:
        """Added knee flexion (deg) at s = 1: 40° for a stoop, 120° for a squat."""
        return 40.0 + 80.0 * q

    def pose(
        self, s: np.ndarray, q: np.ndarray, back: np.ndarray, gaze: np.ndarray | float = 0.0
    ) -> tuple[np.ndarray, np.ndarray]:
        """Root positions (K, 3) and rotations (K, J, 4) with legs, trunk and head posed and
        the arms at rest, for lowering ``s``, strategy ``q`` and hip back-shift ``back`` (cm)."""
        sk = self.skeleton
        rig = Rig(sk)
        s, q, back = np.broadcast_arrays(s, q, back)
        rot = identity_rotations(s.size, sk)
        phi = self.lean + s * self.trunk_range(q)
        yaw = s * self.yaw
        rot[:, 0] = euler_q(flex=0.5 * phi, axial=0.4 * yaw)
        for name, share in (("LowerBack", 0.2), ("Spine", 0.17), ("Spine1", 0.13)):
            rot[:, rig[name]] = euler_q(flex=share * phi, axial=share * 1.2 * yaw)
        head = euler_q(flex=0.5 * (self.head_pitch + np.broadcast_to(gaze, s.shape)))
        rot[:, rig["Neck1"]] = head
        rot[:, rig["Head"]] = head
        for sign, side in ((1.0, "left"), (-1.0, "right")):
            rot[:, rig.side(side, "Shoulder")] = euler_q(lateral=sign * self.shoulder_lift)
        xz = np.stack([s * self.side_shift, self.com_ahead - back], axis=-1)
        y = root_height(sk, xz, rot[:, 0], self.feet, self.knee_lock + s * self.knee_range(q))
        root = np.stack([xz[:, 0], y, xz[:, 1]], axis=-1)
        solve_legs(sk, rot, root, self.feet)
        return root, rot

    def balance(self, s: np.ndarray, q: np.ndarray, iterations: int = 3) -> tuple[np.ndarray, np.ndarray]:
        """Hip back-shift (K,) keeping the centre of mass of legs, trunk and head at its
        standing position over the feet (fixed-point iteration; ``s[0]`` must be 0), and the
        joint positions (K, J, 3) of the posture with that back-shift."""
        sk = self.skeleton
        back = np.zeros(np.broadcast_shapes(np.shape(s), np.shape(q)))
        for it in range(iterations):
            pos = fk(*self.pose(s, q, back)[::-1], sk.offsets, sk.parents)
            if it + 1 < iterations:
                com = body_com(pos, sk, arms=False)[:, 2]
                back = back + (com - com[0]) / 0.85  # the root carries ~85 % of that mass
        return back, pos


@dataclass(frozen=True)
class _Correction:
    """A corrected reach's sub-movements (module docstring): the primary's share of the
    hands' displacement, the secondary's onset and duration as fractions of the primary's
    duration."""

    primary: float
    onset: float
    duration: float


def _given_or_drawn(value: float | None, bounds: tuple[float, float], rng: np.random.Generator) -> float:
    """``value``, or a uniform draw in ``bounds`` when it is None."""
    return float(rng.uniform(*bounds)) if value is None else float(value)


def _draw_correction(params: ReachParams, rng: np.random.Generator) -> _Correction | None:
    """The clip's :class:`_Correction`, or None for a single movement; each value from
    ``params`` or drawn from ``rng`` in a fixed order, whether used or not. With
    ``params.correction`` False nothing is drawn, so the stream is that of a generator
    without corrections."""
    if params.correction is not None and not params.correction:
        return None
    corrected = bool(rng.random() < CORRECTION_SHARE) if params.correction is None else True
    given = params.primary_amplitude
    primary = 1.0 - float(rng.uniform(*PRIMARY_ERROR)) if given is None else float(given)
    onset = _given_or_drawn(params.correction_onset, CORRECTION_ONSET, rng)
    duration = _given_or_drawn(params.correction_duration, CORRECTION_DURATION, rng)
    return _Correction(primary, onset, duration) if corrected else None


@dataclass(frozen=True)
class _ClipDraws:
    """Per-clip values of a reach clip, from :class:`ReachParams` or drawn (module docstring):
    placement, target and object width, timing, lifting strategy ``q``, preferred reach
    elbow (deg), carrying arm posture (rad), the planted feet and the reach's corrective
    sub-movement (None: none)."""

    heading: float
    start_xz: tuple[float, float]
    target: np.ndarray
    width: float
    dscale: float
    hold: float
    lead: float
    settle: float
    q: float
    elbow_pref: float
    carry_flex: float
    carry_elbow: float
    feet: Feet
    correction: _Correction | None


def _draw_clip(
    subject: Subject, params: ReachParams, habit: StanceHabit, style: ReachStyle, rng: np.random.Generator
) -> _ClipDraws:
    """The clip's :class:`_ClipDraws`, drawn from ``rng`` in a fixed order where
    ``params`` leaves a value None; the personal habits vary a little per clip. The
    correction is drawn last, so the other values do not depend on it."""
    heading = np.radians(params.heading_deg if params.heading_deg is not None else rng.uniform(-180.0, 180.0))
    start_xz = params.start_xz if params.start_xz is not None else tuple(rng.uniform(-300.0, 300.0, 2))
    target = draw_target(params, subject, rng)
    width = params.object_width_cm if params.object_width_cm is not None else rng.uniform(20.0, 40.0)
    dscale = params.duration_scale if params.duration_scale is not None else rng.uniform(0.8, 1.25)
    hold = params.hold_s if params.hold_s is not None else rng.uniform(0.2, 0.5)
    lead = params.lead_in_s if params.lead_in_s is not None else rng.uniform(0.1, 0.4)
    settle = params.settle_s if params.settle_s is not None else rng.uniform(0.1, 0.3)
    q = float(np.clip(style.squat_share + rng.normal(0.0, 0.1), 0.0, 1.0))
    elbow_pref = subject.elbow_flex_deg + 15.0 + rng.normal(0.0, 4.0)
    carry_flex = np.radians(style.carry_arm_flex_deg + rng.normal(0.0, 3.0))
    carry_elbow = np.radians(style.carry_elbow_deg + rng.normal(0.0, 4.0))
    feet = plant_feet(subject.skeleton, habit.width_cm + rng.normal(0.0, 1.0), habit.toe_out_deg + rng.normal(0.0, 1.5))
    correction = _draw_correction(params, rng)
    return _ClipDraws(
        heading,
        start_xz,
        target,
        width,
        dscale,
        hold,
        lead,
        settle,
        q,
        elbow_pref,
        carry_flex,
        carry_elbow,
        feet,
        correction,
    )


def _make_body(subject: Subject, habit: StanceHabit, feet: Feet, target: np.ndarray) -> _Body:
    """The clip's :class:`_Body`: the subject's habits, trunk turned and root shifted
    towards the target's side."""
    return _Body(
        skeleton=subject.skeleton,
        feet=feet,
        lean=np.radians(subject.torso_lean_deg),
        knee_lock=habit.lock_knee_deg,
        com_ahead=habit.com_ahead_cm,
        yaw=0.6 * np.arctan2(target[0], target[2]),
        side_shift=0.25 * target[0],
        shoulder_lift=np.radians(subject.shoulder_lift_deg),
        head_pitch=np.radians(subject.head_pitch_deg),
    )


def _reach_posture(
    subject: Subject, body: _Body, rig: Rig, grips: np.ndarray, target: np.ndarray, q: float, elbow_pref: float
) -> tuple[float, int, np.ndarray, np.ndarray]:
    """Least lowering that brings both shoulders within the preferred reach of their grips,
    with the personal strategy ``q``, or squatting more when that cannot get there
    (module docstring); ValueError when the target is out of reach.

    Returns the strategy used, the lowering's index into ``_GRID``, and the balanced hip
    back-shifts (G,) and joint positions (G, J, 3) of that strategy over ``_GRID``."""
    sk = body.skeleton
    d_pref = min(arm_reach(sk, side, elbow_pref) for side in SIDES)
    d_max = min(arm_reach(sk, side, 0.0) for side in SIDES)
    strategies = np.array([q] + [x for x in (0.25, 0.5, 0.75, 1.0) if x > q])
    s_g, q_g = (a.ravel() for a in np.meshgrid(_GRID, strategies))
    back_g, pos_g = body.balance(s_g, q_g)
    shoulders = pos_g[:, [rig.side(side, "Arm") for side in SIDES]]
    dist = np.max(np.linalg.norm(shoulders - grips, axis=-1), axis=-1)
    ok = np.flatnonzero(dist <= d_pref)  # rows ordered by strategy, then lowering
    best = int(ok[0]) if ok.size else int(np.argmin(dist))
    if dist[best] > 0.995 * d_max:
        raise ValueError(
            f"ReachParams.target {np.round(target, 1).tolist()} is out of reach for subject {subject.subject_id} "
            f"(grips {dist[best]:.1f} cm from the shoulders at best, arm {d_max:.1f} cm)"
        )
    rows = slice(best - best % _GRID.size, best - best % _GRID.size + _GRID.size)  # the chosen strategy
    return q_g[best], best % _GRID.size, back_g[rows], pos_g[rows]


def _gaze_track(body: _Body, rig: Rig, pos_g: np.ndarray, target: np.ndarray, q: float) -> np.ndarray:
    """(G,) head pitch over ``_GRID`` turning the gaze down towards the target: 70 % of the
    neck-to-target angle not already covered by the trunk, kept in [-30°, 45°] (rad)."""
    necks = pos_g[:, rig["Neck1"]]
    gaze_g = np.arctan2(necks[:, 1] - target[1], np.maximum(target[2] - necks[:, 2], 1.0))
    trunk_g = body.lean + _GRID * body.trunk_range(q)
    return np.clip(0.7 * (gaze_g - trunk_g), np.radians(-30.0), np.radians(45.0))


def _hand_waypoints(
    subject: Subject,
    habit: StanceHabit,
    rig: Rig,
    shoulders: np.ndarray,
    grips: np.ndarray,
    target: np.ndarray,
    d: _ClipDraws,
    kind: str,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Hand positions (2, 3) at the start, just after the hold (grasped, or released 3 cm
    out and 2 cm up) and at the end of the clip: relaxed hanging arms (habitual elbow and
    abduction) and the object carried in front (``carry_flex``, ``carry_elbow``), in the
    order of ``kind``; ``shoulders`` (2, 3) are those of the standing posture."""
    sk = subject.skeleton
    relaxed = shoulders + hanging_hand_offsets(sk, subject.elbow_flex_deg, habit.arm_abduction_deg)
    sagittal = np.array([0.0, -np.cos(d.carry_flex), np.sin(d.carry_flex)])
    fore = np.array([0.0, -np.cos(d.carry_flex + d.carry_elbow), np.sin(d.carry_flex + d.carry_elbow)])
    ua, fa = (np.mean([np.linalg.norm(sk.offsets[rig.side(side, p)]) for side in SIDES]) for p in ("ForeArm", "Hand"))
    carry = shoulders.mean(axis=0) + ua * sagittal + fa * fore + grips - target
    release = grips + np.array([[3.0, 2.0, 0.0], [-3.0, 2.0, 0.0]])
    start_hands, end_hands = (relaxed, carry) if kind == "pick" else (carry, relaxed)
    after_hold = grips if kind == "pick" else release
    return start_hands, after_hold, end_hands


def _hand_state(hands: np.ndarray, shoulders: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Key hand state: the hands' centre (3,) relative to the shoulders' midpoint, and each
    hand's offset (2, 3) from that centre."""
    c = hands.mean(axis=0)
    return c - shoulders.mean(axis=0), hands - c


@dataclass(frozen=True)
class _Timeline:
    """Timing of a reach clip (module docstring): reach and retrieve durations (s), the time
    the hands reach the grips, the frame count, and the minimum-jerk profiles (T,) of the
    body and hands going (``m_*``, ``m_hold`` through the hold) and coming back (``u_*``);
    ``m_miss`` is the primary's miss (a share of the hands' displacement) not yet corrected,
    0 without a correction."""

    t_reach: float
    t_back: float
    t_b: float
    n: int
    m_body: np.ndarray
    m_hand: np.ndarray
    m_miss: np.ndarray
    m_hold: np.ndarray
    u_hand: np.ndarray
    u_body: np.ndarray


def _timeline(
    style: ReachStyle, d: _ClipDraws, s_end: float, travel: float, travel_back: float, fps: float
) -> _Timeline:
    """Lead-in, reach, hold, retrieve, settle: each movement lasts 0.55 s + 0.9 s/m × hand
    travel (m) + 0.4 s × lowering, times tempo and duration scale, kept in [0.5, 2.5] s; the
    trunk leads the hands by 10 % of the movement. A corrected reach's two sub-movements
    share the hands' part of it (:func:`~motionvar.synth.signals.submovements`)."""
    t_reach = float(np.clip(style.tempo * d.dscale * (0.55 + 0.9 * travel + 0.4 * s_end), 0.5, 2.5))
    t_back = float(np.clip(style.tempo * d.dscale * (0.55 + 0.9 * travel_back + 0.4 * s_end), 0.5, 2.5))
    hold = d.hold
    t_a = d.lead
    t_b = t_a + t_reach
    t_c = t_b + hold
    t_d = t_c + t_back
    n = int(np.ceil((t_d + d.settle) * fps)) + 1
    t = np.arange(n) / fps
    tau_hand = (t - t_a - 0.1 * t_reach) / (0.9 * t_reach)
    c = d.correction
    if c is None:
        m_hand, m_miss = minimum_jerk(tau_hand), np.zeros(n)
    else:
        m_hand, second = submovements(tau_hand, c.onset, c.duration)
        m_miss = (c.primary - 1.0) * (m_hand - second)
    return _Timeline(
        t_reach=t_reach,
        t_back=t_back,
        t_b=t_b,
        n=n,
        m_body=minimum_jerk((t - t_a) / (0.9 * t_reach)),
        m_hand=m_hand,
        m_miss=m_miss,
        m_hold=minimum_jerk((t - t_b) / hold) if hold > 0 else (t >= t_b).astype(float),
        u_hand=minimum_jerk((t - t_c) / (0.9 * t_back)),
        u_body=minimum_jerk((t - t_c - 0.1 * t_back) / (0.9 * t_back)),
    )


def _hand_path(
    sh_mid: np.ndarray, keys: list[tuple[np.ndarray, np.ndarray]], tl: _Timeline, reach: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """Hands' centre (T, 3) in world coordinates and offsets (T, 2, 3) from it, blended
    between the key states ``keys`` (start, grips, after the hold, end) relative to the
    shoulders' midpoint ``sh_mid`` (T, 3), bowing forward by up to 6 cm on the way, plus the
    primary's uncorrected miss ``tl.m_miss`` × ``reach`` (3,), the centre's displacement from
    the start to the grips."""
    k0, k1, k1b, k2 = keys
    m_hand, m_hold, u_hand = tl.m_hand, tl.m_hold, tl.u_hand
    centre = k0[0] + np.outer(m_hand, k1[0] - k0[0]) + np.outer(m_hold, k1b[0] - k1[0])
    centre = centre + np.outer(u_hand, k2[0] - k1b[0]) + np.outer(tl.m_miss, reach)
    bow = np.array([0.0, 0.0, 1.0])
    for (a, b), m in (((k0, k1), m_hand), ((k1b, k2), u_hand)):
        amp = min(0.1 * np.linalg.norm(b[0] - a[0]), 6.0)
        centre += np.outer(amp * np.sin(np.pi * m), bow)
    spacing = k0[1] + m_hand[:, None, None] * (k1[1] - k0[1]) + m_hold[:, None, None] * (k1b[1] - k1[1])
    spacing = spacing + u_hand[:, None, None] * (k2[1] - k1b[1])
    return sh_mid + centre, spacing


def _reach_truth(params: ReachParams, kind: str, d: _ClipDraws, tl: _Timeline, s_end: float) -> dict:
    """Ground truth of a reach clip (see :func:`generate_pick`)."""
    n = tl.n
    frame_b = int(np.ceil(tl.t_b * float(params.fps) - 1e-9))  # first frame with the hands at the grips
    return {
        "variant": params.region if params.target is None else "custom",
        "target_x": float(d.target[0]),
        "target_y": float(d.target[1]),
        "target_z": float(d.target[2]),
        "segments": format_named([(f"{kind}_reach", 0, frame_b + 1), (f"{kind}_retrieve", frame_b + 1, n)]),
        "left_contacts": format_ranges([(0, n)]),
        "right_contacts": format_ranges([(0, n)]),
        "idle_postures": "",
        "object_width_cm": float(d.width),
        "reach_duration_s": tl.t_reach,
        "retrieve_duration_s": tl.t_back,
        "lowering": float(s_end),
        "reach_submovements": 1 if d.correction is None else 2,
        "heading_deg": float(np.degrees(d.heading)),
        "start_x": float(d.start_xz[0]),
        "start_z": float(d.start_xz[1]),
    }


def _generate(subject: Subject, params: ReachParams, rng: np.random.Generator, kind: str) -> tuple[Motion, dict]:
    """One ``kind`` ("pick" or "place") clip: see :func:`generate_pick` / :func:`generate_place`."""
    params.validate()
    sk = subject.skeleton
    rig = Rig(sk)
    habit = stance_habit(subject)
    style = reach_style(subject)
    fps = float(params.fps)
    d = _draw_clip(subject, params, habit, style, rng)
    target = d.target
    grips = target + np.array([[d.width / 2.0, 0.0, 0.0], [-d.width / 2.0, 0.0, 0.0]])
    body = _make_body(subject, habit, d.feet, target)
    q, k, back_g, pos_g = _reach_posture(subject, body, rig, grips, target, d.q, d.elbow_pref)
    s_end = _GRID[k]
    gaze_g = _gaze_track(body, rig, pos_g, target, q)

    # Key hand states: object centre relative to the shoulders' midpoint, grip spacing.
    arms = [rig.side(side, "Arm") for side in SIDES]
    start_hands, after_hold, end_hands = _hand_waypoints(subject, habit, rig, pos_g[0, arms], grips, target, d, kind)
    keys = [
        _hand_state(h, pos_g[row, arms]) for h, row in ((start_hands, 0), (grips, k), (after_hold, k), (end_hands, 0))
    ]
    reach = grips.mean(0) - start_hands.mean(0)
    travel = np.linalg.norm(reach) / 100.0
    travel_back = np.linalg.norm(end_hands.mean(0) - after_hold.mean(0)) / 100.0
    tl = _timeline(style, d, s_end, travel, travel_back, fps)

    s = s_end * (tl.m_body - tl.u_body)
    attention = tl.m_body - tl.u_body
    back = np.interp(s, _GRID, back_g)
    root, rot = body.pose(s, q, back, gaze=attention * np.interp(s, _GRID, gaze_g))
    frames = fk(rot, root, sk.offsets, sk.parents, return_rotations=True)
    centre_w, spacing = _hand_path(frames[0][:, arms].mean(axis=1), keys, tl, reach)
    turn = heading_quat(s * body.yaw)
    for i, side in enumerate(SIDES):
        solve_arm(sk, rot, root, side, centre_w + spacing[:, i], elbow_pole(turn, side), frames=frames)

    root_w, rot_w = to_world(root, rot, d.heading, d.start_xz)
    return Motion(skeleton=sk, root_pos=root_w, rotations=rot_w, fps=fps), _reach_truth(params, kind, d, tl, s_end)


def generate_pick(subject: Subject, params: ReachParams, rng: np.random.Generator) -> tuple[Motion, dict]:
    """Two-hand pick: reach from relaxed standing to the object at the target, grasp, and
    come back to standing holding it in front of the body.

    Returns the Motion and its truth: variant (the region, or "custom" for a given
    target), target_x/y/z (object centre in the feet frame: x left, y up from the floor,
    z forward, origin between the ankles; cm), segments ``pick_reach`` (until the first
    frame with the hands at the object) and ``pick_retrieve``, foot contacts (both feet
    throughout), object width, durations, the lowering s and ``reach_submovements`` (2 with
    a corrective sub-movement, else 1).
    """
    return _generate(subject, params, rng, "pick")


def generate_place(subject: Subject, params: ReachParams, rng: np.random.Generator) -> tuple[Motion, dict]:
    """Two-hand place: from standing with the object held in front, put it down at the
    target, release it and come back to relaxed standing. Truth as in :func:`generate_pick`
    with segments ``place_reach`` and ``place_retrieve``."""
    return _generate(subject, params, rng, "place")
