"""Measures for the Egges et al. 2004 evaluations: window features and a classifier for
person identification (Sec. 5.6, 8), repetition by normalised cross-correlation
(Sec. 6.2), junction steps for the fitting check (Sec. 5.4.4).
"""

from __future__ import annotations

import time

import numpy as np
from scipy.signal import welch
from sklearn.linear_model import LogisticRegression
from sklearn.pipeline import Pipeline, make_pipeline
from sklearn.preprocessing import StandardScaler

from .balance import synthesize_balance
from .database import IdleDatabase
from .fitting import posture_distance
from .pca import PosturePCA

FEATURE_SETS = ("all", "dynamics")
SWAY_BANDS_HZ = ((0.05, 0.3), (0.3, 1.0), (1.0, 3.0))


def _windows(x: np.ndarray, length: int) -> np.ndarray:
    """(n, length, ...) non-overlapping windows of ``x`` (T, ...); the tail is dropped."""
    n = len(x) // length
    return np.asarray(x)[: n * length].reshape(n, length, *np.shape(x)[1:])


def window_features(
    pcs: np.ndarray,
    support: np.ndarray,
    fps: float,
    window_s: float,
    n_pcs: int,
    feature_set: str = "all",
    margin: float = 0.1,
    n_spectral_pcs: int = 3,
) -> np.ndarray:
    """(n_windows, F) features of non-overlapping windows of an idle sequence.

    ``all``: per window the mean and standard deviation of the first ``n_pcs`` PCs
    (posture and its variation), posture-category statistics from the support ratio
    (mean, SD, share of frames on the left foot / right foot / both, with ``margin`` as
    in :func:`~motionvar.egges2004.categories.name_by_support`), and sway spectra: the log
    Welch power of the first ``n_spectral_pcs`` PCs in the bands of ``SWAY_BANDS_HZ``.
    ``dynamics``: only what describes movement, not the posture held: the PC SDs, the
    support-ratio SD and the sway spectra.
    """
    if feature_set not in FEATURE_SETS:
        raise ValueError(f"feature_set must be one of {FEATURE_SETS}, got {feature_set!r}")
    length = int(round(window_s * fps))
    if length < 2 or len(pcs) < length:
        raise ValueError(f"window_features: a window of {window_s} s needs {length} frames; the sequence has {len(pcs)}")
    w = _windows(np.asarray(pcs)[:, :n_pcs], length)
    lam = _windows(np.asarray(support), length)
    freqs, power = welch(
        w[:, :, :n_spectral_pcs], fs=fps, nperseg=min(length, int(round(8 * fps))), axis=1, detrend="linear"
    )
    bands = np.stack([power[:, (freqs >= lo) & (freqs < hi)].mean(axis=1) for lo, hi in SWAY_BANDS_HZ], axis=2)
    spectra = np.log10(np.maximum(bands, 1e-20)).reshape(len(w), -1)
    dynamics = [w.std(axis=1), lam.std(axis=1, keepdims=True), spectra]
    if feature_set == "dynamics":
        return np.concatenate(dynamics, axis=1)
    shares = np.stack([lam > 0.5 + margin, lam < 0.5 - margin, np.abs(lam - 0.5) <= margin], axis=2).mean(axis=1)
    return np.concatenate([w.mean(axis=1), lam.mean(axis=1, keepdims=True), shares, *dynamics], axis=1)


def make_identifier(seed: int = 0) -> Pipeline:
    """Standardised multinomial logistic regression naming the subject of a window."""
    return make_pipeline(StandardScaler(), LogisticRegression(max_iter=5000, random_state=seed))


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
    query = normalise(np.stack([x[s: s + window] for s in own]))
    best = np.full(len(own), -np.inf)
    view = np.lib.stride_tricks.sliding_window_view(x, window, axis=0)  # (T-w+1, C, w)
    for k in range(0, len(starts), chunk):
        s = starts[k: k + chunk]
        cand = normalise(np.moveaxis(view[s], 2, 1))
        ncc = query @ cand.T
        ncc[np.abs(own[:, None] - s[None, :]) < window] = -np.inf
        best = np.maximum(best, ncc.max(axis=1))
    return best


def junction_steps(pcs: np.ndarray, boundaries: np.ndarray, weights: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Step sizes (sqrt of Eq. 4 between consecutive frames) and second differences at
    the given frames: the step from frame b to b+1 and |x_{b+1} - 2 x_b + x_{b-1}|."""
    pcs = np.asarray(pcs)
    b = np.asarray(boundaries, dtype=np.int64)
    b = b[(b >= 1) & (b < len(pcs) - 1)]
    step = np.sqrt(posture_distance(pcs[b + 1], pcs[b], weights))
    second = pcs[b + 1] - 2 * pcs[b] + pcs[b - 1]
    accel = np.sqrt(posture_distance(second, np.zeros_like(second), weights))
    return step, accel


def all_steps(pcs: np.ndarray, weights: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Step sizes and second differences (as :func:`junction_steps`) at every inner frame."""
    return junction_steps(pcs, np.arange(1, len(pcs) - 1), weights)


def generation_seconds(
    db: IdleDatabase, pca: PosturePCA, n_frames: int, seed: int, repeats: int = 3
) -> dict[str, float]:
    """Best-of-``repeats`` wall time (s) to generate ``n_frames`` frames of idle motion,
    per stage: balance shifting (Sec. 5.4), small variations (Sec. 6), PC values ->
    joint rotations and root translation (Sec. 3.2, the per-frame exponential maps), and
    the total of the three (Sec. 8's real-time claim)."""
    best = {"balance": np.inf, "variations": np.inf, "reconstruct": np.inf}
    for r in range(repeats):
        rng = np.random.default_rng(seed + r)
        t0 = time.perf_counter()
        pcs, _ = synthesize_balance(db, n_frames, rng)
        t1 = time.perf_counter()
        pcs = np.array(pcs, copy=True)
        pcs[:, db.variations.pcs] += db.variations.generate(n_frames, db.fps, rng)
        t2 = time.perf_counter()
        pca.to_rotations(pcs)
        t3 = time.perf_counter()
        for key, dt in zip(best, (t1 - t0, t2 - t1, t3 - t2)):
            best[key] = min(best[key], dt)
    best["total"] = sum(best.values())
    return best
