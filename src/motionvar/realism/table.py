"""The realism table of a packed dataset: one row per statistic (docs/gait.md, "Realism").

Walk statistics come from the clips whose behaviour is ``walk`` (foot contacts detected with
the preprocessing options, the same on every dataset, ground truth unused); reach statistics
from the reaching phase of ``pick`` clips (start to the hands' rest at the target,
:func:`~motionvar.prep.segmentation.reach_boundary`); channel statistics from the local
rotations of every joint but the root (whose yaw is the heading) over all frames of a behaviour.
A walk's gait events count only where they are plausibly a walk's
(:func:`~motionvar.metrics.realism.implausible_events`); the others are left out of every
statistic built on them, and the ``note`` column says how many and why. A statistic the data
cannot give (no walk of three plausible strides, too few subjects or reaches) has no value,
``n`` 0 and its reason in ``note``.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field

import numpy as np
import pandas as pd

from ..core.extremities import foot_points
from ..core.joint_map import JointMap
from ..core.motion import Motion
from ..core.quaternions import quat_to_rotvec
from ..io.dataset import MotionDataset
from ..metrics import realism as rm
from ..metrics import standing
from ..prep.contacts import detect_foot_contacts
from ..prep.options import PrepOptions
from ..prep.segmentation import hand_speed, reach_boundary
from .bands import CMU_CAPTURED_CHANNELS
from .settings import RealismSettings

COLUMNS = ("statistic", "behaviour", "value", "unit", "n", "description", "note")
JOINT_COLUMNS = ("behaviour", "joint", "sd_x_deg", "sd_y_deg", "sd_z_deg", "max_sd_deg", "classes")


@dataclass
class _WalkStats:
    """Per-clip walk statistics, collected over a dataset's walks."""

    stride_cv: list[float] = field(default_factory=list)
    stride_time_cv: list[float] = field(default_factory=list)
    step_time_cv: list[float] = field(default_factory=list)
    stance_sd: list[float] = field(default_factory=list)
    asym_cm: list[float] = field(default_factory=list)
    asym_pct: list[float] = field(default_factory=list)
    clearance: list[np.ndarray] = field(default_factory=list)
    noise: list[float] = field(default_factory=list)
    n_strides: int = 0
    left_out: dict[str, int] = field(default_factory=dict)  # reason -> walks whose events fail

    def note(self) -> str:
        """How many walks' events were left out, and why."""
        if not self.left_out:
            return ""
        n = sum(self.left_out.values())
        reasons = "; ".join(f"{k}: {v}" for k, v in sorted(self.left_out.items(), key=lambda kv: -kv[1]))
        return f"{n} of {n + len(self.stride_cv)} walks' gait events left out as implausible ({reasons})"


def _walk_clip(stats: _WalkStats, motion: Motion, joint_map: JointMap, prep: PrepOptions, s: RealismSettings) -> float:
    """Add one walk's statistics to ``stats``; its mean steady stride (NaN without one)."""
    raw = motion.positions()
    contacts = detect_foot_contacts(motion, joint_map, prep, raw)
    pos = raw * prep.units_cm
    ankles = tuple(int(i) for i in joint_map.indices(motion.skeleton, ["left_ankle", "right_ankle"]))
    toes = foot_points(motion, joint_map, raw)[:, :, 1, 1] * prep.units_cm  # (T, 2) toe heights (or End Sites')
    cycles = rm.walk_cycles(rm.walk_events(pos, (contacts.left, contacts.right), ankles, motion.fps))
    stats.noise.append(rm.high_frequency_rms(pos - pos[:, :1], motion.fps, s.noise_band_hz))
    clearance = [
        rm.toe_clearance(toes[:, side], mask, s.toe_window) for side, mask in enumerate((contacts.left, contacts.right))
    ]
    reason = rm.implausible_events(
        cycles, pos[:, 0, [0, 2]], np.concatenate(clearance), s.stance_range, s.travel_tolerance, s.min_clearance_cm
    )
    if reason:
        check = reason.split(":")[0]
        stats.left_out[check] = stats.left_out.get(check, 0) + 1
        return float("nan")
    stats.stride_cv.append(rm.coefficient_of_variation(cycles.stride_length))
    stats.stride_time_cv.append(rm.coefficient_of_variation(cycles.stride_time))
    stats.step_time_cv.append(rm.coefficient_of_variation(cycles.step_time))
    stats.stance_sd.append(
        float(np.std(cycles.stance_fraction, ddof=1)) if len(cycles.stance_fraction) >= 3 else np.nan
    )
    asym = rm.step_asymmetry(cycles)
    stats.asym_cm.append(asym)
    stats.asym_pct.append(asym / float(np.mean(cycles.step_length)) if np.isfinite(asym) else np.nan)
    stats.clearance += clearance
    stats.n_strides += len(cycles.stride_length)
    return float(np.mean(cycles.stride_length)) if len(cycles.stride_length) else float("nan")


