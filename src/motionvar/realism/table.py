"""The realism table of a packed dataset: one row per statistic (docs/gait.md, "Realism").

Walk statistics come from the clips whose behaviour is ``walk`` (foot contacts detected with
the preprocessing options, the same on every dataset, ground truth unused); reach statistics
from the reaching phase of ``pick`` clips (start to the hands' rest at the target,
:func:`~motionvar.prep.segmentation.reach_boundary`); channel statistics from the local
rotations of every joint but the root (whose yaw is the heading) over all frames of a behaviour.
A statistic the data cannot give (no walks of three steady strides, one subject) is NaN.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field

import numpy as np
import pandas as pd

from ..core.joint_map import JointMap
from ..core.motion import Motion
from ..core.quaternions import quat_to_rotvec
from ..io.dataset import MotionDataset
from ..metrics import realism as rm
from ..prep.contacts import detect_foot_contacts
from ..prep.options import PrepOptions
from ..prep.segmentation import hand_speed, reach_boundary
from .bands import CMU_CAPTURED_CHANNELS
from .settings import RealismSettings

COLUMNS = ("statistic", "behaviour", "value", "unit", "n", "description")
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


def _walk_clip(stats: _WalkStats, motion: Motion, joint_map: JointMap, prep: PrepOptions, s: RealismSettings) -> float:
    """Add one walk's statistics to ``stats``; its mean steady stride (NaN without one)."""
    raw = motion.positions()
    contacts = detect_foot_contacts(motion, joint_map, prep, raw)
    pos = raw * prep.units_cm
    ankles = tuple(int(i) for i in joint_map.indices(motion.skeleton, ["left_ankle", "right_ankle"]))
    toes = joint_map.indices(motion.skeleton, ["left_toe", "right_toe"])
    cycles = rm.walk_cycles(rm.walk_events(pos, (contacts.left, contacts.right), ankles, motion.fps))
    stats.stride_cv.append(rm.coefficient_of_variation(cycles.stride_length))
    stats.stride_time_cv.append(rm.coefficient_of_variation(cycles.stride_time))
    stats.step_time_cv.append(rm.coefficient_of_variation(cycles.step_time))
    stats.stance_sd.append(
        float(np.std(cycles.stance_fraction, ddof=1)) if len(cycles.stance_fraction) >= 3 else np.nan
    )
    asym = rm.step_asymmetry(cycles)
    stats.asym_cm.append(asym)
    stats.asym_pct.append(asym / float(np.mean(cycles.step_length)) if np.isfinite(asym) else np.nan)
    for side, mask in enumerate((contacts.left, contacts.right)):
        stats.clearance.append(rm.toe_clearance(pos[:, toes[side], 1], mask, s.toe_window))
    stats.noise.append(rm.high_frequency_rms(pos - pos[:, :1], motion.fps, s.noise_band_hz))
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
    return [
        (
            "stride_cv_pct",
            "walk",
            _median(pct(st.stride_cv)),
            "%",
            _count(st.stride_cv),
            "stride length: SD over mean within a walk (median over walks)",
        ),
        (
            "stride_time_cv_pct",
            "walk",
            _median(pct(st.stride_time_cv)),
            "%",
            _count(st.stride_time_cv),
            "stride time: SD over mean within a walk",
        ),
        (
            "step_time_cv_pct",
            "walk",
            _median(pct(st.step_time_cv)),
            "%",
            _count(st.step_time_cv),
            "step time: SD over mean within a walk",
        ),
        (
            "stance_fraction_sd_pct",
            "walk",
            _median(pct(st.stance_sd)),
            "% of cycle",
            _count(st.stance_sd),
            "gait-event jitter: SD of the toe-off's place in the cycle between strides of a walk",
        ),
        (
            "step_asymmetry_cm",
            "walk",
            _median(st.asym_cm),
            "cm",
            _count(st.asym_cm),
            "|mean left step - mean right step| of a walk",
        ),
        (
            "step_asymmetry_pct",
            "walk",
            _median(pct(st.asym_pct)),
            "%",
            _count(st.asym_pct),
            "step asymmetry over the mean step",
        ),
        (
            "toe_clearance_median_cm",
            "walk",
            _median(clear),
            "cm",
            len(clear),
            "minimum toe clearance in mid-swing, median over swings",
        ),
        (
            "toe_clearance_p5_cm",
            "walk",
            float(np.percentile(clear, 5)) if len(clear) else np.nan,
            "cm",
            len(clear),
            "minimum toe clearance in mid-swing, 5th percentile",
        ),
        (
            "noise_rms_mm",
            "walk",
            10.0 * _median(st.noise),
            "mm",
            _count(st.noise),
            "RMS of root-relative joint positions in the noise band",
        ),
        ("strides", "walk", float(st.n_strides), "", len(st.stride_cv), "steady strides measured"),
    ]


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
        ),
        (
            "cmu_captured_static_kept_share",
            behaviour,
            float(np.mean(kept)),
            "share",
            len(kept),
            "CMU rig: share of the channels captured walks hold still that are (near-)static here",
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
        rows.append(
            (
                "stride_within_between",
                "walk",
                rm.within_between_ratio(strides[measured], spread_subject[measured], s.min_clips_per_subject),
                "ratio",
                int(measured.sum()),
                "within-subject SD of a (neutral) walk's mean stride over the SD of subject means",
            )
        )
        rows.append(
            (
                "posture_within_between",
                "walk",
                rm.within_between_ratio(np.array(postures), spread_subject, s.min_clips_per_subject),
                "ratio",
                len(postures),
                "the same for a walk's mean posture (joint rotation vectors)",
            )
        )
    picks = np.flatnonzero(behaviour == "pick")
    if len(picks):
        reach = [_reach_clip(dataset.motion(int(i)), joint_map, prep, s) for i in picks]
        peaks = np.array([r[0] for r in reach], dtype=float)
        rows += [
            (
                "reach_speed_peaks",
                "pick",
                float(peaks.mean()),
                "peaks",
                len(peaks),
                "hand-speed peaks in a reach (mean)",
            ),
            (
                "reach_multi_peak_share",
                "pick",
                float(np.mean(peaks >= 2)),
                "share",
                len(peaks),
                "share of reaches with a corrective sub-movement (two or more speed peaks)",
            ),
            (
                "reach_path_ratio",
                "pick",
                _median(r[1] for r in reach),
                "ratio",
                len(reach),
                "hand path length over straight distance in a reach (median)",
            ),
        ]
    for name in ("walk", "pick"):
        idx = np.flatnonzero(behaviour == name)
        if len(idx):
            r, j = _channel_rows([dataset.motion(int(i)) for i in idx], name, s)
            rows += r
            joints += j
    return pd.DataFrame(rows, columns=list(COLUMNS)), pd.DataFrame(joints, columns=list(JOINT_COLUMNS))
