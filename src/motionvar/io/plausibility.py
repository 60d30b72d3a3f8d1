"""Sanity gates on imported motion, before any result is computed from it: is this a
human body, in centimetres, with its pelvis where the joint map says?

A wrong ``unit_cm``, a joint map whose ``hips`` names a ground-projected root, a frame
time in the wrong unit or mislabelled behaviours do not crash anything downstream: they
give numbers, and verdicts, about garbage. :func:`check_plausibility` measures every clip
(:func:`clip_measures`) and returns one problem per gate whose median over the clips lies
outside the human range (NaN and frame rate: any clip), each naming what is wrong and what
to change. Speeds are checked only when the other gates pass: a wrong unit, frame time or
hips joint makes them wrong too, and the first cause is the one to fix.

Bounds (generous on purpose: they catch a wrong unit, joint or label, not an unusual
person), in the style of docs/gait.md:

- Pelvis height above the floor: the hip joint stands at about 0.53 x stature (Winter,
  *Biomechanics and Motor Control of Human Movement*, 2009, Fig. 4.1, after Drillis &
  Contini), 80-106 cm for adults of 150-200 cm; walking, stylised and crouching motion
  lower it. Bound 60-130 cm for the median over frames. The floor is a low percentile
  (:data:`FLOOR_PERCENTILE`) of the lowest ankle or toe joint per frame (not height 0:
  some captures put the floor elsewhere); a rig without toe joints gives the ankles' End
  Sites instead (:func:`motionvar.core.extremities.foot_points`).
- Leg length, hip joint to ankle joint (thigh + shank): 0.245 + 0.246 = 0.49 x stature
  (Winter 2009), 74-98 cm for 150-200 cm. Bound 50-120 cm.
- The pelvis stands over the feet: its horizontal distance to the mean of the two
  ankles stays within about half a stride (running strides 2-3.5 m are split between
  the feet, so the mean of the ankles stays near the pelvis; docs/gait.md). Bound
  60 cm for the median over frames.
- Frame rate 10-1,000 fps (motion capture runs at 30-480; animation exports at 24-60).
- Speed of the root path (horizontal path of the hips, sampled at 10 Hz, over the clip's
  duration), per behaviour: walk 0.2-3 m/s (comfortable 1.2-1.5 m/s, Perry & Burnfield
  2010; slow and elderly walks 0.4-1.0 m/s, Bohannon, "Comfortable and maximum walking
  speed of adults aged 20-79 years", 1997; the walk-run transition at about 2 m/s,
  Hreljac 1993); run 1-10 m/s (jogging from 2.5 m/s, Novacheck 1998; stylised and
  tired runs slower; sprinters reach 10-12 m/s); sidestep 0.1-3 m/s (slower cadence
  than walking, steps of 30-60 cm); idle at most 0.5 m/s (postural sway moves the pelvis
  by centimetres per second, Winter 2009). Picks and places may step or stand: no bound.
- No NaN or infinite value in positions or rotations.
"""

from __future__ import annotations

import logging
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import pandas as pd

from ..core.extremities import foot_points, toe_stand_in
from ..core.joint_map import JointMap
from ..core.motion import Motion

log = logging.getLogger(__name__)

PELVIS_HEIGHT_CM = (60.0, 130.0)
LEG_LENGTH_CM = (50.0, 120.0)
PELVIS_OFF_CENTRE_CM = 60.0
FPS = (10.0, 1000.0)
SPEED_M_S = {"walk": (0.2, 3.0), "run": (1.0, 10.0), "sidestep": (0.1, 3.0), "idle": (0.0, 0.5)}
FLOOR_PERCENTILE = 2.0
PATH_RATE_HZ = 10.0
TYPICAL_LEG_CM = 85.0  # for the unit hint: the leg of a 175 cm adult

MEASURES = ("fps", "pelvis_height_cm", "leg_length_cm", "pelvis_off_centre_cm", "speed_m_s", "finite")


