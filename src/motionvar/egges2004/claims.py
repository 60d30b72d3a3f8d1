"""The claims of Egges et al. 2004, in one place: what the paper states, where, the kind of
evidence our check is, the bound, and the function that judges each from its evaluation's
measurements (``motionvar.claims.ClaimSpec``). Evaluations return measurements; the verdicts
are computed here.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

from ..claims import ClaimSpec, Judgement, verdict_threshold

Measurements = Mapping[str, Any]


#: largest start / end joint-position error (cm) that counts as hitting the end postures exactly
EXACT_END_CM = 1e-6


def _fitting(m: Measurements) -> Judgement:
    """Sec. 5.4.4, 7.1, Fig. 4-5: with the paper's linear ramp, fitted animations start at p and end
    at q exactly and no junction step exceeds the recorded steps' quantile (partial: exact ends, but a
    junction jumps more than recorded motion does)."""
    end_err, step = m["max_end_error_cm"], m["max_junction_step_ratio"]
    exact, smooth_joins = end_err <= EXACT_END_CM, step["linear"] <= 1.0
    verdict = "reproduced" if exact and smooth_joins else ("partial" if exact else "not reproduced")
    accel = m["max_junction_accel_ratio"]
    return Judgement(
        verdict=verdict,
        measured=(
            f"largest start/end joint-position error {end_err:.1e} cm over {m['fits']} fits; "
            f"largest step at a junction = {step['linear']:.2f} x the {m['quantile']:.0%} quantile of steps inside "
            f"recorded shifts (smoothstep ramp: {step['smoothstep']:.2f}; second "
            f"differences: linear {accel['linear']:.2f}, smoothstep {accel['smoothstep']:.2f})"
        ),
        note=(
            "Errors are between the joint positions (forward kinematics) of the target posture and of the fitted "
            f"frame; junction steps are compared with the {m['quantile']:.0%} quantile of frame-to-frame steps "
            "inside the recorded balance shifts. Fig. 5's o_j = a_j - p_j is a sign slip (it would end at "
            "2a_j - p_j), so we use p_j - a_j as the text requires. The smoothstep ramp is our option beside the "
            "paper's linear one."
        ),
        value=step["linear"],
        bound=1.0,
        unit="ratio",
        direction="<=",
    )


def _identification(m: Measurements) -> Judgement:
    """Sec. 5.6, 8 (stand-in for an informal viewing test): windows of generated idle motion are
    named as their subject above chance (binomial p < alpha) and at least as well as those of the
    Perlin baseline (partial: above chance only)."""
    acc, subjects = m["accuracy"], m["subjects"]
    gen, per, rec = acc["generated"]["all"], acc["perlin"]["all"], acc["recorded"]["all"]
    p_gen = m["p_value_generated"]
    above = p_gen < m["alpha"]
    verdict = "reproduced" if above and gen >= per else ("partial" if above else "not reproduced")
    return Judgement(
        verdict=verdict,
        measured=(
            f"accuracy {gen:.2f} on generated windows (chance {1.0 / subjects:.2f}, p = {p_gen:.1e}, "
            f"{subjects} subjects); Perlin baseline {per:.2f}; held-out recordings {rec:.2f}"
        ),
        note=(
            f"A logistic-regression classifier trained on {m['window_s']:g}-s windows of each subject's recorded "
            "idle clips names the subject of generated windows, in place of the paper's informal viewing test; "
            "the Perlin baseline is the subject's mean posture plus generic Perlin noise on the PCs. "
            "Reproduced = above chance (binomial test) and at least as good as the Perlin baseline; partial = "
            "above chance only. With movement-only features (no posture means): generated "
            f"{acc['generated']['dynamics']:.2f}, Perlin {acc['perlin']['dynamics']:.2f}, recorded "
            f"{acc['recorded']['dynamics']:.2f}."
        ),
        value=gen - per,
        bound=0.0,
        unit="share",
        direction=">=",
    )


def _repetition(m: Measurements) -> Judgement:
    """Sec. 6.2: generated variations repeat less than a loop and, at the recorded length, no
    more than the recorded rest variations (partial within ``tolerance``, or with no recorded
    rest long enough to compare)."""
    med = m["median_best_ncc"]
    gen, cut, rec, loop = (med[k] for k in ("generated", "generated_cut", "recorded", "looped"))
    if not gen < loop:
        verdict = "not reproduced"
    elif m["subjects_with_recorded_rest"] == 0 or math.isnan(rec):
        verdict = "partial"
    else:
        verdict = verdict_threshold(cut, rec, "<=", m["tolerance"])
    w, seq = m["window_s"], m["sequence_s"]
    return Judgement(
        verdict=verdict,
        measured=(
            f"median best-match NCC of {w:g}-s windows: generated variations {gen:.2f} over {seq:g} s vs looped "
            f"rest {loop:.2f}; at the recorded length ({m['recorded_rest_s']:.0f} s on average) generated {cut:.2f} "
            f"vs recorded rest variations {rec:.2f}; full idle over {seq:g} s: generated {med['generated_idle']:.2f}, "
            f"looped clip {med['looped_idle']:.2f}, Perlin {med['perlin_idle']:.2f} (recorded idle "
            f"{med['recorded_idle']:.2f} over its own length)"
        ),
        note=(
            "Repetition = for each non-overlapping window, the highest normalised cross-correlation with any other "
            "non-overlapping window of the same sequence (1 = an exact repeat). Reproduced = generated variations "
            "repeat less than a loop and, at the same length, no more than the recorded resting variations "
            f"(partial: within {m['tolerance']:.0%}, or no recorded rest long enough to compare). "
            f"{m['subjects']} subjects, {m['subjects_with_recorded_rest']} of them with recorded resting segments "
            f"of at least two {w:g}-s windows."
        ),
        value=cut,
        bound=rec,
        unit="ncc",
        direction="<=",
    )


def _real_time(m: Measurements) -> Judgement:
    """Sec. 8: the slowest subject's idle motion is generated at least as fast as it plays back."""
    worst = m["min_realtime_ratio"]
    return Judgement(
        verdict=verdict_threshold(worst, 1.0, ">="),
        measured=(
            f"slowest subject: {m['min_frames_per_second']:,.0f} frames/s = {worst:.0f} x the playback rate "
            f"of {m['playback_fps']:g} fps ({m['sequence_s']:g}-s sequences, best of {m['repeats']})"
        ),
        note=(
            "Measured on one core of the CI machine, generating whole sequences at once (the paper's engine runs "
            "frame by frame inside an animation system); includes the exponential maps back to joint rotations, "
            "not rendering."
        ),
        value=worst,
        bound=1.0,
        unit="ratio",
        direction=">=",
    )


