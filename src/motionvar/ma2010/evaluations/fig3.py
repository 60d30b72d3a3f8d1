"""Ma et al. 2010 Fig. 3, Sec. 4.1: S_M(t) and its key frames for a walk and a run; the
claim checks over every walk and run of a dataset that the maxima of S_M(t) (the legs
farthest apart) fall at one phase of the step (between a foot strike and the next), so
that the key frames cut every cycle at the same gait phase."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import pandas as pd

from ...claims import EvaluationResult, judge_claims
from ...core.joint_map import JointMap
from ...core.motion import Motion
from ...prep.contacts import detect_foot_contacts
from ...prep.intervals import parse_intervals
from ..claims import CLAIMS
from ..examples import extract_cycles, rows_matching
from ..settings import Ma2010Settings


def step_phases(maxima: np.ndarray, strikes: np.ndarray) -> np.ndarray:
    """Phase in [0, 1) of each maximum within its step (previous strike -> next strike);
    maxima outside the first and last strike are left out."""
    k = np.searchsorted(strikes, maxima, side="right") - 1
    ok = (k >= 0) & (k + 1 < len(strikes))
    k = k[ok]
    return (maxima[ok] - strikes[k]) / (strikes[k + 1] - strikes[k])


def circular_sd(phases) -> float:
    """Circular standard deviation of phases in [0, 1), in units of one step."""
    r = np.abs(np.mean(np.exp(2j * np.pi * np.asarray(phases))))
    return float(np.sqrt(-2.0 * np.log(max(r, 1e-12))) / (2 * np.pi))


def has_true_contacts(row: pd.Series) -> bool:
    """Whether a clip's metadata row holds ground-truth contact intervals (synthetic data)."""
    return all(f"{s}_contacts" in row and isinstance(row[f"{s}_contacts"], str) for s in ("left", "right"))


def foot_strikes(row: pd.Series, motion: Motion, joint_map: JointMap) -> np.ndarray:
    """Foot-strike frames of a clip: the generator's ground truth when its metadata row
    has contact intervals, else detected (motionvar.prep)."""
    if has_true_contacts(row):
        starts = [parse_intervals(row[f"{s}_contacts"], f"{s}_contacts")[:, 0] for s in ("left", "right")]
    else:
        c = detect_foot_contacts(motion, joint_map)
        starts = [c.intervals(s)[:, 0] for s in ("left", "right")]
    all_starts = np.sort(np.concatenate(starts))
    return all_starts[all_starts > 0]


@dataclass
class BehaviourScan:
    """What :func:`scan_behaviour` finds over the clips of one behaviour: the phase of every
    maximum within its step and its offset from the nearest foot strike (s), the counts of
    maxima and of clips with two or more strikes, where the strikes came from (all clips;
    the shown first clip), and the first clip's key frames as table rows with what Fig. 3
    shows of it."""

    phases: list = field(default_factory=list)
    offsets: list = field(default_factory=list)
    n_maxima: int = 0
    n_struck: int = 0
    strike_source: str | None = None
    shown_source: str | None = None
    rows: list = field(default_factory=list)
    shown: tuple | None = None


def keyframe_rows(clip_id: str, behaviour: str, motion: Motion, ex, strikes: np.ndarray) -> list[dict]:
    """One table row per key frame of the shown clip: frame, time, kind, S_M, time to the
    nearest foot strike and the signal's D_l, D_u and part (Eq. 3-4)."""
    rows = []
    for f, kind in zip(ex.frames, ex.kinds):
        near = np.abs(strikes - f).min() / motion.fps if len(strikes) else np.nan
        rows.append(
            {
                "clip_id": clip_id,
                "behaviour": behaviour,
                "frame": int(f),
                "time_s": f / motion.fps,
                "extremum": "max" if kind == 1 else "min",
                "S_M": float(ex.signal.signal[f]),
                "to_foot_strike_s": near,
                "D_l": ex.signal.d_lower,
                "D_u": ex.signal.d_upper,
                "part": ex.signal.part,
            }
        )
    return rows