def clip_measures(motion: Motion, joint_map: JointMap) -> dict[str, float]:
    """The gated quantities of one clip (see the module docstring): fps, pelvis height
    above the floor, leg length, horizontal pelvis-to-ankles distance (medians over frames,
    cm), root path speed (m/s) and whether every value is finite."""
    sk = motion.skeleton
    pos = motion.positions()
    finite = bool(np.isfinite(pos).all() and np.isfinite(motion.rotations).all())
    pos = np.nan_to_num(pos)
    chain = [f"{side}_{part}" for side in ("left", "right") for part in ("hip", "knee", "ankle")]
    j = {s: joint_map.index(sk, s) for s in ("hips", *chain)}
    feet = foot_points(motion, joint_map, pos)[..., 1].reshape(len(pos), 4)  # ankles and toes (or End Sites)
    floor = np.percentile(feet.min(axis=1), FLOOR_PERCENTILE)
    hips = pos[:, j["hips"]]
    legs = [
        np.linalg.norm(pos[:, j[f"{s}_hip"]] - pos[:, j[f"{s}_knee"]], axis=-1)
        + np.linalg.norm(pos[:, j[f"{s}_knee"]] - pos[:, j[f"{s}_ankle"]], axis=-1)
        for s in ("left", "right")
    ]
    ankles = 0.5 * (pos[:, j["left_ankle"]] + pos[:, j["right_ankle"]])
    off = np.linalg.norm((hips - ankles)[:, [0, 2]], axis=-1)
    step = max(1, int(round(motion.fps / PATH_RATE_HZ)))
    path = hips[::step, [0, 2]]
    if (motion.n_frames - 1) % step:
        path = np.vstack([path, hips[-1:, [0, 2]]])
    length_cm = np.linalg.norm(np.diff(path, axis=0), axis=-1).sum()
    speed = length_cm / 100.0 / motion.duration if motion.n_frames > 1 else 0.0
    return {
        "fps": float(motion.fps),
        "pelvis_height_cm": float(np.median(hips[:, 1]) - floor),
        "leg_length_cm": float(np.median(np.concatenate(legs))),
        "pelvis_off_centre_cm": float(np.median(off)),
        "speed_m_s": float(speed),
        "finite": finite,
    }


@dataclass
class PlausibilityReport:
    """Per-clip measures (``clip_id``, ``behaviour`` and :data:`MEASURES`) and the problems
    found (empty: the data passes)."""

    measures: pd.DataFrame
    problems: list[str]

    def summary(self) -> str:
        """One line per gate: median and range over the clips (per behaviour for speeds)."""
        m = self.measures
        lines = [f"plausibility over {len(m)} clips: median (min-max)"]
        for col, unit in (
            ("pelvis_height_cm", "cm"),
            ("leg_length_cm", "cm"),
            ("pelvis_off_centre_cm", "cm"),
            ("fps", "fps"),
        ):
            lines.append(f"  {col}: {m[col].median():.1f} {unit} ({m[col].min():.1f}-{m[col].max():.1f})")
        for b, g in m.groupby("behaviour", sort=True):
            s = g["speed_m_s"]
            lines.append(f"  speed {b} ({len(g)} clips): {s.median():.2f} m/s ({s.min():.2f}-{s.max():.2f})")
        return "\n".join(lines)


def _where(joint_map: JointMap) -> str:
    return joint_map.origin if joint_map.origin else "joint_map: null, the CMU 31-joint rig"


def _unit_hint(leg_cm: float, unit_cm: float | None) -> str:
    if unit_cm is None or not leg_cm > 0:
        return "check the length unit"
    better = unit_cm * TYPICAL_LEG_CM / leg_cm
    return f"check unit_cm (now {unit_cm:g} cm per file unit; about {better:.3g} gives legs of {TYPICAL_LEG_CM:g} cm)"


def _outside(values: pd.Series, lo: float, hi: float) -> int:
    return int(((values < lo) | (values > hi)).sum())


