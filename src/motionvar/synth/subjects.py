"""Synthetic subjects: body proportions and personal habits.

A subject's traits persist across all of that subject's clips; clip-to-clip variation
within a subject is drawn separately and is smaller (docs/gait.md, "Consistency"). The
habits are the per-person "variation" of Ma et al. 2010 (Sec. 1, 5) and the personal
idle style of Egges et al. 2004 (Sec. 5.6).

Ranges and their rationale:
- height_scale ~ N(1, 0.05): adult stature SD is about 7 cm of 170 cm (~4 %); CMU subject
  02's proportions are the mean body.
- segment_jitter ~ N(0, 0.02) per bone, symmetric left/right: limb-length ratios vary by a
  few percent between adults (Winter 2009, anthropometric tables).
- arm_swing_scale ~ U(0.6, 1.4): shoulder swing of ±15-30 degrees at comfortable walking
  speed (docs/gait.md) spans a factor 2 between people.
- knee_lift_scale ~ U(0.85, 1.15): peak swing knee flexion 60-65 degrees, ±10 %.
- torso_lean_deg ~ N(3, 2.5): habitual forward trunk inclination of a few degrees.
- head_pitch_deg ~ N(0, 4): head carriage, up (negative) or down (positive).
- elbow_flex_deg ~ U(10, 30): resting elbow flexion during walking (docs/gait.md).
- step_width_cm ~ U(6, 12): step width 5-13 cm (docs/gait.md).
- cadence_scale ~ U(0.93, 1.07): comfortable cadence 100-120 steps/min.
- shoulder_lift_deg ~ N(0, 3): habitual shoulder elevation / depression.
- sway_cm ~ U(0.3, 1.0): centre-of-pressure RMS in quiet standing 0.3-1 cm (Winter 2009).
- weight_shift_s ~ U(4, 15): mean time between weight shifts (docs/gait.md: several to tens of s).
- idle_foot_preference ~ Dirichlet(2, 2, 1): how often the subject rests on the left foot,
  the right foot or both (Egges 2004 Sec. 5.1 categories).
- breath_rate_hz ~ U(0.2, 0.33): 12-20 breaths per minute.
- step_asymmetry_cm ~ N(0, ``STEP_ASYMMETRY_SD_CM``): how much longer the left steps are than
  the right ones; captured walks differ by a few cm (Bandai-Namco's walks: a median of 2.9 cm,
  docs/gait.md "Realism"), drawn from a stream of its own.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..core.skeleton import Skeleton, cmu_skeleton

STEP_ASYMMETRY_SD_CM = 2.5


@dataclass(frozen=True)
class Subject:
    """One synthetic person: an id, a scaled skeleton and habits (see module docstring)."""

    subject_id: str
    skeleton: Skeleton
    height_scale: float
    arm_swing_scale: float
    knee_lift_scale: float
    torso_lean_deg: float
    head_pitch_deg: float
    elbow_flex_deg: float
    step_width_cm: float
    cadence_scale: float
    shoulder_lift_deg: float
    sway_cm: float
    weight_shift_s: float
    idle_foot_preference: tuple[float, float, float]
    breath_rate_hz: float
    step_asymmetry_cm: float = 0.0

    @property
    def leg_length_cm(self) -> float:
        """Hip joint to ground along the straight leg (thigh + shin + ankle height)."""
        sk = self.skeleton
        return float(
            sum(np.linalg.norm(sk.offsets[sk.index(n)]) for n in ("LeftLeg", "LeftFoot"))
            + abs(sk.offsets[sk.index("LeftToeBase"), 1])
        )


def _symmetric_jitter(skeleton: Skeleton, rng: np.random.Generator, sd: float) -> np.ndarray:
    """Per-joint length factors, identical for a left joint and its right twin."""
    factors = {}
    out = np.ones(skeleton.n_joints)
    for j, name in enumerate(skeleton.names):
        key = name.replace("Left", "").replace("Right", "").replace("LHip", "Hip").replace("RHip", "Hip")
        key = key.replace("LThumb", "Thumb").replace("RThumb", "Thumb")
        if key not in factors:
            factors[key] = 1.0 + rng.normal(0.0, sd)
        out[j] = factors[key]
    return out


def make_subjects(n: int, seed: int) -> list[Subject]:
    """``n`` subjects drawn from the ranges in the module docstring, deterministic in ``seed``."""
    if n < 1:
        raise ValueError(f"number of subjects must be >= 1, got {n}")
    rng = np.random.default_rng(seed)
    # a stream of its own, so that every other trait is drawn as before
    asymmetry = np.random.default_rng([seed, 1]).normal(0.0, STEP_ASYMMETRY_SD_CM, n)
    base = cmu_skeleton()
    subjects = []
    for i in range(n):
        height = float(np.clip(rng.normal(1.0, 0.05), 0.85, 1.15))
        skeleton = base.scaled(height * _symmetric_jitter(base, rng, 0.02))
        pref = rng.dirichlet([2.0, 2.0, 1.0])
        subjects.append(
            Subject(
                subject_id=f"{i + 1:02d}",
                skeleton=skeleton,
                height_scale=height,
                arm_swing_scale=float(rng.uniform(0.6, 1.4)),
                knee_lift_scale=float(rng.uniform(0.85, 1.15)),
                torso_lean_deg=float(rng.normal(3.0, 2.5)),
                head_pitch_deg=float(rng.normal(0.0, 4.0)),
                elbow_flex_deg=float(rng.uniform(10.0, 30.0)),
                step_width_cm=float(rng.uniform(6.0, 12.0)),
                cadence_scale=float(rng.uniform(0.93, 1.07)),
                shoulder_lift_deg=float(rng.normal(0.0, 3.0)),
                sway_cm=float(rng.uniform(0.3, 1.0)),
                weight_shift_s=float(rng.uniform(4.0, 15.0)),
                idle_foot_preference=(float(pref[0]), float(pref[1]), float(pref[2])),
                breath_rate_hz=float(rng.uniform(0.2, 0.33)),
                step_asymmetry_cm=float(asymmetry[i]),
            )
        )
    return subjects
