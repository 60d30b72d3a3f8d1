"""The synthetic dataset: every subject performs every behaviour a set number of times.

:func:`generate_dataset` returns the clips and one metadata row per clip (the shared
contract, docs/design.md "Datasets"): clip_id, subject, behaviour (walk | run | sidestep | pick |
place | idle), style, variant, primitive ("" for whole clips), the style parameters and
ground truth (stride_length_cm, speed_cm_s, step_width_cm, turn_deg, target_x/y/z,
segments, left_contacts, right_contacts, idle_postures; NaN where a column does not apply),
further per-generator truth (cadence, stance fraction, placement, ...) and the subject's
traits prefixed ``subj_``.

Randomness: subjects come from ``make_subjects(subjects, seed)``; each (subject, behaviour)
pair draws from its own stream ``default_rng([seed, subject index, behaviour index])``, so
changing one behaviour's clip count leaves every other clip unchanged, and the same spec
gives identical arrays and tables. The capture layer (:mod:`.capture`, with ``SynthSpec.captured_variation``)
draws from a stream of its own per clip, ``capture_rng(seed, subject index, behaviour index,
clip index)``, so switching it leaves every other draw unchanged.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, fields

import numpy as np
import pandas as pd

from ..core.motion import Motion
from .capture import add_capture_motion, capture_rng
from .gait_params import sample_run_params, sample_sidestep_params, sample_walk_params
from .idle import IdleParams, generate_idle
from .locomotion import generate_run, generate_sidestep, generate_walk
from .reach import ReachParams, generate_pick, generate_place
from .styles import STYLES
from .subjects import Subject, make_subjects

BEHAVIOURS = ("walk", "run", "sidestep", "pick", "place", "idle")
CONTRACT_COLUMNS = (
    "clip_id",
    "subject",
    "behaviour",
    "style",
    "variant",
    "primitive",
    "stride_length_cm",
    "speed_cm_s",
    "step_width_cm",
    "turn_deg",
    "target_x",
    "target_y",
    "target_z",
    "segments",
    "left_contacts",
    "right_contacts",
    "idle_postures",
)
TURN_RANGE_DEG = (30.0, 90.0)  # total turn of a turning walk or run
REACH_REGIONS = ("low", "forward", "high")


@dataclass(frozen=True)
class SynthSpec:
    """What to generate. Defaults are the full replication (25 subjects × 37 clips, about
    half a million frames); a CI spec lowers ``subjects`` and the counts.

    Attributes:
        subjects: number of synthetic persons; seed: the random seed.
        walks_per_style: straight walks per subject and style (7 styles).
        turning_walks: neutral walks turning left / right by 30-90° (alternating).
        runs: runs per subject (forward, left, right, forward, ...).
        sidesteps: side-step clips (left, right, ...).
        picks / places: two-hand pick and place clips (regions low, forward, high, ...).
        idle_clips: idle standing clips of ``idle_duration_s`` seconds each.
        fps: frame rate of every clip.
        captured_variation: vary as captured motion does (docs/gait.md, "Realism"): steps
            that differ within a walk and between the feet (``sample_walk_params(...,
            captured=True)``), the small smooth rotations captured data carries on channels the
            generator holds constant (:func:`~motionvar.synth.capture.add_capture_motion`; feet,
            hips, knees, ankles, toes, root and the gripping hands keep their positions) and
            reaches with corrective sub-movements (the default). False gives the generator's
            clean data (strides repeated within a walk, left equal to right, still channels,
            single-peaked reaches); every extra draw comes after the others or from a stream of
            its own, so the rest of each clip is drawn alike.
    """

    subjects: int = 25
    seed: int = 0
    walks_per_style: int = 2
    turning_walks: int = 4
    runs: int = 2
    sidesteps: int = 2
    picks: int = 3
    places: int = 3
    idle_clips: int = 2
    idle_duration_s: float = 20.0
    fps: float = 120.0
    captured_variation: bool = True

    def validate(self) -> None:
        """ValueError naming the first bad field."""
        for f in fields(self):
            v = getattr(self, f.name)
            if f.name in ("idle_duration_s", "fps", "captured_variation"):
                continue
            low = 1 if f.name == "subjects" else 0
            if isinstance(v, bool) or not isinstance(v, (int, np.integer)) or v < low:
                raise ValueError(f"SynthSpec.{f.name} must be an integer >= {low}; got {v!r}")
        for name, lo, hi in (("idle_duration_s", 0.5, 3600.0), ("fps", 24.0, 1000.0)):
            v = getattr(self, name)
            if isinstance(v, bool) or not isinstance(v, (int, float)) or not (math.isfinite(v) and lo <= v <= hi):
                raise ValueError(f"SynthSpec.{name} must be a number in [{lo}, {hi}]; got {v!r}")
        if not isinstance(self.captured_variation, (bool, np.bool_)):
            raise ValueError(f"SynthSpec.captured_variation must be true or false; got {self.captured_variation!r}")


def _turn(rng: np.random.Generator, variant: str) -> float:
    sign = {"forward": 0.0, "left": 1.0, "right": -1.0}[variant]
    return sign * float(rng.uniform(*TURN_RANGE_DEG)) if sign else 0.0


def _clips(subject: Subject, spec: SynthSpec, behaviour: str, rng: np.random.Generator):
    """Yield (style, clip-id tag, Motion, truth) for one subject and behaviour, in a fixed
    order; the truth carries the variant."""
    fps, captured = spec.fps, spec.captured_variation
    if behaviour == "walk":
        for style in STYLES:
            for _ in range(spec.walks_per_style):
                m, tr = generate_walk(subject, sample_walk_params(subject, rng, style, fps=fps, captured=captured))
                yield style, style, m, tr
        for k in range(spec.turning_walks):
            variant = ("left", "right")[k % 2]
            params = sample_walk_params(subject, rng, "neutral", _turn(rng, variant), fps=fps, captured=captured)
            m, tr = generate_walk(subject, params)
            yield "neutral", variant, m, tr
    elif behaviour == "run":
        for k in range(spec.runs):
            variant = ("forward", "left", "right")[k % 3]
            m, tr = generate_run(subject, sample_run_params(subject, rng, _turn(rng, variant), fps=fps))
            yield "neutral", variant, m, tr
    elif behaviour == "sidestep":
        for k in range(spec.sidesteps):
            variant = ("left", "right")[k % 2]
            m, tr = generate_sidestep(subject, sample_sidestep_params(subject, rng, variant, fps=fps))
            yield "neutral", variant, m, tr
    elif behaviour in ("pick", "place"):
        gen: Callable = generate_pick if behaviour == "pick" else generate_place
        for k in range(spec.picks if behaviour == "pick" else spec.places):
            params = ReachParams(region=REACH_REGIONS[k % 3], fps=fps, correction=None if captured else False)
            m, tr = gen(subject, params, rng)
            yield "neutral", tr["variant"], m, tr
    else:
        for _ in range(spec.idle_clips):
            m, tr = generate_idle(subject, IdleParams(duration_s=spec.idle_duration_s, fps=fps), rng)
            yield "neutral", tr["variant"], m, tr


def subject_traits(subject: Subject) -> dict:
    """The subject's proportions and habits as ``subj_*`` metadata columns."""
    out = {"subj_leg_length_cm": subject.leg_length_cm}
    for f in fields(subject):
        v = getattr(subject, f.name)
        if f.name == "idle_foot_preference":
            out.update({f"subj_idle_pref_{c}": float(p) for c, p in zip(("left", "right", "both"), v)})
        elif isinstance(v, float):
            out[f"subj_{f.name}"] = v
    return out