def check_plausibility(
    motions: Sequence[Motion],
    metadata: pd.DataFrame,
    joint_map: JointMap,
    unit_cm: float | None = None,
) -> PlausibilityReport:
    """Measure every clip and list the gates that fail (module docstring). ``metadata``
    gives ``clip_id`` and ``behaviour`` per clip; ``unit_cm`` (the import's unit, if any)
    makes the unit hint concrete."""
    if motions and (stand_in := toe_stand_in(joint_map, motions[0])):
        log.info("%s (the floor)", stand_in)
    rows = [clip_measures(m, joint_map) for m in motions]
    meas = pd.DataFrame(rows, columns=list(MEASURES))
    meas.insert(0, "behaviour", metadata["behaviour"].astype(str).to_numpy())
    meas.insert(0, "clip_id", metadata["clip_id"].astype(str).to_numpy())
    problems: list[str] = []
    n = len(meas)
    bad = meas.loc[~meas["finite"], "clip_id"].tolist()
    if bad:
        problems.append(
            f"NaN or infinite positions in {len(bad)}/{n} clips ({', '.join(bad[:5])}): check those BVH files"
        )
    bad = meas.loc[(meas["fps"] < FPS[0]) | (meas["fps"] > FPS[1])]
    if len(bad):
        problems.append(
            f"frame rate {bad['fps'].iloc[0]:.4g} fps in {len(bad)}/{n} clips ({bad['clip_id'].iloc[0]}, "
            f"...); motion capture runs at {FPS[0]:g}-{FPS[1]:,.0f} fps: check the BVH 'Frame Time' "
            f"(seconds per frame)"
        )
    leg = meas["leg_length_cm"].median()
    leg_ok = LEG_LENGTH_CM[0] <= leg <= LEG_LENGTH_CM[1]
    hips_name = joint_map.joints["hips"]
    if not leg_ok:
        lo, hi = LEG_LENGTH_CM
        problems.append(
            f"leg (joint map {joint_map.joints['left_hip']} to {joint_map.joints['left_ankle']}) is {leg:.1f} cm long "
            f"(median; {_outside(meas['leg_length_cm'], lo, hi)}/{n} clips outside {lo:g}-{hi:g} cm); a human leg "
            f"is {lo:g}-{hi:g} cm from hip to ankle: {_unit_hint(leg, unit_cm)}, and the joint map's hip, knee "
            f"and ankle joints ({_where(joint_map)})"
        )
    height = meas["pelvis_height_cm"].median()
    lo, hi = PELVIS_HEIGHT_CM
    if not lo <= height <= hi:
        fix = f"check the joint map's 'hips' ({_where(joint_map)})" if leg_ok else "see the leg length"
        problems.append(
            f"pelvis (joint map hips = {hips_name}) is {height:.1f} cm above the floor (median; "
            f"{_outside(meas['pelvis_height_cm'], lo, hi)}/{n} clips outside {lo:g}-{hi:g} cm); a standing human "
            f"pelvis is {lo:g}-{hi:g} cm high: {fix}"
        )
    off = meas["pelvis_off_centre_cm"].median()
    if not off <= PELVIS_OFF_CENTRE_CM:
        n_out = int((meas["pelvis_off_centre_cm"] > PELVIS_OFF_CENTRE_CM).sum())
        problems.append(
            f"pelvis (joint map hips = {hips_name}) is {off:.1f} cm away from the feet horizontally (median; "
            f"{n_out}/{n} clips over {PELVIS_OFF_CENTRE_CM:g} cm); a human pelvis stands over the mean of the "
            f"ankles, within {PELVIS_OFF_CENTRE_CM:g} cm: check the joint map's 'hips' and ankles ({_where(joint_map)})"
        )
    if problems:  # speeds follow from the unit, the frame time and the hips: fix those first
        return PlausibilityReport(meas, problems)
    for behaviour, (lo, hi) in SPEED_M_S.items():
        s = meas.loc[meas["behaviour"] == behaviour, "speed_m_s"]
        if len(s) and not lo <= s.median() <= hi:
            problems.append(
                f"{behaviour} clips move at {s.median():.2f} m/s (median of the root path speed; "
                f"{_outside(s, lo, hi)}/{len(s)} clips outside {lo:g}-{hi:g} m/s); a human {behaviour} moves at "
                f"{lo:g}-{hi:g} m/s: check the labels' behaviour column (and behaviour_aliases) and the BVH "
                f"'Frame Time'"
            )
    return PlausibilityReport(meas, problems)


class PlausibilityError(ValueError):
    """Imported motion that fails a sanity gate; the message lists every problem."""


def plausibility_gate(
    motions: Sequence[Motion],
    metadata: pd.DataFrame,
    joint_map: JointMap,
    unit_cm: float | None = None,
    enabled: bool = True,
) -> PlausibilityReport | None:
    """:func:`check_plausibility`, its summary logged; :class:`PlausibilityError` (one line,
    the problems joined by "; ") if any gate fails. ``enabled=False`` (config
    ``plausibility_check: false``, expert use) skips it, with a warning; returns None."""
    if not enabled:
        log.warning("plausibility checks switched off (plausibility_check: false)")
        return None
    report = check_plausibility(motions, metadata, joint_map, unit_cm)
    log.info("%s", report.summary())
    if report.problems:
        raise PlausibilityError(
            "; ".join(report.problems) + " (if the data is right after all, "
            "plausibility_check: false skips these checks)"
        )
    return report