def _reach_clip(motion: Motion, joint_map: JointMap, prep: PrepOptions, s: RealismSettings) -> tuple[int, float]:
    """(speed peaks, hand path ratio) of a pick clip's reach, from its start to the hands' rest."""
    pos = motion.positions()
    speed = hand_speed(motion, joint_map, pos, prep)
    stop = max(reach_boundary(speed, prep.hand_stop_fraction, prep.hand_rest_fraction), 2)
    hands = joint_map.indices(motion.skeleton, ["left_hand", "right_hand"])
    return rm.speed_peaks(speed[:stop], s.peak_prominence), rm.path_ratio(pos[:stop, hands].mean(axis=1))


def _median(values: Iterable[float]) -> float:
    x = np.asarray(list(values), dtype=float)
    x = x[np.isfinite(x)]
    return float(np.median(x)) if len(x) else float("nan")


def _count(values: Iterable[float]) -> int:
    return int(np.isfinite(np.asarray(list(values), dtype=float)).sum())


def _walk_rows(st: _WalkStats) -> list[tuple]:
    clear = np.concatenate(st.clearance) if st.clearance else np.zeros(0)
    pct = lambda v: [100.0 * x for x in v]  # noqa: E731
    cv_need = "no walk of 3 plausible strides"
    left_out = st.note()  # the statistics built on gait events say which walks they leave out
    rows = [
        (
            "stride_cv_pct",
            _median(pct(st.stride_cv)),
            "%",
            _count(st.stride_cv),
            "stride length: SD over mean within a walk (median over walks)",
            cv_need,
            left_out,
        ),
        (
            "stride_time_cv_pct",
            _median(pct(st.stride_time_cv)),
            "%",
            _count(st.stride_time_cv),
            "stride time: SD over mean within a walk",
            cv_need,
            left_out,
        ),
        (
            "step_time_cv_pct",
            _median(pct(st.step_time_cv)),
            "%",
            _count(st.step_time_cv),
            "step time: SD over mean within a walk",
            "no walk of 3 plausible steps",
            left_out,
        ),
        (
            "stance_fraction_sd_pct",
            _median(pct(st.stance_sd)),
            "% of cycle",
            _count(st.stance_sd),
            "gait-event jitter: SD of the toe-off's place in the cycle between strides of a walk",
            cv_need,
            left_out,
        ),
        (
            "step_asymmetry_cm",
            _median(st.asym_cm),
            "cm",
            _count(st.asym_cm),
            "|mean left step - mean right step| of a walk",
            "no walk of 2 plausible steps of each foot",
            left_out,
        ),
        (
            "step_asymmetry_pct",
            _median(pct(st.asym_pct)),
            "%",
            _count(st.asym_pct),
            "step asymmetry over the mean step",
            "no walk of 2 plausible steps of each foot",
            left_out,
        ),
        (
            "toe_clearance_median_cm",
            _median(clear),
            "cm",
            len(clear),
            "minimum toe clearance in mid-swing, median over swings",
            "no swing between plausible contacts",
            left_out,
        ),
        (
            "toe_clearance_p5_cm",
            float(np.percentile(clear, 5)) if len(clear) else np.nan,
            "cm",
            len(clear),
            "minimum toe clearance in mid-swing, 5th percentile",
            "no swing between plausible contacts",
            left_out,
        ),
        (
            "noise_rms_mm",
            10.0 * _median(st.noise),
            "mm",
            _count(st.noise),
            "RMS of root-relative joint positions in the noise band",
            "no walk long enough to filter",
            "",
        ),
        ("strides", float(st.n_strides), "", len(st.stride_cv), "steady strides measured", "", left_out),
    ]
    return [(s, "walk", v, u, n, d, _note(v, missing, why)) for s, v, u, n, d, missing, why in rows]


def _note(value: float, missing: str, otherwise: str) -> str:
    """``missing`` (why there is no value) for a NaN value, else ``otherwise``."""
    return (f"{missing}; {otherwise}" if otherwise else missing) if not np.isfinite(value) else otherwise


def _channel_rows(motions: list[Motion], behaviour: str, s: RealismSettings) -> tuple[list[tuple], list[tuple]]:
    rotations = np.concatenate([m.rotations[:, 1:] for m in motions])
    sd = rm.rotation_channel_sd(rotations)
    classes = rm.channel_classes(sd, s.static_deg, s.near_static_deg)
    n = classes.size
    rows = [
        (
            f"channels_{c.replace('-', '_')}_share",
            behaviour,
            float(np.mean(classes == c)),
            "share",
            n,
            f"share of non-root rotation channels that are {c}",
            "",
        )
        for c in ("static", "near-static", "moving")
    ]
    names = motions[0].skeleton.names[1:]
    if set(CMU_CAPTURED_CHANNELS) <= set(names):
        rows += _cmu_rows(dict(zip(names, classes)), behaviour)
    joints = [(behaviour, name, *sd[j], float(sd[j].max()), "/".join(classes[j])) for j, name in enumerate(names)]
    return rows, joints


