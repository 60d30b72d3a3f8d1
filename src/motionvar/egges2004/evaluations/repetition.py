"""Repetition and structure of the small posture variations (Egges et al. 2004, Sec. 6.2:
"the variations show very little repetition, but the PC value curve over the animation still
has a very similar structure to the animation samples that were analysed"): the best-match
normalised cross-correlation between non-overlapping windows of generated, recorded, looped,
white-noise and Perlin sequences, and the spectral distance of the variation sequences from
the recorded resting variations.
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


GEN_VAR, GEN_VAR_CUT, REC_VAR, LOOP_VAR, WHITE_VAR = (
    "generated variations (Sec. 6)",
    "generated variations, cut to the recorded length",
    "recorded rest variations",
    "looped rest variations",
    "white noise (recorded variance)",
)
GEN_IDLE, REC_IDLE, LOOP_IDLE, PERLIN_IDLE = (
    "generated idle (both layers)",
    "recorded idle",
    "looped recorded clip",
    "Perlin noise on PCs",
)
REPETITION_SOURCES = (GEN_VAR, GEN_VAR_CUT, REC_VAR, LOOP_VAR, WHITE_VAR, GEN_IDLE, REC_IDLE, LOOP_IDLE, PERLIN_IDLE)
#: the sources whose varied PCs are variations around a fixed posture, compared in spectrum with the recorded
#: resting variations (the recorded ones with themselves: their first half against their second)
STRUCTURE_SOURCES = (GEN_VAR, GEN_VAR_CUT, REC_VAR, LOOP_VAR, WHITE_VAR, PERLIN_IDLE)


def power_spectra(x: np.ndarray, fps: float, segment: int) -> tuple[np.ndarray, np.ndarray]:
    """Welch power spectral density of each channel of x (T, C): Hann segments of ``segment``
    frames (fewer when x is shorter), half overlapping, each segment's mean removed; the zero
    frequency is dropped. Returns the frequencies (F,) and the densities (F, C)."""
    from scipy.signal import welch  # scipy.signal loads scipy.stats: only for this rule

    x = np.asarray(x, dtype=float)
    if len(x) < 2:
        raise ValueError(f"power_spectra: need at least two frames; got {len(x)}")
    freqs, psd = welch(x, fs=fps, nperseg=min(segment, len(x)), axis=0, detrend="constant")
    return freqs[1:], psd[1:]


def spectral_distance_db(p: np.ndarray, q: np.ndarray) -> np.ndarray:
    """Power-weighted RMS log-spectral distance (dB) per channel between two power spectra (F, C)
    on the same frequencies: sqrt(sum_f w_f (10 log10(p_f / q_f))^2) with w the mean of the two
    spectra normalised to unit sum, so the frequencies where either signal has its power count
    and the others hardly do. 0 = the same spectrum; 3 dB = power off by a factor of two on
    average there. A channel without power in either counts 0; one without power in only one is
    floored at 1e-12 of the other's total power."""
    p, q = np.asarray(p, dtype=float), np.asarray(q, dtype=float)
    if p.shape != q.shape:
        raise ValueError(f"spectral_distance_db: spectra must have the same shape; got {p.shape} and {q.shape}")
    tot_p, tot_q = p.sum(axis=0), q.sum(axis=0)
    floor = 1e-12 * np.maximum(np.maximum(tot_p, tot_q), np.finfo(float).tiny)
    ratio_db = 10.0 * np.log10(np.maximum(p, floor) / np.maximum(q, floor))
    w = 0.5 * (p / np.where(tot_p > 0, tot_p, 1.0) + q / np.where(tot_q > 0, tot_q, 1.0))
    return np.sqrt(np.sum(w * ratio_db**2, axis=0))