def _subject_clips(spec: SynthSpec, i: int) -> tuple[list[Motion], list[dict]]:
    """Clips and metadata rows of subject ``i`` (its own random streams, see module docstring)."""
    subject = make_subjects(spec.subjects, spec.seed)[i]
    traits = subject_traits(subject)
    motions: list[Motion] = []
    rows: list[dict] = []
    for b, behaviour in enumerate(BEHAVIOURS):
        rng = np.random.default_rng([spec.seed, i, b])
        counts: dict[str, int] = {}
        for n, (style, tag, motion, truth) in enumerate(_clips(subject, spec, behaviour, rng)):
            k = counts[tag] = counts.get(tag, -1) + 1
            if spec.captured_variation:
                motion = add_capture_motion(motion, behaviour, capture_rng(spec.seed, i, b, n))
            row = {c: float("nan") for c in CONTRACT_COLUMNS}
            row.update(truth)
            row.update(
                {
                    "clip_id": f"s{subject.subject_id}_{behaviour}_{tag}_{k:02d}",
                    "subject": subject.subject_id,
                    "behaviour": behaviour,
                    "style": style,
                    "primitive": "",
                }
            )
            if behaviour != "idle":
                row["idle_postures"] = float("nan")
            rows.append({**row, **traits})
            motions.append(motion)
    return motions, rows


def generate_dataset(spec: SynthSpec, workers: int = 1) -> tuple[list[Motion], pd.DataFrame]:
    """All clips of ``spec`` (subject by subject, behaviours in :data:`BEHAVIOURS` order) and
    their metadata table (see the module docstring). ``workers`` > 1 generates subjects in
    that many processes; the result is the same."""
    spec.validate()
    if isinstance(workers, bool) or not isinstance(workers, (int, np.integer)) or workers < 1:
        raise ValueError(f"generate_dataset: workers must be an integer >= 1; got {workers!r}")
    if workers > 1 and spec.subjects > 1:
        from concurrent.futures import ProcessPoolExecutor

        with ProcessPoolExecutor(min(workers, spec.subjects)) as pool:
            parts = list(pool.map(_subject_clips, [spec] * spec.subjects, range(spec.subjects)))
    else:
        parts = [_subject_clips(spec, i) for i in range(spec.subjects)]
    motions = [m for ms, _ in parts for m in ms]
    rows = [r for _, rs in parts for r in rs]
    if not rows:
        raise ValueError("SynthSpec: every clip count is 0; nothing to generate")
    meta = pd.DataFrame(rows)
    extras = sorted(c for c in meta.columns if c not in CONTRACT_COLUMNS and not c.startswith("subj_"))
    traits = [c for c in meta.columns if c.startswith("subj_")]
    return motions, meta[list(CONTRACT_COLUMNS) + extras + traits]