def _cmu_rows(classes: dict[str, np.ndarray], behaviour: str) -> list[tuple]:
    """On the CMU rig: the shares of the channels captured walks move (hold still) that this
    data moves (holds static or near-static), against :data:`CMU_CAPTURED_CHANNELS`."""
    moved, kept = [], []
    for joint, captured in CMU_CAPTURED_CHANNELS.items():
        for mine, theirs in zip(classes[joint], captured):
            if theirs == "moving":
                moved.append(mine == "moving")
            elif theirs == "still":
                kept.append(mine != "moving")
    return [
        (
            "cmu_captured_moving_kept_share",
            behaviour,
            float(np.mean(moved)),
            "share",
            len(moved),
            "CMU rig: share of the channels captured walks move that move here",
            "",
        ),
        (
            "cmu_captured_static_kept_share",
            behaviour,
            float(np.mean(kept)),
            "share",
            len(kept),
            "CMU rig: share of the channels captured walks hold still that are (near-)static here",
            "",
        ),
    ]


def _spread_rows(
    strides: np.ndarray, stride_subject: np.ndarray, postures: np.ndarray, subject: np.ndarray, s: RealismSettings
) -> list[tuple]:
    """The within- against between-subject spread of a walk's mean stride and mean posture,
    over subjects with ``s.min_clips_per_subject`` walks; no value below ``s.min_subjects``."""
    rows = []
    for name, values, groups, what in (
        ("stride_within_between", strides, stride_subject, "a (neutral) walk's mean stride"),
        ("posture_within_between", postures, subject, "a walk's mean posture (joint rotation vectors)"),
    ):
        labels, counts = np.unique(groups, return_counts=True)
        k = int(np.sum(counts >= max(s.min_clips_per_subject, 2)))
        few = k < s.min_subjects
        value = np.nan if few else rm.within_between_ratio(values, groups, s.min_clips_per_subject)
        note = f"{k} subjects with {s.min_clips_per_subject} walks, fewer than realism.min_subjects = {s.min_subjects}"
        rows.append(
            (
                name,
                "walk",
                value,
                "ratio",
                0 if few else len(values),
                f"within-subject SD of {what} over the SD of subject means",
                note if few else "",
            )
        )
    return rows


def _idle_rows(
    motions: list[Motion], subjects: np.ndarray, joint_map: JointMap, prep: PrepOptions, s: RealismSettings
) -> list[tuple]:
    """Standing idle clips: the pelvis's sway (amplitude, the fast part beside the posture
    held, median frequency), the rate of weight shifts between the feet and the within-
    against between-person spread of the postures held (windows of ``s.idle_window_s``)."""
    sd, fast, freq, windows, groups = [], [], [], [], []
    shifts, minutes = 0, 0.0
    for m, subject in zip(motions, subjects):
        pos = m.positions() * prep.units_cm
        hips, la, ra = (pos[:, joint_map.index(m.skeleton, j), ::2] for j in ("hips", "left_ankle", "right_ankle"))
        sd.append(standing.sway_sd(hips))
        fast.append(10.0 * standing.sway_band_rms(hips, m.fps, s.idle_fast_hz))
        freq.append(standing.sway_median_frequency(hips, m.fps, s.idle_band_hz, s.idle_segment_s))
        shifts += standing.weight_shifts(standing.support_ratio(hips, la, ra), m.fps, s.idle_margin, s.idle_min_s)
        minutes += m.duration / 60.0
        n = max(1, int(round(s.idle_window_s * m.fps)))
        for a in range(0, m.n_frames - n + 1, n):
            windows.append(_posture(m.slice(a, a + n)))
            groups.append(subject)
    groups_arr = np.array(groups)
    people = int(np.sum(np.unique(groups_arr, return_counts=True)[1] >= 2)) if groups else 0
    few = people < s.min_idle_subjects
    ratio = np.nan if few else rm.within_between_ratio(np.array(windows), groups_arr)
    n = len(motions)
    return [
        (
            "idle_sway_sd_cm",
            "idle",
            _median(sd),
            "cm",
            _count(sd),
            "pelvis ground-plane SD about its mean (median over clips)",
            "",
        ),
        (
            "idle_sway_fast_rms_mm",
            "idle",
            _median(fast),
            "mm",
            _count(fast),
            f"pelvis ground-plane RMS above {s.idle_fast_hz:g} Hz: the small variations beside the posture held",
            "" if _count(fast) else "no clip long enough to filter",
        ),
        (
            "idle_sway_median_hz",
            "idle",
            _median(freq),
            "Hz",
            _count(freq),
            f"median frequency of the pelvis sway within {s.idle_band_hz[0]:g}-{s.idle_band_hz[1]:g} Hz",
            "" if _count(freq) else f"no clip of one {s.idle_segment_s:g} s Welch segment",
        ),
        (
            "idle_weight_shifts_per_min",
            "idle",
            shifts / minutes if minutes > 0 else np.nan,
            "per min",
            n,
            f"changes of the foot the pelvis stands over (held {s.idle_min_s:g} s, margin {s.idle_margin:g}), "
            "per minute over all clips",
            "",
        ),
        (
            "idle_posture_within_between",
            "idle",
            ratio,
            "ratio",
            0 if few else len(windows),
            f"within-person SD of a {s.idle_window_s:g} s window's mean posture over the SD of person means",
            f"{people} people with two windows, fewer than realism.min_idle_subjects = {s.min_idle_subjects}"
            if few
            else "",
        ),
    ]


