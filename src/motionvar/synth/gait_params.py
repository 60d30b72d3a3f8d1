"""Per-clip parameters of the locomotion generator and how they are drawn.

A clip is described by *what* is done (stride length, speed, step width, turn, number of
steps: Ma 2010's style parameters) and *how* (:class:`Manner`: arm swing, trunk lean, knee
lift, ...: the subject's habits — Ma 2010's "variation" — changed by the labelled style).

Neutral adult values (docs/gait.md; Perry & Burnfield 2010, Winter 2009, Novacheck 1998):
- walking stride = ``WALK_STRIDE_PER_LEG`` (1.6) × leg length, inside 1.5-1.7; cadence
  ``WALK_CADENCE`` (110 steps/min, inside 100-120) × the subject's cadence habit; so a
  leg of 87 cm walks 139 cm strides at ≈ 1.3 m/s.
- stance ≈ 60 % of the cycle at 1.3 m/s, shrinking by 8 % per m/s faster (double support
  shrinks as speed grows), clipped to 55-68 %.
- arm swing ±20° × the arm-swing habit (±12-28°, GAIT ±15-30°); elbow flexion at the habit
  (10-30°); peak swing knee flexion 62° × the knee-lift habit (60-65°); foot-floor angles at
  heel strike 15° and at toe-off 60° (authors' choice: heel first at initial contact, heel
  high at the end of pre-swing, where the knee flexes to ≈ 40° in Perry's data); pelvis rotation ±4.5°, obliquity ±4°, tilt ±2°; thorax counter-rotation
  0.7 × pelvic rotation; vertical pelvis excursion 2 × 2 cm (3-5 cm); lateral ±(1.5 + 0.05 ×
  step width) cm (3-5 cm in all).
- running: stride 2.6 × leg length (2-3.5 m), cadence 165 steps/min (150-180), stance 36 %
  at 3 m/s, 3 % less per m/s faster (30-40 %); swing knee peak 105° (90-130°); elbows 85° +
  the habit's offset from 20° (80-100°); arm swing ±30°; 4° more forward lean.
- side-stepping: lateral step 30-55 cm (GAIT 30-60), 90 steps/min (slower than walking),
  swing 55 % of each step, feet lifted 7 cm.
Clip-to-clip variation within a subject is small (walking stride ±4 %, cadence ±3 %, arm swing
±6 %, lean ±1°), so subjects stay recognisable (docs/gait.md, "Consistency").

Captured variation (``sample_walk_params(..., captured=True)``, which ``SynthSpec`` passes by
default): a walk's stride varies by ``CAPTURED_STRIDE_CLIP_SD`` (0.75 %) around the subject's
instead of 4 % (a test-retest ICC of stride length of 0.8-0.98 in healthy adults puts the
within-subject SD at 0.14-0.5 of the between-subject SD, docs/gait.md "Realism"; with the
subjects' leg lengths spread by ≈ 5 % that is a walk-to-walk SD of 0.7-2.5 %; a walk's measured
mean stride adds its averaged step-to-step variation, so the drawn part takes the low end: the
measured ratio is 0.33-0.46 at full size over five seeds), and steps vary within a walk (the captured Bandai-Namco walks
give stride CV 3.1 %, stride-time CV 2.9 %, toe-off jitter 1.8 % of the cycle; Hausdorff 2005:
stride-time CV 1-3 % in healthy adults): each heel strike's footprint lies off its nominal place
along the path by an AR(1) process over the footfalls (SD ``FOOTFALL_JITTER_CM``, lag-one
correlation ``FOOTFALL_JITTER_RHO``: a slowly varying progression that the body follows), each
heel strike and toe-off is early or late by ``STRIKE_JITTER_S`` / ``TOE_OFF_JITTER_S`` (SD), and
the subject's left steps are longer than its right ones by ``Subject.step_asymmetry_cm``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, fields

import numpy as np

from .styles import STYLES, style_factors
from .subjects import Subject

SIDES = ("left", "right")
WALK_STRIDE_PER_LEG = 1.6
WALK_CADENCE = 110.0  # steps / min
RUN_STRIDE_PER_LEG = 2.6
RUN_CADENCE = 165.0  # steps / min
SIDESTEP_CADENCE = 90.0  # steps / min
WALK_STRIDE_CLIP_SD = 0.04  # log-SD of a walk's stride around the subject's
CAPTURED_STRIDE_CLIP_SD = 0.0075  # the same with captured variation (module docstring)
FOOTFALL_JITTER_CM = 2.5  # SD of a footprint's offset along the path (stride CV ≈ 2 %)
FOOTFALL_JITTER_RHO = 0.5  # lag-one correlation of successive footprints' offsets
STRIKE_JITTER_S = 0.015  # SD of a heel strike's time (stride-time CV ≈ 2 %)
TOE_OFF_JITTER_S = 0.015  # SD of a toe-off's time (stance fraction SD ≈ 1.4 % of the cycle)


@dataclass(frozen=True)
class Manner:
    """How a clip is executed (degrees, cm; see the module docstring for the values)."""

    arm_swing_deg: float = 20.0
    arm_mean_deg: float = 0.0
    arm_abduction_deg: float = 8.0
    elbow_flex_deg: float = 20.0
    elbow_swing_deg: float = 8.0
    torso_lean_deg: float = 3.0
    head_pitch_deg: float = 0.0
    shoulder_lift_deg: float = 0.0
    knee_peak_deg: float = 62.0
    push_off_deg: float = 60.0
    heel_strike_deg: float = 15.0
    bob_cm: float = 2.0
    sway_cm: float = 2.0
    pelvis_rotation_deg: float = 4.5
    pelvis_obliquity_deg: float = 4.0
    pelvis_tilt_deg: float = 2.0
    pelvis_tilt_mean_deg: float = 5.0
    thorax_rotation_ratio: float = 0.7
    stance_fraction: float = 0.6
    lift_cm: float = 7.0

    def validate(self, owner: str, stance: tuple[float, float]) -> None:
        """ValueError naming the first field out of its range; ``stance`` bounds the stance fraction."""
        limits = {
            "arm_swing_deg": (0.0, 80.0),
            "arm_mean_deg": (-45.0, 45.0),
            "arm_abduction_deg": (0.0, 45.0),
            "elbow_flex_deg": (0.0, 140.0),
            "elbow_swing_deg": (0.0, 40.0),
            "torso_lean_deg": (-30.0, 45.0),
            "head_pitch_deg": (-45.0, 60.0),
            "shoulder_lift_deg": (-20.0, 20.0),
            "knee_peak_deg": (20.0, 140.0),
            "push_off_deg": (0.0, 80.0),
            "heel_strike_deg": (0.0, 35.0),
            "bob_cm": (0.0, 8.0),
            "sway_cm": (0.0, 8.0),
            "pelvis_rotation_deg": (0.0, 20.0),
            "pelvis_obliquity_deg": (0.0, 15.0),
            "pelvis_tilt_deg": (0.0, 10.0),
            "pelvis_tilt_mean_deg": (-10.0, 20.0),
            "thorax_rotation_ratio": (0.0, 2.0),
            "stance_fraction": stance,
            "lift_cm": (1.0, 30.0),
        }
        for name, (lo, hi) in limits.items():
            v = getattr(self, name)
            if not (isinstance(v, (int, float)) and math.isfinite(v) and lo <= v <= hi):
                raise ValueError(f"{owner}.manner.{name} must be in [{lo}, {hi}]; got {v!r}")


def _check(owner: str, name: str, value, lo: float, hi: float) -> None:
    if (
        isinstance(value, bool)
        or not isinstance(value, (int, float))
        or not (math.isfinite(value) and lo <= value <= hi)
    ):
        raise ValueError(f"{owner}.{name} must be a number in [{lo}, {hi}]; got {value!r}")


def _check_common(p, owner: str) -> None:
    """Checks shared by all locomotion params: placement, frame rate, first foot, integers."""
    _check(owner, "heading_deg", p.heading_deg, -360.0, 360.0)
    _check(owner, "fps", p.fps, 24.0, 1000.0)
    if len(p.start_xz) != 2:
        raise ValueError(f"{owner}.start_xz must be (x, z); got {p.start_xz!r}")
    for v in p.start_xz:
        _check(owner, "start_xz", v, -1e5, 1e5)


def _check_gait(p, owner: str, stride: tuple, speed: tuple, steps: tuple, cadence: tuple) -> None:
    """Checks shared by walks and runs: stride, speed, width, turn, steps, first foot, and the
    cadence that stride and speed imply; then :func:`_check_common`."""
    _check(owner, "stride_length_cm", p.stride_length_cm, *stride)
    _check(owner, "speed_cm_s", p.speed_cm_s, *speed)
    _check(owner, "step_width_cm", p.step_width_cm, 0.0, 40.0)
    _check(owner, "turn_deg", p.turn_deg, -180.0, 180.0)
    if not isinstance(p.n_steps, (int, np.integer)) or not steps[0] <= p.n_steps <= steps[1]:
        raise ValueError(f"{owner}.n_steps must be an integer in [{steps[0]}, {steps[1]}]; got {p.n_steps!r}")
    if p.first_foot not in SIDES:
        raise ValueError(f"{owner}.first_foot must be one of {SIDES}; got {p.first_foot!r}")
    steps_min = 120.0 * p.speed_cm_s / p.stride_length_cm
    if not cadence[0] <= steps_min <= cadence[1]:
        raise ValueError(
            f"{owner}.speed_cm_s / stride_length_cm give a cadence of {steps_min:.0f} steps/min; "
            f"{cadence[0]:.0f}-{cadence[1]:.0f} expected"
        )
    _check_common(p, owner)


@dataclass(frozen=True)
class WalkParams:
    """A walk: stand, ``n_steps`` heel strikes on a straight or curved path, a closing step,
    stand. ``turn_deg`` > 0 turns left. Stride, speed and width are the steady-gait values."""

    style: str = "neutral"
    stride_length_cm: float = 140.0
    speed_cm_s: float = 128.0
    step_width_cm: float = 9.0
    turn_deg: float = 0.0
    n_steps: int = 6
    first_foot: str = "left"
    stand_start_s: float = 0.5
    stand_end_s: float = 0.5
    start_xz: tuple[float, float] = (0.0, 0.0)
    heading_deg: float = 0.0
    fps: float = 120.0
    manner: Manner = field(default_factory=Manner)
    footfall_offsets_cm: tuple[float, ...] = ()
    strike_offsets_s: tuple[float, ...] = ()
    toe_off_offsets_s: tuple[float, ...] = ()
    step_asymmetry_cm: float = 0.0

    @property
    def variant(self) -> str:
        return "forward" if self.turn_deg == 0 else ("left" if self.turn_deg > 0 else "right")

    def offsets(self, name: str) -> np.ndarray:
        """(n_steps,) per-heel-strike offsets of ``name`` (module docstring): zeros when none."""
        values = getattr(self, name)
        return np.asarray(values, dtype=float) if len(values) else np.zeros(self.n_steps)

    def validate(self) -> None:
        o = "WalkParams"
        if self.style not in STYLES:
            raise ValueError(f"{o}.style must be one of {STYLES}; got {self.style!r}")
        _check(o, "stand_start_s", self.stand_start_s, 0.1, 30.0)
        _check(o, "stand_end_s", self.stand_end_s, 0.1, 30.0)
        _check_gait(self, o, stride=(20.0, 250.0), speed=(10.0, 300.0), steps=(3, 60), cadence=(40.0, 200.0))
        self.manner.validate(o, (0.52, 0.8))
        limits = {"footfall_offsets_cm": 0.1 * self.stride_length_cm, "strike_offsets_s": 0.1, "toe_off_offsets_s": 0.1}
        for name, limit in limits.items():
            values = getattr(self, name)
            if len(values) not in (0, self.n_steps) or not np.all(np.abs(values) <= limit):
                raise ValueError(f"{o}.{name} must hold n_steps values within ±{limit:.3g}; got {values}")
        _check(
            o, "step_asymmetry_cm", self.step_asymmetry_cm, -0.1 * self.stride_length_cm, 0.1 * self.stride_length_cm
        )


@dataclass(frozen=True)
class RunParams:
    """A steady run (the clip starts and ends in flight) with ``n_steps`` complete stance
    primitives; ``turn_deg`` > 0 turns left."""

    stride_length_cm: float = 230.0
    speed_cm_s: float = 315.0
    step_width_cm: float = 4.0
    turn_deg: float = 0.0
    n_steps: int = 6
    first_foot: str = "left"
    start_xz: tuple[float, float] = (0.0, 0.0)
    heading_deg: float = 0.0
    fps: float = 120.0
    manner: Manner = field(
        default_factory=lambda: Manner(
            arm_swing_deg=30.0,
            elbow_flex_deg=85.0,
            elbow_swing_deg=10.0,
            torso_lean_deg=7.0,
            knee_peak_deg=105.0,
            push_off_deg=60.0,
            heel_strike_deg=8.0,
            bob_cm=0.0,
            sway_cm=1.0,
            pelvis_rotation_deg=6.0,
            thorax_rotation_ratio=0.8,
            stance_fraction=0.36,
            pelvis_tilt_mean_deg=8.0,
        )
    )

    @property
    def variant(self) -> str:
        return "forward" if self.turn_deg == 0 else ("left" if self.turn_deg > 0 else "right")

    def validate(self) -> None:
        o = "RunParams"
        _check_gait(self, o, stride=(80.0, 500.0), speed=(150.0, 1000.0), steps=(2, 80), cadence=(120.0, 240.0))
        self.manner.validate(o, (0.2, 0.48))


@dataclass(frozen=True)
class SidestepParams:
    """Side-stepping ``n_cycles`` lateral step cycles (lead foot out, trail foot in) to the
    ``direction`` side, facing forward, from standing to standing."""

    direction: str = "left"
    step_cm: float = 40.0
    stance_width_cm: float = 20.0
    n_cycles: int = 3
    cadence_steps_min: float = 90.0
    swing_fraction: float = 0.55
    stand_start_s: float = 0.5
    stand_end_s: float = 0.5
    start_xz: tuple[float, float] = (0.0, 0.0)
    heading_deg: float = 0.0
    fps: float = 120.0
    manner: Manner = field(
        default_factory=lambda: Manner(
            arm_swing_deg=3.0,
            knee_peak_deg=60.0,
            push_off_deg=0.0,
            heel_strike_deg=0.0,
            bob_cm=0.5,
            sway_cm=0.0,
            pelvis_rotation_deg=0.0,
            pelvis_obliquity_deg=3.0,
            pelvis_tilt_deg=0.0,
            pelvis_tilt_mean_deg=0.0,
            stance_fraction=0.7,
        )
    )

    @property
    def variant(self) -> str:
        return self.direction

    def validate(self) -> None:
        o = "SidestepParams"
        if self.direction not in SIDES:
            raise ValueError(f"{o}.direction must be one of {SIDES}; got {self.direction!r}")
        _check(o, "step_cm", self.step_cm, 5.0, 80.0)
        _check(o, "stance_width_cm", self.stance_width_cm, 5.0, 45.0)
        _check(o, "cadence_steps_min", self.cadence_steps_min, 30.0, 180.0)
        _check(o, "swing_fraction", self.swing_fraction, 0.2, 0.9)
        _check(o, "stand_start_s", self.stand_start_s, 0.1, 30.0)
        _check(o, "stand_end_s", self.stand_end_s, 0.1, 30.0)
        if not isinstance(self.n_cycles, (int, np.integer)) or not 2 <= self.n_cycles <= 40:
            raise ValueError(f"{o}.n_cycles must be an integer in [2, 40]; got {self.n_cycles!r}")
        _check_common(self, o)
        self.manner.validate(o, (0.0, 1.0))


def _placement(rng: np.random.Generator) -> dict:
    """Anywhere on a 6 m × 6 m floor, any heading (clips start like real mocap takes)."""
    return {
        "start_xz": tuple(float(v) for v in rng.uniform(-300.0, 300.0, 2)),
        "heading_deg": float(rng.uniform(-180, 180)),
    }


def walk_manner(
    subject: Subject, style: str, speed_cm_s: float, step_width_cm: float, rng: np.random.Generator
) -> Manner:
    """The subject's habits changed by ``style``, with small clip-to-clip jitter."""
    f = style_factors(style)
    stance = 0.60 - 0.08 * (speed_cm_s / 100.0 - 1.3) + f.stance_add
    return Manner(
        arm_swing_deg=20.0 * subject.arm_swing_scale * f.arm_swing * rng.normal(1.0, 0.06),
        elbow_flex_deg=float(np.clip(subject.elbow_flex_deg + f.elbow_add_deg + rng.normal(0.0, 2.0), 0.0, 140.0)),
        elbow_swing_deg=8.0 * f.elbow_swing,
        torso_lean_deg=subject.torso_lean_deg + f.torso_lean_add_deg + rng.normal(0.0, 1.0),
        head_pitch_deg=subject.head_pitch_deg + f.head_pitch_add_deg + rng.normal(0.0, 1.5),
        shoulder_lift_deg=subject.shoulder_lift_deg + f.shoulder_lift_add_deg + rng.normal(0.0, 1.0),
        knee_peak_deg=62.0 * subject.knee_lift_scale * f.knee_lift * rng.normal(1.0, 0.02),
        push_off_deg=60.0 * f.push_off,
        heel_strike_deg=15.0 * f.heel_strike,
        bob_cm=2.0 * f.bob * rng.normal(1.0, 0.08),
        sway_cm=1.5 + 0.05 * step_width_cm,
        pelvis_rotation_deg=4.5 * f.pelvis_rotation,
        pelvis_obliquity_deg=4.0 * f.pelvis_obliquity,
        pelvis_tilt_deg=2.0,
        thorax_rotation_ratio=0.7 * f.thorax_rotation,
        stance_fraction=float(np.clip(stance, 0.55, 0.68)),
    )


