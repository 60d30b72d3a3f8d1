"""Ma et al. 2010 Sec. 7.4: long sequences from a few example cycles of about one stride
length (one per subject, as Fig. 1) by every method (:func:`..comparison.method_sequences`:
ours, Perlin noise, a Bayesian GPLVM along a helix, RBFs, style-only Kriging, a DBN),
all root-solved by the same footskate cleanup. Measured: naturalness (whole-body and
root-free jerk against the examples', foot skating at real contacts, distance to the
nearest example pose, discontinuities) and the variation between a method's sequences."""

from __future__ import annotations

import logging

import numpy as np
import pandas as pd

from ...claims import Claim, EvaluationResult, NotApplicable, verdict_from_fraction
from ...core.motion import Motion
from ...core.threads import fixed_threads
from ...metrics.jerk import mean_jerk, root_free_jerk
from ..comparison import (
    LABELS,
    METHODS,
    NATURALNESS_SCORES,
    NaturalnessReference,
    best_with_variation,
    example_pose_sequences,
    method_sequences,
    naturalness,
    naturalness_scores,
    variation_between,
)
from ..examples import WalkCycles
from ..settings import Ma2010Settings
from .common import PAPER, PROTOCOL, nearest_clips

log = logging.getLogger(__name__)

# The rivals' fits (the Bayesian GPLVM's 200 L-BFGS-B iterations in torch, the DBN's regressions)
# follow paths whose last bits depend on how many threads torch and BLAS split a product over,
# and the paths amplify them: at full size one thread instead of two moved GPLVM rows of the
# table by up to 13 % (the verdict held). So the sequences are made with a fixed thread count,
# the one of the published runs, whatever cores the job was given.
RIVAL_THREADS = 2


def sequence_rows(
    out: dict[str, list[Motion]], examples: list[Motion], ref: NaturalnessReference, full: float
) -> list[dict]:
    """One table row per sequence (method, number, length, :func:`..comparison.naturalness`,
    :func:`..comparison.naturalness_scores`, variation between the method's sequences), then
    the examples as reference. A sequence shorter than ``full`` s stopped early (diverged):
    its scores and its method's variation are infinite."""
    example_jerk = float(np.mean([mean_jerk(m.positions(), m.fps) for m in examples]))
    example_root_free_jerk = float(np.mean([root_free_jerk(m.positions(), m.fps) for m in examples]))
    rows = []
    for method, motions in out.items():
        diverged = any(m.duration < full for m in motions)
        var = np.inf if diverged else variation_between(motions)
        for s, m in enumerate(motions):
            meas = naturalness(m, ref)
            scores = naturalness_scores(meas, example_jerk, example_root_free_jerk)
            if m.duration < full:  # the sequence broke down before its end: unusable, least natural
                scores = {k: np.inf for k in scores}
            rows.append(
                {
                    "method": method,
                    "sequence": s + 1,
                    "seconds": m.duration,
                    **meas,
                    **scores,
                    "variation_between_sequences_cm": var,
                }
            )
            log.info("%s %d: %.1f s, %s", method, s + 1, m.duration, meas)
    for s, m in enumerate(examples):  # reference: the examples themselves, root-solved alike
        meas = naturalness(m, ref)
        rows.append(
            {
                "method": "examples",
                "sequence": s + 1,
                "seconds": m.duration,
                **meas,
                **naturalness_scores(meas, example_jerk, example_root_free_jerk),
                "variation_between_sequences_cm": np.nan,
            }
        )
    return rows