def _posture(motion: Motion) -> np.ndarray:
    """A clip's mean posture: the mean rotation vector (degrees) of every non-root joint."""
    return np.degrees(quat_to_rotvec(motion.rotations[:, 1:]).mean(axis=0)).ravel()


def dataset_realism(
    dataset: MotionDataset,
    joint_map: JointMap,
    prep: PrepOptions | None = None,
    settings: RealismSettings | None = None,
) -> tuple[pd.DataFrame, pd.DataFrame]:
    """The realism table (one row per statistic, :data:`COLUMNS`) and the per-joint channel
    table (:data:`JOINT_COLUMNS`) of a dataset."""
    prep, s = prep or PrepOptions(), settings or RealismSettings()
    meta = dataset.metadata.reset_index(drop=True)
    behaviour = meta["behaviour"].astype(str).to_numpy()
    subjects = meta["subject"].astype(str).to_numpy()
    rows: list[tuple] = []
    joints: list[tuple] = []
    walks = np.flatnonzero(behaviour == "walk")
    style = meta["style"].astype(str).to_numpy() if "style" in meta else np.full(len(meta), "")
    spread_style = "neutral" if np.any(style[walks] == "neutral") else None
    st = _WalkStats()
    strides, postures, spread_subject = [], [], []  # the walks of one style, for the spread
    for i in walks:
        m = dataset.motion(int(i))
        stride = _walk_clip(st, m, joint_map, prep, s)
        if spread_style is None or style[i] == spread_style:
            strides.append(stride)
            postures.append(_posture(m))
            spread_subject.append(subjects[i])
    strides, spread_subject = np.array(strides), np.array(spread_subject)
    measured = np.isfinite(strides)
    if len(walks):
        rows += _walk_rows(st)
        rows += _spread_rows(strides[measured], spread_subject[measured], np.array(postures), spread_subject, s)
    picks = np.flatnonzero(behaviour == "pick")
    if len(picks) and joint_map.has("left_hand", "right_hand"):  # a rig without hands has no reach to measure
        reach = [_reach_clip(dataset.motion(int(i)), joint_map, prep, s) for i in picks]
        peaks = np.array([r[0] for r in reach], dtype=float)
        few = len(peaks) < s.min_reaches
        rows += [
            (
                "reach_speed_peaks",
                "pick",
                float(peaks.mean()),
                "peaks",
                len(peaks),
                "hand-speed peaks in a reach (mean)",
                "",
            ),
            (
                "reach_multi_peak_share",
                "pick",
                np.nan if few else float(np.mean(peaks >= 2)),
                "share",
                0 if few else len(peaks),
                "share of reaches with a corrective sub-movement (two or more speed peaks)",
                f"{len(peaks)} reaches, fewer than realism.min_reaches = {s.min_reaches}" if few else "",
            ),
            (
                "reach_path_ratio",
                "pick",
                _median(r[1] for r in reach),
                "ratio",
                len(reach),
                "hand path length over straight distance in a reach (median)",
                "",
            ),
        ]
    idle = np.flatnonzero(behaviour == "idle")
    if len(idle):
        rows += _idle_rows([dataset.motion(int(i)) for i in idle], subjects[idle], joint_map, prep, s)
    for name in ("walk", "pick", "idle"):
        idx = np.flatnonzero(behaviour == name)
        if len(idx):
            r, j = _channel_rows([dataset.motion(int(i)) for i in idx], name, s)
            rows += r
            joints += j
    return pd.DataFrame(rows, columns=list(COLUMNS)), pd.DataFrame(joints, columns=list(JOINT_COLUMNS))