def scan_behaviour(
    dataset, idx: np.ndarray, behaviour: str, joint_map: JointMap, settings: Ma2010Settings
) -> BehaviourScan:
    """Key frames (``settings`` keyframe_prominence, keyframe_min_separation_s) and foot
    strikes of the first ``settings.fig3.max_clips`` clips ``idx`` (0: all) of one behaviour."""
    meta = dataset.metadata
    clips = idx[: settings.fig3.max_clips or None]
    scan = BehaviourScan()
    truth = [has_true_contacts(meta.iloc[int(i)]) for i in clips]
    if len(truth):
        scan.strike_source = "ground truth" if all(truth) else "detected" if not any(truth) else "mixed"
    for k, i in enumerate(clips):  # loop over clips
        m = dataset.motion(int(i))
        ex = extract_cycles(m, joint_map, settings.clips.keyframe_prominence, settings.clips.keyframe_min_separation_s)
        strikes = foot_strikes(meta.iloc[int(i)], m, joint_map)
        maxima = ex.frames[ex.kinds == 1]
        scan.n_maxima, scan.n_struck = scan.n_maxima + len(maxima), scan.n_struck + int(len(strikes) >= 2)
        if len(strikes) and len(maxima):
            diff = maxima[:, None] - strikes[None, :]
            scan.offsets.extend((diff[np.arange(len(maxima)), np.abs(diff).argmin(axis=1)] / m.fps).tolist())
            scan.phases.extend(step_phases(maxima, strikes).tolist())
        if k == 0:
            scan.shown = (meta["clip_id"].iloc[int(i)], m, ex, strikes)
            scan.shown_source = "ground truth" if truth[0] else "detected"
            scan.rows = keyframe_rows(meta["clip_id"].iloc[int(i)], behaviour, m, ex, strikes)
    return scan


def behaviour_measurements(scan: BehaviourScan, n_clips: int) -> dict:
    """What Fig. 3's claim on one behaviour is judged on (``motionvar.ma2010.claims``): the circular
    SD of its maxima's phase within the step and their median offset from the nearest foot strike
    (NaN without a maximum between two strikes), the counts of clips scanned, of clips with two or
    more strikes, of maxima and of maxima between two strikes, and where the strikes came from."""
    return {
        "phase_sd": circular_sd(scan.phases) if scan.phases else float("nan"),
        "median_offset_s": float(np.median(scan.offsets)) if scan.offsets else float("nan"),
        "clips": n_clips,
        "clips_with_strikes": scan.n_struck,
        "maxima": scan.n_maxima,
        "maxima_in_steps": len(scan.phases),
        "strike_source": scan.strike_source,
    }


def fig3_keyframes(dataset, joint_map: JointMap, settings: Ma2010Settings, what: str = "metadata") -> EvaluationResult:
    """Fig. 3 on a dataset (``motionvar.io.MotionDataset``): the key frames of the first
    walk (of ``settings`` walk_styles and walk_variants) and the first run as the table,
    and per behaviour a claim on the circular SD of the maxima's phase within the step over
    its first ``settings.fig3.max_clips`` clips (0: all), reproduced at most
    ``settings.fig3.phase_sd`` (measurements: :func:`behaviour_measurements` per behaviour).
    ``what`` names the metadata in errors. A behaviour without clips, or whose clips hold no
    maximum between two foot strikes, gets its claim with verdict ``not applicable`` and the
    reason. Figure: ``shown`` (behaviour -> clip id, motion, its
    :class:`CycleExtraction`, foot strikes) and ``strike_source`` (behaviour -> "ground
    truth" or "detected": the shown clip's strikes)."""
    meta = dataset.metadata
    walks = rows_matching(
        meta, behaviour="walk", style=settings.clips.walk_styles, variant=settings.clips.walk_variants, what=what
    )
    runs = np.flatnonzero(meta["behaviour"].astype(str).to_numpy() == "run")
    rows, shown, shown_source, behaviours = [], {}, {}, {}
    for behaviour, idx in (("walk", walks), ("run", runs)):
        scan = scan_behaviour(dataset, idx, behaviour, joint_map, settings)
        rows += scan.rows
        if scan.shown is not None:
            shown[behaviour], shown_source[behaviour] = scan.shown, scan.shown_source
        if len(idx):  # a behaviour without clips has no claim
            behaviours[behaviour] = behaviour_measurements(scan, len(idx[: settings.fig3.max_clips or None]))
    measurements = {
        "behaviours": behaviours,
        "phase_sd_bound": settings.fig3.phase_sd,
        "max_clips": settings.fig3.max_clips,
    }
    claims = judge_claims(CLAIMS, "ma2010_fig3", measurements)
    figure = {"shown": shown, "strike_source": shown_source}
    return EvaluationResult(pd.DataFrame(rows), claims, figure, measurements)