def natural_claim(means: pd.DataFrame, out: dict[str, list[Motion]], full: float, settings: Ma2010Settings) -> Claim:
    """Sec. 7.4's claim from the per-method means of the table: ours is at least as natural
    as every rival that varies, on every naturalness score (:data:`NATURALNESS_SCORES`)."""
    scores = {m: {k: float(means.loc[m, k]) for k in NATURALNESS_SCORES} for m in METHODS}
    variation = {m: float(means.loc[m, "variation_between_sequences_cm"]) for m in METHODS}
    best = best_with_variation(scores, variation, "ours")
    rivals = [LABELS[m] for m in METHODS if m != "ours" and variation[m] > 1e-6]
    ours_varies = variation["ours"] > 1e-6
    n_best = sum(best.values()) if ours_varies else 0
    xi_per, landing_rule = settings.comparison_xi, settings.comparison_landing
    return Claim(
        claim_id=f"{PAPER}.sec7_4.ours_most_natural_with_variation",
        paper=PAPER,
        source="Sec. 7.4",
        statement="Three long sequences by our method are visually different but more natural than those of Perlin "
        "noise, a GPLVM, RBFs, Kriging and a DBN built from the same five example clips.",
        published="ours natural and varied; the others unnatural (Perlin, GPLVM jerks, DBN after many iterations) "
        "or without variation (RBF, Kriging); judged from video",
        measured=f"ours best on {n_best}/{len(best)} naturalness scores among the methods that vary ({', '.join(rivals)}): "
        + "; ".join(
            f"{NATURALNESS_SCORES[k]}: ours {scores['ours'][k]:.3g}, best rival "
            f"{min((scores[m][k] for m in METHODS if m != 'ours' and variation[m] > 1e-6), default=float('nan')):.3g}"
            + (" (ours best)" if best[k] else "")
            for k in NATURALNESS_SCORES
        )
        + f"; variation between ours' sequences {variation['ours']:.2f} cm",
        verdict=verdict_from_fraction(n_best, len(best), full=1.0, partial=0.5),
        value=n_best / len(best) if best else float("nan"),
        bound=1.0,
        unit="share",
        direction=">=",
        note=(
            "Diverged (unrolled process left the rotation range before the end): "
            + ", ".join(
                f"{LABELS[m]} after {min(x.duration for x in out[m]):.1f} s"
                for m in METHODS
                if any(x.duration < full for x in out[m])
            )
            + ". "
            if any(x.duration < full for m in METHODS for x in out[m])
            else ""
        )
        + f"The paper judges naturalness by eye; here {len(best)} scores stand in for it (all best: reproduced; at "
        "least half: partial). RBF and Kriging make identical sequences (variation 0) and are not rivals. "
        f"Ours draws xi once per {xi_per} ({'one person per sequence' if xi_per == 'sequence' else 'a new person every cycle'}; "
        f"the paper does not say); transitions land on the {landing_rule.replace('_', ' ')} of the pose distance "
        "(Eq. 15). The GPLVM rival is a Bayesian GPLVM along a fitted helix, stronger than the MAP GPLVM of "
        "[Law03] that the paper drives 'roughly'. Perlin "
        f"amplitude {settings.perlin_amplitude_rad:g} rad at {settings.perlin_frequency_hz:g} Hz (set by hand, as in the "
        f"paper). Changed from the previous run (full config: ours best on 0/4, skating ours vs best rival "
        "not distinguishable): foot skating now counts only frames where the contact detection has a foot down "
        "and takes its contact point's speed (the generator's walks score ~0.1 cm/s; the earlier "
        "height-threshold measure, in the table as low_joint_speed_cm_s, scored them 13-47 cm/s: heel and toe "
        "roll); root-free jerk is scored beside whole-body jerk (5 scores, was 4: the shared root cleanup "
        "dominated whole-body jerk); xi per sequence (was per cycle) and the significant-maximum landing "
        "(was the first local maximum, 3-5 frames in) are the new defaults (config ma2010.comparison_xi, "
        "comparison_landing); the shared footskate cleanup keeps each support foot at least 0.1 s (was the "
        f"lower foot of every frame, which flickered in double support and jolted the root). {PROTOCOL}",
    )


def sec7_4_comparison(walks: WalkCycles, settings: Ma2010Settings, threads: int = RIVAL_THREADS) -> EvaluationResult:
    """Sec. 7.4 from the ``settings.comparison_examples`` cycles nearest the median stride
    (one per subject): every method's sequences (:func:`..comparison.method_sequences`,
    with ``settings``), their naturalness (:func:`..comparison.naturalness`: foot skating
    at detected contacts; the height-threshold measure with ``settings.contact_height_cm``
    beside it; a discontinuity is an acceleration above ``settings.discontinuity_factor`` x
    the examples' peak) and variation, one table row per sequence plus the examples as
    reference (:func:`sequence_rows`); a sequence that stops early (diverged) scores
    infinite. Claim: ours is the most natural of the methods that vary. Figure: ``means``
    (per-method means of the table), ``n_examples``, ``seconds``, ``n_sequences``,
    ``sequences`` (method -> motions). The sequences are made on ``threads`` torch and BLAS
    threads (:data:`RIVAL_THREADS`)."""
    style = np.median(walks.clips.style, axis=0)
    near = nearest_clips(walks.clips, style, settings.comparison_examples, walks.subjects)
    if len(near) < 2:
        raise NotApplicable(
            f"{walks.source}: {len(set(walks.subjects))} subject(s) among the {walks.clips.n_clips} walking cycles; "
            "Sec. 7.4 takes its example cycles one per subject (as the five clips of Fig. 1), so it needs cycles of "
            "at least 2 subjects"
        )
    five = walks.clips.subset(near)
    with fixed_threads(threads):
        out = method_sequences(five, walks.groups, walks.solver, settings)
    examples = [walks.solver.motion(r, five.fps) for r in example_pose_sequences(five)]
    ref = NaturalnessReference.from_examples(
        examples, walks.solver, settings.contact_height_cm, settings.discontinuity_factor
    )
    seconds = settings.comparison_seconds
    full = seconds - 1.0 / five.fps
    table = pd.DataFrame(sequence_rows(out, examples, ref, full))
    means = table.groupby("method", sort=False).mean(numeric_only=True)
    figure = {
        "means": means,
        "n_examples": len(near),
        "seconds": seconds,
        "n_sequences": settings.comparison_sequences,
        "sequences": out,
    }
    return EvaluationResult(table=table, claims=[natural_claim(means, out, full, settings)], figure=figure)