def sample_walk_params(
    subject: Subject,
    rng: np.random.Generator,
    style: str = "neutral",
    turn_deg: float = 0.0,
    n_steps: int | None = None,
    fps: float = 120.0,
    captured: bool = False,
) -> WalkParams:
    """A walk of ``subject`` in ``style``: stride ∝ leg length, cadence from the habit; with
    ``captured``, steps that vary as captured ones do (module docstring), drawn after the rest."""
    f = style_factors(style)
    clip_sd = CAPTURED_STRIDE_CLIP_SD if captured else WALK_STRIDE_CLIP_SD
    stride = WALK_STRIDE_PER_LEG * subject.leg_length_cm * f.stride * math.exp(rng.normal(0.0, clip_sd))
    cadence = WALK_CADENCE * subject.cadence_scale * f.cadence * math.exp(rng.normal(0.0, 0.03))
    speed = stride * cadence / 120.0
    width = max(subject.step_width_cm * f.step_width + rng.normal(0.0, 1.0), 0.0)
    steps = int(n_steps if n_steps is not None else rng.integers(5, 9))
    first_foot = SIDES[int(rng.integers(2))]
    stand = (float(rng.uniform(0.4, 0.9)), float(rng.uniform(0.4, 0.9)))
    manner = walk_manner(subject, style, speed, width, rng)
    placement = _placement(rng)
    return WalkParams(
        style=style,
        stride_length_cm=stride,
        speed_cm_s=speed,
        step_width_cm=width,
        turn_deg=float(turn_deg),
        n_steps=steps,
        first_foot=first_foot,
        stand_start_s=stand[0],
        stand_end_s=stand[1],
        fps=fps,
        manner=manner,
        **placement,
        **(step_variation(steps, stride, subject.step_asymmetry_cm, rng) if captured else {}),
    )