def structure_distances(seqs: dict[str, np.ndarray], fps: float, segment: int) -> dict[str, np.ndarray]:
    """Per source of :data:`STRUCTURE_SOURCES` in ``seqs`` (variation sequences (T, P) at ``fps``),
    the spectral distance (dB, per PC) from the recorded resting variations ``seqs[REC_VAR]``; for
    those, the distance between their first and their second half (how far two stretches of the
    same person's recorded variations lie apart). Sequences shorter than two segments are left out
    (an empty array)."""
    rec = seqs[REC_VAR]
    if len(rec) < 2 * segment:
        return {k: np.empty(0) for k in STRUCTURE_SOURCES if k in seqs}
    _, target = power_spectra(rec, fps, segment)
    half = len(rec) // 2
    out = {
        REC_VAR: spectral_distance_db(
            power_spectra(rec[:half], fps, segment)[1], power_spectra(rec[half:], fps, segment)[1]
        )
    }
    for k in STRUCTURE_SOURCES:
        if k != REC_VAR and k in seqs:
            x = seqs[k] - seqs[k].mean(axis=0)
            out[k] = (
                spectral_distance_db(power_spectra(x, fps, segment)[1], target)
                if len(x) >= 2 * segment
                else np.empty(0)
            )
    return out


def repetition(
    model: IdleModel, recordings: dict[str, list[Recording]], settings: Egges2004Settings
) -> EvaluationResult:
    """Best-match normalised cross-correlation of non-overlapping windows (the varied PCs)
    for generated and recorded sequences, loops and white noise, and the spectral distance of
    the variation sequences from the recorded resting variations (``settings.repetition``,
    ``settings.perlin_frequency_hz``, ``settings.seed``). Generated, looped, white-noise and
    Perlin sequences last ``sequence_s``; recorded ones as long as the training recordings
    allow, and the generated variations are also measured cut to that length (a longer
    sequence offers more candidates, hence higher best matches). Spectra: Welch segments of
    ``window_s`` at ``fps`` (:func:`structure_distances`). Returns the per-subject table, the
    claims and, for the figure, ``pooled`` (the best-match values per source, over all
    subjects), ``spectra`` (:func:`_figure_spectra`), ``sequence_s``, ``window_s`` and
    ``n_pcs`` (the varied PCs compared)."""
    params = settings.repetition
    subjects = list(model.databases)[: params.subjects or None]
    sds = perlin_sds(model, recordings)
    rows, pooled = [], {k: [] for k in REPETITION_SOURCES}
    structure = {k: [] for k in STRUCTURE_SOURCES}
    spectra = {}
    for s in subjects:
        db = model.databases[s]
        fps, P = db.fps, db.variations.pcs.size
        seqs = _sequences(model, s, recordings[s], sds, settings)
        step = max(1, int(round(fps / params.fps)))
        window = int(round(params.window_s * fps / step))
        stride = max(1, int(round(params.stride_s * fps / step)))
        sub = {source: x[::step, :P] for source, x in seqs.items()}
        dist = structure_distances(sub, fps / step, window)
        for k, d in dist.items():
            structure[k].append(d)
        if not spectra and len(dist[REC_VAR]):
            spectra = _figure_spectra(sub, fps / step, window, s)
        for source, y in sub.items():
            # a recording too short for two windows has nothing to repeat: left out (windows 0)
            best = window_best_match(y, window, stride) if len(y) >= 2 * window else np.empty(0)
            pooled[source].append(best)
            d = dist.get(source, np.empty(0))
            rows.append(
                {
                    "subject": s,
                    "source": source,
                    "seconds": len(seqs[source]) / fps,
                    "windows": len(best),
                    "median_best_ncc": float(np.median(best)) if len(best) else np.nan,
                    "max_best_ncc": float(best.max()) if len(best) else np.nan,
                    "spectral_distance_db": float(np.median(d)) if len(d) else np.nan,
                }
            )
    table = pd.DataFrame(rows)
    pooled = {k: np.concatenate(v) for k, v in pooled.items()}
    structure = {k: np.concatenate(v) for k, v in structure.items()}
    n_pcs = next(iter(model.databases.values())).variations.pcs.size
    figure = {
        "pooled": pooled,
        "spectra": spectra,
        "sequence_s": params.sequence_s,
        "window_s": params.window_s,
        "n_pcs": n_pcs,
    }
    measurements = repetition_measurements(table, pooled, structure, params, len(subjects))
    return EvaluationResult(table, judge_claims(CLAIMS, "egges2004_repetition", measurements), figure, measurements)