CLAIMS: tuple[ClaimSpec, ...] = (
    ClaimSpec(
        claim_id="egges2004.sec5_4.fitting_hits_end_postures",
        evaluation="egges2004_fitting",
        source="Sec. 5.4.4, 7.1, Fig. 4-5",
        kind="consistency",
        statement=(
            "fitAnim_part makes the best-fitting animation start at posture p and end at q, so that the next "
            "animation joins continuously (also for idle motion between two given postures, Sec. 7.1)."
        ),
        published="by construction (a_0 = p, a_e = q); no number",
        bound="linear ramp: ends within 1e-6 cm and junction step <= 1 x the recorded steps' quantile",
        judge=_fitting,
    ),
    ClaimSpec(
        claim_id="egges2004.sec8.generated_idle_identifies_person",
        evaluation="egges2004_identification",
        source="Sec. 5.6, 8",
        kind="stand-in",
        statement="Idle motion generated from a person's database lets viewers recognise that person.",
        published="informal viewing test: 'in general, test subjects could recognise the person' (no number)",
        bound="generated accuracy above chance (p < alpha) and >= Perlin's (partial: above chance only)",
        judge=_identification,
    ),
    ClaimSpec(
        claim_id="egges2004.sec6.variations_show_little_repetition",
        evaluation="egges2004_repetition",
        source="Sec. 6.2",
        kind="replication",
        statement="Small posture variations generated from clustered (distance, value) pairs show very little repetition.",
        published="qualitative: 'the variations show very little repetition' (no number)",
        bound="generated < looped; at the recorded length generated <= recorded (partial within tolerance)",
        judge=_repetition,
    ),
    ClaimSpec(
        claim_id="egges2004.sec8.real_time",
        evaluation="egges2004_speed",
        source="Sec. 8",
        kind="consistency",
        statement="Idle motions are generated in real time (faster than they play back).",
        published="real time on a 1.8 GHz desktop PC (no number)",
        bound="slowest subject's frames generated per second >= 1 x the playback rate",
        judge=_real_time,
    ),
)