def _bounded(rng: np.random.Generator, sd: float, n: int, limit: float) -> np.ndarray:
    return np.clip(rng.normal(0.0, sd, n), -limit, limit)


def step_variation(n_steps: int, stride_cm: float, asymmetry_cm: float, rng: np.random.Generator) -> dict:
    """WalkParams fields of a walk's step-to-step variation (module docstring): AR(1) footprint
    offsets, heel-strike and toe-off jitter (each within 3 SD and the fields' limits)."""
    limit = min(3.0 * FOOTFALL_JITTER_CM, 0.1 * stride_cm)
    e = np.empty(n_steps)
    innovation = rng.normal(0.0, FOOTFALL_JITTER_CM * math.sqrt(1.0 - FOOTFALL_JITTER_RHO**2), n_steps)
    e[0] = rng.normal(0.0, FOOTFALL_JITTER_CM)
    for k in range(1, n_steps):
        e[k] = FOOTFALL_JITTER_RHO * e[k - 1] + innovation[k]
    return {
        "footfall_offsets_cm": tuple(float(x) for x in np.clip(e, -limit, limit)),
        "strike_offsets_s": tuple(float(x) for x in _bounded(rng, STRIKE_JITTER_S, n_steps, 3 * STRIKE_JITTER_S)),
        "toe_off_offsets_s": tuple(float(x) for x in _bounded(rng, TOE_OFF_JITTER_S, n_steps, 3 * TOE_OFF_JITTER_S)),
        "step_asymmetry_cm": float(np.clip(asymmetry_cm, -0.1 * stride_cm, 0.1 * stride_cm)),
    }


