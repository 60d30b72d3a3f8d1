"""Repetition (Egges et al. 2004, Sec. 6.2: generated small variations "show very little
repetition"): the best-match normalised cross-correlation between non-overlapping
windows of generated, recorded, looped and Perlin sequences.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pandas as pd

from ...claims import EvaluationResult, judge_claims
from ..baselines import loop_frames
from ..claims import CLAIMS
from ..database import Recording
from ..engine import generate_idle_pcs
from ..pipeline import IdleModel
from ..settings import Egges2004Settings, RepetitionSettings
from .common import perlin_sds, perlin_sequence, subject_rng


def window_best_match(x: np.ndarray, window: int, stride: int, chunk: int = 512) -> np.ndarray:
    """Repetition of a multichannel sequence x (T, C): for each non-overlapping window,
    the highest normalised cross-correlation with any other window of the sequence that
    does not overlap it (candidate starts every ``stride`` frames).

    Windows are centred per channel and scaled to unit norm over all channels, so 1
    means the same movement shape repeats exactly (a looped clip reaches it at the loop
    length); a window without movement counts as 0.
    """
    x = np.asarray(x, dtype=float)
    if window < 2 or len(x) < 2 * window:
        raise ValueError(f"window_best_match: need at least two windows of {window} frames; got {len(x)} frames")

    def normalise(v: np.ndarray) -> np.ndarray:
        v = v - v.mean(axis=1, keepdims=True)
        flat = v.reshape(len(v), -1)
        norm = np.linalg.norm(flat, axis=1, keepdims=True)
        return np.divide(flat, norm, out=np.zeros_like(flat), where=norm > 1e-12)

    starts = np.arange(0, len(x) - window + 1, stride)
    own = np.arange(0, len(x) - window + 1, window)
    query = normalise(np.stack([x[s : s + window] for s in own]))
    best = np.full(len(own), -np.inf)
    view = np.lib.stride_tricks.sliding_window_view(x, window, axis=0)  # (T-w+1, C, w)
    for k in range(0, len(starts), chunk):
        s = starts[k : k + chunk]
        cand = normalise(np.moveaxis(view[s], 2, 1))
        ncc = query @ cand.T
        ncc[np.abs(own[:, None] - s[None, :]) < window] = -np.inf
        best = np.maximum(best, ncc.max(axis=1))
    return best


GEN_VAR, GEN_VAR_CUT, REC_VAR, LOOP_VAR = (
    "generated variations (Sec. 6)",
    "generated variations, cut to the recorded length",
    "recorded rest variations",
    "looped rest variations",
)
GEN_IDLE, REC_IDLE, LOOP_IDLE, PERLIN_IDLE = (
    "generated idle (both layers)",
    "recorded idle",
    "looped recorded clip",
    "Perlin noise on PCs",
)
REPETITION_SOURCES = (GEN_VAR, GEN_VAR_CUT, REC_VAR, LOOP_VAR, GEN_IDLE, REC_IDLE, LOOP_IDLE, PERLIN_IDLE)


def repetition(
    model: IdleModel, recordings: dict[str, list[Recording]], settings: Egges2004Settings
) -> EvaluationResult:
    """Best-match normalised cross-correlation of non-overlapping windows (the varied PCs)
    for generated and recorded sequences and loops (``settings.repetition``,
    ``settings.perlin_frequency_hz``, ``settings.seed``). Generated, looped and Perlin
    sequences last ``sequence_s``; recorded ones as long as the training recordings allow,
    and the generated variations are also measured cut to that length (a longer sequence
    offers more candidates, hence higher best matches). Returns the per-subject table,
    the claim and, for the figure, ``pooled`` (the best-match values per source, over all
    subjects), ``sequence_s``, ``window_s`` and ``n_pcs`` (the varied PCs compared)."""
    params = settings.repetition
    subjects = list(model.databases)[: params.subjects or None]
    sds = perlin_sds(model, recordings)
    rows, pooled = [], {k: [] for k in REPETITION_SOURCES}
    for s in subjects:
        db = model.databases[s]
        fps, P = db.fps, db.variations.pcs.size
        seqs = _sequences(model, s, recordings[s], sds, settings)
        step = max(1, int(round(fps / params.fps)))
        window = int(round(params.window_s * fps / step))
        stride = max(1, int(round(params.stride_s * fps / step)))
        for source, x in seqs.items():
            y = x[::step, :P]
            # a recording too short for two windows has nothing to repeat: left out (windows 0)
            best = window_best_match(y, window, stride) if len(y) >= 2 * window else np.empty(0)
            pooled[source].append(best)
            rows.append(
                {
                    "subject": s,
                    "source": source,
                    "seconds": len(x) / fps,
                    "windows": len(best),
                    "median_best_ncc": float(np.median(best)) if len(best) else np.nan,
                    "max_best_ncc": float(best.max()) if len(best) else np.nan,
                }
            )
    table = pd.DataFrame(rows)
    pooled = {k: np.concatenate(v) for k, v in pooled.items()}
    n_pcs = next(iter(model.databases.values())).variations.pcs.size
    figure = {"pooled": pooled, "sequence_s": params.sequence_s, "window_s": params.window_s, "n_pcs": n_pcs}
    measurements = repetition_measurements(table, pooled, params, len(subjects))
    return EvaluationResult(table, judge_claims(CLAIMS, "egges2004_repetition", measurements), figure, measurements)


#: measurement key of each source's pooled median (motionvar.egges2004.claims)
MEDIAN_KEYS = {
    GEN_VAR: "generated",
    GEN_VAR_CUT: "generated_cut",
    REC_VAR: "recorded",
    LOOP_VAR: "looped",
    GEN_IDLE: "generated_idle",
    REC_IDLE: "recorded_idle",
    LOOP_IDLE: "looped_idle",
    PERLIN_IDLE: "perlin_idle",
}


def repetition_measurements(
    table: pd.DataFrame, pooled: dict[str, np.ndarray], params: RepetitionSettings, n_subjects: int
) -> dict[str, Any]:
    """What Sec. 6.2's claim is judged on: the median best match per source (pooled over
    subjects; NaN without windows), the mean length of the recorded rests that were measured,
    the subject counts, and the window, sequence length and tolerance used."""
    measured_rec = table[(table.source == REC_VAR) & (table.windows > 0)]
    return {
        "median_best_ncc": {MEDIAN_KEYS[k]: float(np.median(v)) if len(v) else float("nan") for k, v in pooled.items()},
        "recorded_rest_s": float(measured_rec["seconds"].mean()),
        "subjects": n_subjects,
        "subjects_with_recorded_rest": len(measured_rec),
        "window_s": params.window_s,
        "sequence_s": params.sequence_s,
        "tolerance": params.tolerance,
    }


def _sequences(
    model: IdleModel, s: str, recs: list[Recording], sds: np.ndarray, settings: Egges2004Settings
) -> dict[str, np.ndarray]:
    """Subject ``s``'s sequences of every source (REPETITION_SOURCES), PC values over frames:
    generated, looped and Perlin ones of ``sequence_s``, recorded ones cut to it."""
    params = settings.repetition
    db = model.databases[s]
    fps, P = db.fps, db.variations.pcs.size
    n = int(round(params.sequence_s * fps)) + 1
    rng = subject_rng(settings.seed, s, "repetition")
    rests = [r.pcs[a:b, :P] - r.pcs[a:b, :P].mean(axis=0) for r in recs for a, b in db.segments[r.name][0]]
    recorded_rests = np.concatenate(rests)[:n]
    generated = db.variations.generate(n, fps, rng)
    return {
        GEN_VAR: generated,
        GEN_VAR_CUT: generated[: len(recorded_rests)],
        REC_VAR: recorded_rests,
        LOOP_VAR: loop_frames(max(rests, key=len), n),
        GEN_IDLE: generate_idle_pcs(db, n, rng)[0],
        REC_IDLE: np.concatenate([r.pcs for r in recs])[:n],
        LOOP_IDLE: loop_frames(recs[0].pcs[: int(round(params.loop_clip_s * fps))], n),
        PERLIN_IDLE: perlin_sequence(model, recs, sds, settings.perlin_frequency_hz, n, int(rng.integers(2**31))),
    }
