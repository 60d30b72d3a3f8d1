"""Idle standing: balance shifts between resting postures plus small posture variations
(Egges et al. 2004, Sec. 5 and 6), with the feet planted.

Structure (Egges 2004 Sec. 5.1, 5.4): the body rests in one of three categories —
weight on the left foot, on the right foot, or on both — for a dwell time, then shifts its
balance to another posture in a transition of about 0.5–1.5 s. The next category is drawn
from the subject's ``idle_foot_preference`` (the category transition graph of Sec. 5.3,
Fig. 3, here with P(c ⇒ s) = preference of s, so the preference is the share of time in
each category; c ⇒ c is a re-adjustment within the category); each rest is a slightly
different posture of its category (the posture sets Q_c). On top run continuous small
variations (Sec. 6): postural sway, breathing, small head and arm movements.

Biomechanics (docs/gait.md, "Quiet standing"; ranges of the personal traits in brackets):
- Loaded leg straight (knee ``lock_knee_deg``, 1–5°), the root height follows from it;
  the pelvis drops towards the unloaded side by ``pelvis_drop_deg`` (2–5°, "a few
  degrees"), which bends the unloaded knee; the trunk bends back over the pelvis so the
  head stays above it.
- The centre of mass moves over the loaded foot by ``com_shift_frac`` (35–75 %) of half
  the stance width (Duarte & Zatsiorsky 1999: prolonged standing is a sequence of such
  shifts of the centre of pressure between the feet).
- Postural sway: centre-of-mass displacement with RMS ``subject.sway_cm`` (resultant of
  antero-posterior and medio-lateral; 0.3–1 cm, Winter 2009), low-pass noise with a corner
  of 0.15–0.5 Hz, so its power lies below 1 Hz; applied as an inverted pendulum about the
  ankles (the body tilts by displacement / root height).
- Breathing at ``subject.breath_rate_hz`` (12–20 /min), shoulders rising by 0.3–0.9 cm
  and the chest extending by about a degree per breath.
- Stance (ankle spacing, toe-out, straight-knee flexion, COM ahead of the ankles, arm
  abduction): :class:`~motionvar.synth.stance.StanceHabit`, shared with the reach clips.

Personal traits beyond :class:`Subject` (:class:`IdleStyle`) come from
:func:`~motionvar.synth.signals.subject_rng`: they persist across the subject's clips, so
that subjects can be told apart (Egges 2004 Sec. 5.6, 8). Within a subject, clips differ by
the random sequence of rests, small per-rest posture changes and ±1 cm / ±1.5° of stance.
"""

from __future__ import annotations

import zlib
from dataclasses import dataclass, replace

import numpy as np