def sample_run_params(
    subject: Subject,
    rng: np.random.Generator,
    turn_deg: float = 0.0,
    n_steps: int | None = None,
    fps: float = 120.0,
) -> RunParams:
    """A run of ``subject`` at its habitual cadence, stride ∝ leg length."""
    stride = RUN_STRIDE_PER_LEG * subject.leg_length_cm * math.exp(rng.normal(0.0, 0.05))
    cadence = RUN_CADENCE * subject.cadence_scale * math.exp(rng.normal(0.0, 0.03))
    speed = stride * cadence / 120.0
    base = RunParams().manner
    manner = Manner(
        **{
            **{f.name: getattr(base, f.name) for f in fields(Manner)},
            "arm_swing_deg": 30.0 * subject.arm_swing_scale * rng.normal(1.0, 0.06),
            "elbow_flex_deg": float(np.clip(85.0 + subject.elbow_flex_deg - 20.0 + rng.normal(0.0, 2.0), 60.0, 120.0)),
            "torso_lean_deg": subject.torso_lean_deg + 4.0 + rng.normal(0.0, 1.0),
            "head_pitch_deg": subject.head_pitch_deg + rng.normal(0.0, 1.5),
            "shoulder_lift_deg": subject.shoulder_lift_deg + rng.normal(0.0, 1.0),
            "knee_peak_deg": 105.0 * subject.knee_lift_scale * rng.normal(1.0, 0.02),
            "stance_fraction": float(np.clip(0.36 - 0.03 * (speed / 100.0 - 3.0), 0.28, 0.42)),
        }
    )
    return RunParams(
        stride_length_cm=stride,
        speed_cm_s=speed,
        step_width_cm=max(0.5 * subject.step_width_cm + rng.normal(0, 1), 0.0),
        turn_deg=float(turn_deg),
        n_steps=int(n_steps if n_steps is not None else rng.integers(6, 9)),
        first_foot=SIDES[int(rng.integers(2))],
        fps=fps,
        manner=manner,
        **_placement(rng),
    )