def _figure_spectra(seqs: dict[str, np.ndarray], fps: float, segment: int, subject: str) -> dict[str, Any]:
    """For the figure: the power spectra of PC 1 (the first varied PC) of one subject's variation
    sequences, ``freqs`` (Hz) and ``psd`` per source of :data:`STRUCTURE_SOURCES` but the cut one."""
    out = {}
    for k in STRUCTURE_SOURCES:
        x = seqs[k][:, :1] - seqs[k][:, :1].mean(axis=0)
        if k != GEN_VAR_CUT and len(x) >= 2 * segment:
            freqs, out[k] = power_spectra(x, fps, segment)
    return {"subject": subject, "freqs": freqs, "psd": {k: v[:, 0] for k, v in out.items()}}


#: measurement key of each source's pooled median (motionvar.egges2004.claims)
MEDIAN_KEYS = {
    GEN_VAR: "generated",
    GEN_VAR_CUT: "generated_cut",
    REC_VAR: "recorded",
    LOOP_VAR: "looped",
    WHITE_VAR: "white_noise",
    GEN_IDLE: "generated_idle",
    REC_IDLE: "recorded_idle",
    LOOP_IDLE: "looped_idle",
    PERLIN_IDLE: "perlin_idle",
}


def repetition_measurements(
    table: pd.DataFrame,
    pooled: dict[str, np.ndarray],
    structure: dict[str, np.ndarray],
    params: RepetitionSettings,
    n_subjects: int,
) -> dict[str, Any]:
    """What Sec. 6.2's claims are judged on: the median best match per source (pooled over
    subjects; NaN without windows) and the subjects whose generated variations (cut to the
    recorded length) repeat more than their recorded ones; the median spectral distance (dB) from
    the recorded resting variations per source of :data:`STRUCTURE_SOURCES` over all (subject,
    PC) pairs (``recorded``: between the recordings' halves; NaN without recorded rests of two
    windows); the mean length of the recorded rests that were measured, the subject counts, and
    the window, sequence length and tolerance used."""
    measured_rec = table[(table.source == REC_VAR) & (table.windows > 0)]
    per_subject = table.pivot(index="subject", columns="source", values="median_best_ncc")
    more = per_subject[GEN_VAR_CUT] > per_subject[REC_VAR]

    def median(v: np.ndarray) -> float:
        return float(np.median(v)) if len(v) else float("nan")

    return {
        "median_best_ncc": {MEDIAN_KEYS[k]: median(v) for k, v in pooled.items()},
        "subjects_repeating_more": sorted(map(str, per_subject.index[more])),
        "spectral_distance_db": {MEDIAN_KEYS[k]: median(v) for k, v in structure.items()},
        "structure_pairs": len(structure[GEN_VAR]),
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
    generated, looped, white-noise (each varied PC with its recorded resting SD) and Perlin ones
    of ``sequence_s``, recorded ones cut to it."""
    params = settings.repetition
    db = model.databases[s]
    fps, P = db.fps, db.variations.pcs.size
    n = int(round(params.sequence_s * fps)) + 1
    rng = subject_rng(settings.seed, s, "repetition")
    rests = [r.pcs[a:b, :P] - r.pcs[a:b, :P].mean(axis=0) for r in recs for a, b in db.segments[r.name][0]]
    recorded_rests = np.concatenate(rests)[:n]
    generated = db.variations.generate(n, fps, rng)
    white = subject_rng(settings.seed, s, "white noise").normal(size=(n, P)) * recorded_rests.std(axis=0)
    return {
        GEN_VAR: generated,
        GEN_VAR_CUT: generated[: len(recorded_rests)],
        REC_VAR: recorded_rests,
        LOOP_VAR: loop_frames(max(rests, key=len), n),
        WHITE_VAR: white,
        GEN_IDLE: generate_idle_pcs(db, n, rng)[0],
        REC_IDLE: np.concatenate([r.pcs for r in recs])[:n],
        LOOP_IDLE: loop_frames(recs[0].pcs[: int(round(params.loop_clip_s * fps))], n),
        PERLIN_IDLE: perlin_sequence(model, recs, sds, settings.perlin_frequency_hz, n, int(rng.integers(2**31))),
    }
