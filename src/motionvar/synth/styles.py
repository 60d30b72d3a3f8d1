"""Labelled walking styles as direction-of-change factors relative to neutral walking.

The directions come from the perception and gait literature (docs/gait.md, "Styles"):

- depressed / sad: slower (≈ 0.8-1.0 m/s), shorter strides, smaller arm swing, head and trunk
  flexed forward by 10-20°, reduced limb flexion (Roether et al. 2009).
- proud / happy: faster, longer strides, larger arm swing, upright chest, head raised
  (Roether et al. 2009).
- angry: fast, heavy steps, large arm swing with flexed elbows, more forward lean
  (Roether et al. 2009).
- old: slower, shorter steps, wider base, slight forward trunk lean, reduced swing knee
  flexion and push-off, longer double support (Winter et al. 1990).
- childlike: higher cadence, shorter strides, larger vertical bounce, looser arm swing.
- female: more lateral pelvis motion, narrower step width (feet near the midline), smaller
  shoulder (thorax) sway (Troje 2002).

The magnitudes are the authors' choice, picked to sit inside the ranges quoted above (e.g.
depressed speed 0.80 × 0.88 ≈ 0.70 of neutral, ≈ 0.9 m/s for a 1.3 m/s neutral walker); they
were fixed before any evaluation ran and are not tuned to a paper's claim. Multiplicative
factors are dimensionless, additive ones in degrees or as a stance-fraction change.
"""

from __future__ import annotations

from dataclasses import dataclass

STYLES = ("neutral", "proud", "depressed", "angry", "female", "childlike", "old")


@dataclass(frozen=True)
class StyleFactors:
    """How a style changes a walk, relative to the subject's neutral walk."""

    stride: float = 1.0  # × stride length
    cadence: float = 1.0  # × steps per minute (speed = stride × cadence)
    step_width: float = 1.0  # × step width
    arm_swing: float = 1.0  # × shoulder swing amplitude
    elbow_add_deg: float = 0.0  # + mean elbow flexion
    elbow_swing: float = 1.0  # × elbow oscillation ("loose" arms swing at the elbow)
    torso_lean_add_deg: float = 0.0  # + forward trunk lean
    head_pitch_add_deg: float = 0.0  # + head flexion (down positive)
    shoulder_lift_add_deg: float = 0.0  # + shoulder elevation (negative: drooping)
    knee_lift: float = 1.0  # × peak swing knee flexion
    push_off: float = 1.0  # × heel rise at toe-off (forefoot push-off)
    heel_strike: float = 1.0  # × foot-floor angle at heel strike
    bob: float = 1.0  # × vertical pelvis excursion
    pelvis_obliquity: float = 1.0  # × pelvic drop (frontal plane)
    pelvis_rotation: float = 1.0  # × pelvic rotation (transverse plane)
    thorax_rotation: float = 1.0  # × thorax counter-rotation ("shoulder sway")
    stance_add: float = 0.0  # + stance fraction of the gait cycle


STYLE_FACTORS: dict[str, StyleFactors] = {
    "neutral": StyleFactors(),
    "proud": StyleFactors(
        stride=1.08,
        cadence=1.04,
        arm_swing=1.3,
        torso_lean_add_deg=-4.0,
        head_pitch_add_deg=-8.0,
        shoulder_lift_add_deg=2.0,
        knee_lift=1.05,
        push_off=1.05,
        heel_strike=1.1,
        bob=1.1,
        pelvis_rotation=1.1,
        thorax_rotation=1.1,
    ),
    "depressed": StyleFactors(
        stride=0.80,
        cadence=0.88,
        arm_swing=0.45,
        elbow_add_deg=-5.0,
        elbow_swing=0.5,
        torso_lean_add_deg=10.0,
        head_pitch_add_deg=18.0,
        shoulder_lift_add_deg=-5.0,
        knee_lift=0.80,
        push_off=0.75,
        heel_strike=0.6,
        bob=0.7,
        pelvis_rotation=0.8,
        thorax_rotation=0.7,
        stance_add=0.02,
    ),
    "angry": StyleFactors(
        stride=1.05,
        cadence=1.12,
        arm_swing=1.35,
        elbow_add_deg=30.0,
        elbow_swing=1.3,
        torso_lean_add_deg=6.0,
        head_pitch_add_deg=5.0,
        shoulder_lift_add_deg=3.0,
        knee_lift=1.1,
        push_off=1.1,
        heel_strike=1.25,
        bob=1.25,
        pelvis_rotation=1.1,
        thorax_rotation=1.2,
    ),
    "female": StyleFactors(
        stride=0.95,
        cadence=1.05,
        step_width=0.3,
        arm_swing=0.9,
        pelvis_obliquity=1.8,
        pelvis_rotation=1.5,
        thorax_rotation=0.6,
    ),
    "childlike": StyleFactors(
        stride=0.80,
        cadence=1.18,
        arm_swing=1.3,
        elbow_add_deg=-5.0,
        elbow_swing=1.8,
        knee_lift=1.15,
        bob=1.6,
        head_pitch_add_deg=-3.0,
    ),
    "old": StyleFactors(
        stride=0.82,
        cadence=0.92,
        step_width=1.4,
        arm_swing=0.7,
        torso_lean_add_deg=8.0,
        head_pitch_add_deg=5.0,
        shoulder_lift_add_deg=-2.0,
        knee_lift=0.8,
        push_off=0.7,
        heel_strike=0.6,
        bob=0.8,
        stance_add=0.03,
    ),
}


def style_factors(style: str) -> StyleFactors:
    """The factors of ``style``; ValueError naming the known styles otherwise."""
    try:
        return STYLE_FACTORS[style]
    except KeyError:
        raise ValueError(f"style must be one of {STYLES}; got {style!r}") from None