def sample_sidestep_params(
    subject: Subject,
    rng: np.random.Generator,
    direction: str = "left",
    n_cycles: int | None = None,
    fps: float = 120.0,
) -> SidestepParams:
    """Side-steps of ``subject``: lateral step ∝ body size, the habit's cadence."""
    base = SidestepParams().manner
    manner = Manner(
        **{
            **{f.name: getattr(base, f.name) for f in fields(Manner)},
            "arm_swing_deg": 3.0 * subject.arm_swing_scale,
            "elbow_flex_deg": float(np.clip(subject.elbow_flex_deg + rng.normal(0.0, 2.0), 0.0, 140.0)),
            "torso_lean_deg": subject.torso_lean_deg + rng.normal(0.0, 1.0),
            "head_pitch_deg": subject.head_pitch_deg + rng.normal(0.0, 1.5),
            "shoulder_lift_deg": subject.shoulder_lift_deg + rng.normal(0.0, 1.0),
            "lift_cm": 7.0 * subject.knee_lift_scale,
        }
    )
    hip_width = 2.0 * 9.2 * subject.height_scale  # CMU subject 02: hip joints ±9.2 cm
    return SidestepParams(
        direction=direction,
        step_cm=float(rng.uniform(30.0, 55.0) * subject.height_scale),
        stance_width_cm=float(hip_width + rng.normal(0.0, 1.5)),
        n_cycles=int(n_cycles if n_cycles is not None else rng.integers(3, 5)),
        cadence_steps_min=SIDESTEP_CADENCE * subject.cadence_scale * math.exp(rng.normal(0.0, 0.04)),
        stand_start_s=float(rng.uniform(0.4, 0.9)),
        stand_end_s=float(rng.uniform(0.4, 0.9)),
        fps=fps,
        manner=manner,
        **_placement(rng),
    )