from ..core.kinematics import fk
from ..core.motion import Motion
from ..core.quaternions import qmul, qrot
from ..core.skeleton import Skeleton
from ..io.intervals import format_named, format_ranges
from .signals import colored_noise, minimum_jerk, subject_rng
from .stance import (
    Feet,
    Rig,
    StanceHabit,
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

CATEGORIES = ("left", "right", "both")
_WEIGHT = {"left": 1.0, "right": -1.0, "both": 0.0}  # COM shift towards the left foot, in units


@dataclass(frozen=True)
class IdleParams:
    """Per-clip settings of :func:`generate_idle`.

    Attributes:
        duration_s: clip length in seconds (the clip has round(duration * fps) + 1 frames).
        fps: frames per second.
        start_xz: floor position (x, z) of the body-frame origin (between the ankles);
            None draws it uniformly in ±300 cm.
        heading_deg: facing direction, degrees about +y from +z; None draws it in ±180.
        start_category: resting category at frame 0 (left | right | both); None draws it
            from the subject's ``idle_foot_preference``.
    """

    duration_s: float = 60.0
    fps: float = 120.0
    start_xz: tuple[float, float] | None = None
    heading_deg: float | None = None
    start_category: str | None = None

    def validate(self) -> None:
        if not (np.isfinite(self.duration_s) and 0.5 <= self.duration_s <= 3600.0):
            raise ValueError(f"IdleParams.duration_s must be in [0.5, 3600] s; got {self.duration_s}")
        if not (np.isfinite(self.fps) and 10.0 <= self.fps <= 1000.0):
            raise ValueError(f"IdleParams.fps must be in [10, 1000]; got {self.fps}")
        if self.start_xz is not None and (len(self.start_xz) != 2 or not np.all(np.isfinite(self.start_xz))):
            raise ValueError(f"IdleParams.start_xz must be two finite numbers; got {self.start_xz}")
        if self.heading_deg is not None and not np.isfinite(self.heading_deg):
            raise ValueError(f"IdleParams.heading_deg must be finite; got {self.heading_deg}")
        if self.start_category is not None and self.start_category not in CATEGORIES:
            raise ValueError(f"IdleParams.start_category must be one of {CATEGORIES}; got {self.start_category!r}")


@dataclass(frozen=True)
class IdleStyle:
    """A subject's personal way of standing (ranges and sources in the module docstring)."""

    com_shift_frac: float  # COM shift over the loaded foot, fraction of half the stance width
    pelvis_drop_deg: float  # pelvic obliquity towards the unloaded side
    pelvis_yaw_deg: float  # pelvis turns this much towards the loaded side (sign personal)
    trunk_compensation: float  # fraction of the pelvic obliquity the trunk bends back
    transition_s: float  # mean duration of a balance shift
    sway_corner_hz: float
    sway_ml_ratio: float  # medio-lateral / antero-posterior sway RMS
    head_rms_deg: float
    arm_rms_deg: float  # small arm movements: RMS of elbow and shoulder angle noise
    breath_rise_cm: float


def idle_style(subject: Subject) -> IdleStyle:
    """The subject's :class:`IdleStyle`: same subject, same style."""
    r = subject_rng(subject, "idle")
    return IdleStyle(
        com_shift_frac=float(r.uniform(0.35, 0.75)),
        pelvis_drop_deg=float(r.uniform(2.0, 5.0)),
        pelvis_yaw_deg=float(r.choice([-1.0, 1.0]) * r.uniform(1.0, 5.0)),
        trunk_compensation=float(r.uniform(0.5, 1.0)),
        transition_s=float(r.uniform(0.6, 1.3)),
        sway_corner_hz=float(r.uniform(0.15, 0.5)),
        sway_ml_ratio=float(r.uniform(0.5, 0.9)),
        head_rms_deg=float(r.uniform(1.0, 4.0)),
        arm_rms_deg=float(r.uniform(0.5, 2.5)),
        breath_rise_cm=float(r.uniform(0.3, 0.9)),
    )


@dataclass(frozen=True)
class Rest:
    """One resting posture and the balance shift that follows it (times in seconds)."""

    category: str
    start: float  # seconds
    stop: float  # end of the rest = start of the following shift
    shift_stop: float  # end of the following shift (= stop for the last rest)
    values: np.ndarray  # posture parameters of this rest, see _rest_values


def _rest_values(category: str, rng: np.random.Generator) -> np.ndarray:
    """One posture of a category (Egges' Q_c): weight, pelvis yaw offset (deg), elbow
    offset (deg), head pitch offset (deg), head yaw offset (deg)."""
    w = _WEIGHT[category] * rng.uniform(0.85, 1.1) if category != "both" else rng.normal(0.0, 0.08)
    return np.array([w, rng.normal(0.0, 1.5), rng.normal(0.0, 4.0), rng.normal(0.0, 2.0), rng.normal(0.0, 4.0)])


def sample_rests(
    subject: Subject, duration: float, first: str, rng: np.random.Generator, style: IdleStyle | None = None
) -> list[Rest]:
    """Rests and balance shifts until ``duration`` s, starting in category ``first``
    (Egges 2004 Sec. 5.4): dwell ~ Gamma(shape 4, mean ``weight_shift_s``), at least 1 s
    (the clip starts at a random point of the first dwell); the next category is drawn from
    ``idle_foot_preference``, so that is the share of time spent in each (a repeat is a
    re-adjustment to another posture of the same category); shifts last
    ``transition_s`` × U(0.8, 1.25), kept in [0.5, 1.5] s (``style``: the subject's
    :class:`IdleStyle` unless given)."""
    if first not in CATEGORIES:
        raise ValueError(f"first category must be one of {CATEGORIES}; got {first!r}")
    style = style or idle_style(subject)
    pref = np.asarray(subject.idle_foot_preference, dtype=float)
    rests, t, cat, first_rest = [], 0.0, first, True
    while t < duration:
        dwell = max(rng.gamma(4.0, subject.weight_shift_s / 4.0), 1.0)
        if first_rest:
            dwell *= rng.uniform(0.3, 1.0)
            first_rest = False
        shift = float(np.clip(style.transition_s * rng.uniform(0.8, 1.25), 0.5, 1.5))
        rests.append(Rest(cat, t, t + dwell, t + dwell + shift, _rest_values(cat, rng)))
        t += dwell + shift
        cat = CATEGORIES[rng.choice(3, p=pref / pref.sum())]
    return rests


def _posture_tracks(rests: list[Rest], t: np.ndarray) -> np.ndarray:
    """(T, P) posture parameters over time: constant in each rest, minimum-jerk shifts."""
    out = np.broadcast_to(rests[0].values, (t.size, rests[0].values.size)).copy()
    for a, b in zip(rests[:-1], rests[1:]):
        s = minimum_jerk((t - a.stop) / (a.shift_stop - a.stop))
        out += s[:, None] * (b.values - a.values)
    return out


def _truth_intervals(rests: list[Rest], fps: float, n: int) -> tuple[str, str]:
    """(idle_postures, idle_phases): categories split at the middle of each shift; phases
    name each rest ``rest`` and each transition ``shift``."""
    frame = lambda s: int(np.clip(round(s * fps), 0, n))  # noqa: E731
    postures, phases = [], []
    for i, r in enumerate(rests):
        a = 0 if i == 0 else frame(0.5 * (rests[i - 1].stop + rests[i - 1].shift_stop))
        b = frame(0.5 * (r.stop + r.shift_stop)) if i + 1 < len(rests) else n
        if postures and postures[-1][0] == r.category:
            postures[-1] = (r.category, postures[-1][1], b)
        elif b > a:
            postures.append((r.category, a, b))
        for name, lo, hi in (("rest", r.start, r.stop), ("shift", r.stop, r.shift_stop)):
            if frame(hi) > frame(lo):
                phases.append((name, frame(lo), frame(hi)))
    return format_named(postures), format_named(phases)


@dataclass(frozen=True)
class _Variations:
    """Small continuous variations of one idle clip (Egges 2004 Sec. 6): medio-lateral and
    antero-posterior sway (cm), breathing 0 (exhaled) … 1 (inhaled), head noise (T, 2)
    (pitch, yaw; rad) and arm noise (T, 2, 3) (per side: elbow, shoulder flexion,
    abduction; rad)."""

    sway_ml: np.ndarray
    sway_ap: np.ndarray
    breath: np.ndarray
    head: np.ndarray
    arms: np.ndarray


def _small_variations(subject: Subject, style: IdleStyle, n: int, fps: float, rng: np.random.Generator) -> _Variations:
    """Postural sway of RMS ``subject.sway_cm`` split into antero-posterior and medio-lateral
    parts, breathing at a slowly varying rate, head and arm noise (module docstring)."""
    sway = colored_noise(n, fps, style.sway_corner_hz, rng, channels=2)
    ap_rms = subject.sway_cm / np.hypot(1.0, style.sway_ml_ratio)
    sway_ml, sway_ap = sway[:, 0] * style.sway_ml_ratio * ap_rms, sway[:, 1] * ap_rms
    rate = subject.breath_rate_hz * (1.0 + 0.08 * colored_noise(n, fps, 0.05, rng)[:, 0])
    phase = 2.0 * np.pi * np.cumsum(rate) / fps + rng.uniform(0.0, 2.0 * np.pi)
    breath = 0.5 * (1.0 - np.cos(phase)) * (1.0 + 0.15 * colored_noise(n, fps, 0.05, rng)[:, 0])
    head_noise = np.radians(style.head_rms_deg) * colored_noise(n, fps, 0.3, rng, channels=2)
    arm_noise = np.radians(style.arm_rms_deg) * colored_noise(n, fps, 0.4, rng, channels=6).reshape(n, 2, 3)
    return _Variations(sway_ml, sway_ap, breath, head_noise, arm_noise)


def _pose_pelvis_and_legs(
    sk: Skeleton,
    habit: StanceHabit,
    style: IdleStyle,
    feet: Feet,
    width: float,
    post: np.ndarray,
    var: _Variations,
    rot: np.ndarray,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Pelvis shifted over the loaded foot, dropped towards the unloaded side, turned and
    swaying as an inverted pendulum about the ankles; legs solved to the planted ``feet``.
    Fills ``rot``'s root and legs; returns root positions (T, 3), pelvic drop and yaw (T,) (rad)."""
    w, yaw_off = post[:, 0], post[:, 1]
    root_x = w * style.com_shift_frac * width / 2.0 + var.sway_ml
    root_z = habit.com_ahead_cm + var.sway_ap
    root_y0 = root_height(sk, np.zeros((1, 2)), rot[:1, 0], feet, habit.lock_knee_deg)[0]
    drop = np.radians(style.pelvis_drop_deg) * w
    yaw = np.radians(style.pelvis_yaw_deg * w + yaw_off)
    rot[:, 0] = euler_q(flex=var.sway_ap / root_y0, axial=yaw, lateral=drop - var.sway_ml / root_y0)
    root_xz = np.stack([root_x, root_z], axis=-1)
    root_pos = np.stack([root_x, root_height(sk, root_xz, rot[:, 0], feet, habit.lock_knee_deg), root_z], axis=-1)
    solve_legs(sk, rot, root_pos, feet)
    return root_pos, drop, yaw


def _pose_upper_body(
    subject: Subject,
    style: IdleStyle,
    rig: Rig,
    post: np.ndarray,
    var: _Variations,
    drop: np.ndarray,
    yaw: np.ndarray,
    rot: np.ndarray,
) -> None:
    """Fills ``rot``'s trunk, head and clavicles: habitual lean, lateral bend back over the
    pelvis, turn back towards the front, breathing (chest extension, shoulders rising);
    head at the habitual pitch plus the rest's offsets and small movements."""
    sk = subject.skeleton
    head_pitch_off, head_yaw_off = post[:, 3], post[:, 4]
    lean = np.radians(subject.torso_lean_deg)
    comp = -style.trunk_compensation * drop
    for name, share in (("LowerBack", 0.45), ("Spine", 0.35), ("Spine1", 0.2)):
        extend = np.radians(1.0) * var.breath if name == "Spine1" else 0.0
        rot[:, rig[name]] = euler_q(flex=share * lean - extend, axial=-0.6 * share * yaw, lateral=share * comp)
    pitch = np.radians(subject.head_pitch_deg + head_pitch_off) + var.head[:, 0]
    head_yaw = np.radians(head_yaw_off) + var.head[:, 1]
    rot[:, rig["Neck1"]] = euler_q(flex=0.5 * pitch, axial=0.5 * head_yaw)
    rot[:, rig["Head"]] = euler_q(flex=0.5 * pitch, axial=0.5 * head_yaw)
    for sign, side in ((1.0, "left"), (-1.0, "right")):
        clav = sk.offsets[rig.side(side, "Arm")]
        lift = np.radians(subject.shoulder_lift_deg) + style.breath_rise_cm * var.breath / np.linalg.norm(clav)
        rot[:, rig.side(side, "Shoulder")] = euler_q(lateral=sign * lift)


def _hang_arms(
    subject: Subject,
    habit: StanceHabit,
    rig: Rig,
    root_pos: np.ndarray,
    rot: np.ndarray,
    elbow_off: np.ndarray,
    yaw: np.ndarray,
    arm_noise: np.ndarray,
) -> None:
    """Fills ``rot``'s arms: hands hanging from the shoulders (gravity frame turned with the
    pelvis), elbows at the habit plus the rest's offset, with small arm movements."""
    sk = subject.skeleton
    frames = fk(rot, root_pos, sk.offsets, sk.parents, return_rotations=True)
    pos = frames[0]
    turn = heading_quat(yaw)
    for i, (sign, side) in enumerate(((1.0, "left"), (-1.0, "right"))):
        elbow = np.maximum(subject.elbow_flex_deg + elbow_off + np.degrees(arm_noise[:, i, 0]), 3.0)
        hang = hanging_hand_offsets(sk, elbow, habit.arm_abduction_deg)[:, i]
        swing = euler_q(flex=-arm_noise[:, i, 1], lateral=-sign * arm_noise[:, i, 2])
        target = pos[:, rig.side(side, "Arm")] + qrot(qmul(turn, swing), hang)
        solve_arm(sk, rot, root_pos, side, target, elbow_pole(turn, side), frames=frames)


def _idle_truth(
    rests: list[Rest], fps: float, n: int, heading: float, start_xz: tuple[float, float], width: float, toe_out: float
) -> dict:
    """Ground truth of an idle clip (see :func:`generate_idle`)."""
    postures, phases = _truth_intervals(rests, fps, n)
    return {
        "variant": "standing",
        "target_x": float("nan"),
        "target_y": float("nan"),
        "target_z": float("nan"),
        "segments": format_named([("idle", 0, n)]),
        "idle_phases": phases,
        "left_contacts": format_ranges([(0, n)]),
        "right_contacts": format_ranges([(0, n)]),
        "idle_postures": postures,
        "heading_deg": float(np.degrees(heading)),
        "start_x": float(start_xz[0]),
        "start_z": float(start_xz[1]),
        "stance_width_cm": float(width),
        "toe_out_deg": float(toe_out),
    }


def generate_idle(
    subject: Subject, params: IdleParams, rng: np.random.Generator, style: IdleStyle | None = None
) -> tuple[Motion, dict]:
    """Idle standing of ``params.duration_s`` seconds with balance shifts and small variations,
    in the subject's :class:`IdleStyle` (or ``style``, e.g. of a :func:`movement_twin`).

    Returns the Motion (at ``params.fps``) and its truth: variant ``"standing"``, NaN target,
    ``segments`` (one ``idle`` primitive: idle clips are not segmented), ``idle_phases``
    (rest / shift), foot contacts (both feet all the time), ``idle_postures``
    (left | right | both, split at the middle of each shift) and the stance used.
    """
    params.validate()
    sk = subject.skeleton
    style = style or idle_style(subject)
    habit = stance_habit(subject)
    fps = float(params.fps)
    n = int(round(params.duration_s * fps)) + 1
    t = np.arange(n) / fps
    heading = np.radians(params.heading_deg if params.heading_deg is not None else rng.uniform(-180.0, 180.0))
    start_xz = params.start_xz if params.start_xz is not None else tuple(rng.uniform(-300.0, 300.0, 2))
    pref = np.asarray(subject.idle_foot_preference, dtype=float)
    first = params.start_category or CATEGORIES[rng.choice(3, p=pref / pref.sum())]

    width = habit.width_cm + rng.normal(0.0, 1.0)
    toe_out = habit.toe_out_deg + rng.normal(0.0, 1.5)
    feet = plant_feet(sk, width, toe_out)
    rests = sample_rests(subject, params.duration_s, first, rng, style)
    post = _posture_tracks(rests, t)  # weight, yaw, elbow, head pitch, head yaw offsets
    var = _small_variations(subject, style, n, fps, rng)

    rig = Rig(sk)
    rot = identity_rotations(n, sk)
    root_pos, drop, yaw = _pose_pelvis_and_legs(sk, habit, style, feet, width, post, var, rot)
    _pose_upper_body(subject, style, rig, post, var, drop, yaw, rot)
    _hang_arms(subject, habit, rig, root_pos, rot, post[:, 2], yaw, var.arms)
    root_w, rot_w = to_world(root_pos, rot, heading, start_xz)
    truth = _idle_truth(rests, fps, n, heading, start_xz, width, toe_out)
    return Motion(skeleton=sk, root_pos=root_w, rotations=rot_w, fps=fps), truth


#: the traits of :class:`Subject` and :class:`IdleStyle` that say how a person moves while standing, not which
#: posture they hold (their window means do not depend on them): sway, breathing rate, how often and how fast the
#: balance shifts, head and arm movements
MOVEMENT_TRAITS = (
    "sway_cm",
    "weight_shift_s",
    "breath_rate_hz",
    "transition_s",
    "sway_corner_hz",
    "sway_ml_ratio",
    "head_rms_deg",
    "arm_rms_deg",
)


def movement_twin(subject: Subject, key: int) -> tuple[Subject, IdleStyle]:
    """A person who stands like ``subject`` but moves in their own way: the same body, stance,
    resting postures, foot preference and breathing depth, the :data:`MOVEMENT_TRAITS` drawn
    anew (seeded by ``key``) from the ranges of :func:`~motionvar.synth.subjects.make_subjects`
    and :func:`idle_style`. Pass both to :func:`generate_idle`: twins of one subject are the
    ground truth of a movement-only identification (Egges 2004 Sec. 5.6: "the way a person
    changes posture")."""
    r = np.random.default_rng([key, zlib.crc32(subject.subject_id.encode())])
    twin = replace(
        subject,
        sway_cm=float(r.uniform(0.3, 1.0)),
        weight_shift_s=float(r.uniform(4.0, 15.0)),
        breath_rate_hz=float(r.uniform(0.2, 0.33)),
    )
    style = replace(
        idle_style(subject),
        transition_s=float(r.uniform(0.6, 1.3)),
        sway_corner_hz=float(r.uniform(0.15, 0.5)),
        sway_ml_ratio=float(r.uniform(0.5, 0.9)),
        head_rms_deg=float(r.uniform(1.0, 4.0)),
        arm_rms_deg=float(r.uniform(0.5, 2.5)),
    )
    return twin, style
