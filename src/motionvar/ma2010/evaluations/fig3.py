"""Ma et al. 2010 Fig. 3, Sec. 4.1: S_M(t) and its key frames for a walk and a run; the
claim checks over every walk and run of a dataset that the maxima of S_M(t) (the legs
farthest apart) fall at one phase of the step (between a foot strike and the next), so
that the key frames cut every cycle at the same gait phase."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import pandas as pd

from ...claims import Claim, EvaluationResult, verdict_threshold
from ...core.joint_map import JointMap
from ...core.motion import Motion
from ...prep.contacts import detect_foot_contacts
from ...prep.intervals import parse_intervals
from ..examples import extract_cycles, rows_matching
from .common import PAPER, PROTOCOL

GERUNDS = {"walk": "walking", "run": "running"}  # claim statements: "the key frames of running"


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


def fig3_keyframes(
    dataset,
    joint_map: JointMap,
    walk_styles: str | Sequence[str] = (),
    walk_variants: str | Sequence[str] = (),
    min_prominence: float = 0.1,
    min_separation_s: float = 0.1,
    max_clips: int = 0,
    phase_sd_bound: float = 0.05,
    what: str = "metadata",
) -> EvaluationResult:
    """Fig. 3 on a dataset (``motionvar.io.MotionDataset``): the key frames of the first
    walk (of the given styles and variants) and the first run as the table, and per
    behaviour a claim on the circular SD of the maxima's phase within the step over its
    first ``max_clips`` clips (0: all), reproduced at most ``phase_sd_bound``. ``what``
    names the metadata in errors. A behaviour whose clips hold no maximum between two foot
    strikes gets its claim with verdict ``not applicable`` and the reason. Figure: ``shown``
    (behaviour -> clip id, motion, its :class:`CycleExtraction`, foot strikes) and
    ``strike_source`` (behaviour -> "ground truth" or "detected": the shown clip's strikes)."""
    meta = dataset.metadata
    walks = rows_matching(meta, behaviour="walk", style=walk_styles, variant=walk_variants, what=what)
    runs = np.flatnonzero(meta["behaviour"].astype(str).to_numpy() == "run")
    limit = max_clips or None
    rows, counts, shown, strike_source, shown_source, missing = [], {}, {}, {}, {}, {}
    for behaviour, idx in (("walk", walks), ("run", runs)):
        phases, offsets = [], []
        n_maxima = n_struck = 0
        truth = [has_true_contacts(meta.iloc[int(i)]) for i in idx[:limit]]
        if len(truth):
            strike_source[behaviour] = "ground truth" if all(truth) else "detected" if not any(truth) else "mixed"
        for k, i in enumerate(idx[:limit]):  # loop over clips
            m = dataset.motion(int(i))
            ex = extract_cycles(m, joint_map, min_prominence, min_separation_s)
            strikes = foot_strikes(meta.iloc[int(i)], m, joint_map)
            maxima = ex.frames[ex.kinds == 1]
            n_maxima, n_struck = n_maxima + len(maxima), n_struck + int(len(strikes) >= 2)
            if len(strikes) and len(maxima):
                diff = maxima[:, None] - strikes[None, :]
                offsets.extend((diff[np.arange(len(maxima)), np.abs(diff).argmin(axis=1)] / m.fps).tolist())
                phases.extend(step_phases(maxima, strikes).tolist())
            if k == 0:
                shown[behaviour] = (meta["clip_id"].iloc[int(i)], m, ex, strikes)
                shown_source[behaviour] = "ground truth" if truth[0] else "detected"
                for f, kind in zip(ex.frames, ex.kinds):
                    near = np.abs(strikes - f).min() / m.fps if len(strikes) else np.nan
                    rows.append(
                        {
                            "clip_id": meta["clip_id"].iloc[int(i)],
                            "behaviour": behaviour,
                            "frame": int(f),
                            "time_s": f / m.fps,
                            "extremum": "max" if kind == 1 else "min",
                            "S_M": float(ex.signal.signal[f]),
                            "to_foot_strike_s": near,
                            "D_l": ex.signal.d_lower,
                            "D_u": ex.signal.d_upper,
                            "part": ex.signal.part,
                        }
                    )
        if phases:
            counts[behaviour] = (circular_sd(phases), len(phases), float(np.median(offsets)))
        elif len(idx):
            n = len(idx[:limit])
            missing[behaviour] = (
                f"none of the {n} {behaviour} clips has a maximum of S_M(t) (legs farthest apart) between two foot "
                f"strikes: {n_struck} of them have two or more {strike_source[behaviour]} foot strikes, {n_maxima} "
                "maxima in all; the claim measures where in the step the maxima fall, so it needs clips holding at "
                "least one whole step, from a foot strike to the next"
            )

    claims = []
    for behaviour in ("walk", "run"):
        common = dict(
            claim_id=f"{PAPER}.fig3.{behaviour}_keyframes_at_one_gait_phase",
            paper=PAPER,
            source="Fig. 3, Sec. 4.1-4.2",
            statement=f"The key frames (extrema of S_M(t)) of {GERUNDS.get(behaviour, behaviour)} fall at the same gait phase in every "
            "step, so they can segment and time-warp the motion.",
            published="each local extremum of S_M(t) is a key frame, used to cut and time-warp clips (no number given)",
        )
        if behaviour in missing:
            claims.append(Claim(**common, measured="-", verdict="not applicable", note=missing[behaviour]))
            continue
        if behaviour not in counts:
            continue
        sd, n, offset = counts[behaviour]
        source = {
            "ground truth": "generator ground truth",
            "detected": "detected from foot contacts, motionvar.prep",
            "mixed": "ground truth where the metadata has it, else detected",
        }[strike_source[behaviour]]
        claims.append(
            Claim(
                **common,
                measured=f"circular SD of the maxima's phase within the step: {sd:.3f} of a step over {n} maxima; median "
                f"offset from the nearest foot strike {offset * 1000:+.0f} ms",
                verdict=verdict_threshold(sd, phase_sd_bound, "<=", tolerance=1.0),
                value=sd,
                bound=phase_sd_bound,
                unit="step",
                direction="<=",
                note=f"Reproduced when the SD is at most {phase_sd_bound:g} of a step (partial: twice that; our bound, the "
                f"paper gives none). Steps run from one foot strike ({source}) to the next. {PROTOCOL}",
            )
        )
    return EvaluationResult(
        table=pd.DataFrame(rows), claims=claims, figure={"shown": shown, "strike_source": shown_source}
    )
