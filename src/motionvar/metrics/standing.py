"""Standing idle: how a person stands, from the pelvis and the ankles in the ground plane
(the realism table's idle rows, :mod:`motionvar.realism`; Egges et al. 2004's support ratio).

Sway measures after Prieto et al. 1996, "Measures of postural steadiness" (the pelvis in place
of the centre of pressure); weight shifts as Egges 2004 Sec. 5.1 names the resting postures
(balance on the left foot, the right foot, both). numpy only at import; the spectral measures
load scipy.signal when called.
"""

from __future__ import annotations

import numpy as np


def sway_sd(ground: np.ndarray) -> float:
    """Sway amplitude of a standing clip: the SD of the pelvis's ground-plane position (T, 2)
    about its mean, the square root of the summed variances (the "RMS distance" of a sway
    path, Prieto et al. 1996, "Measures of postural steadiness"), in the positions' unit."""
    g = np.asarray(ground, dtype=float)
    return float(np.sqrt(np.sum(np.var(g, axis=0)))) if len(g) > 1 else float("nan")


def sway_band_rms(ground: np.ndarray, fps: float, above_hz: float) -> float:
    """RMS of the ground-plane position (T, 2) above ``above_hz``: the sway beside the posture
    held (a 2nd-order Butterworth high-pass run forwards and backwards); NaN for a clip too
    short to filter."""
    from scipy.signal import butter, sosfiltfilt

    g = np.asarray(ground, dtype=float)
    if len(g) < 16 or not 0 < above_hz < 0.95 * fps / 2.0:
        return float("nan")
    sos = butter(2, above_hz, btype="highpass", fs=fps, output="sos")
    fast = sosfiltfilt(sos, g - g.mean(axis=0), axis=0, padlen=min(15, len(g) - 1))
    return float(np.sqrt(np.mean(np.sum(fast**2, axis=1))))


def sway_median_frequency(ground: np.ndarray, fps: float, band_hz: tuple[float, float], segment_s: float) -> float:
    """Median frequency (Hz) of the sway: the frequency below which half of the power within
    ``band_hz`` lies, in the summed Welch spectra of the two ground-plane coordinates (T, 2)
    (segments of ``segment_s`` s, each detrended linearly; the "median power frequency" of
    Prieto et al. 1996). NaN for a clip shorter than one segment."""
    from scipy.signal import welch

    g = np.asarray(ground, dtype=float)
    n = int(round(segment_s * fps))
    if len(g) < n or n < 8:
        return float("nan")
    f, p = welch(g, fs=fps, nperseg=n, detrend="linear", axis=0)
    keep = (f >= band_hz[0]) & (f <= band_hz[1])
    power = p[keep].sum(axis=1)
    if not power.sum() > 0:
        return float("nan")
    cumulative = np.cumsum(power) / power.sum()
    return float(f[keep][np.searchsorted(cumulative, 0.5)])


def support_ratio(hips: np.ndarray, left_ankle: np.ndarray, right_ankle: np.ndarray) -> np.ndarray:
    """(T,) where the pelvis stands between the ankles in the ground plane (each (T, 2)): 0
    over the right ankle, 1 over the left (Egges et al. 2004, Sec. 5.1's balance on the left
    foot, the right foot or both)."""
    span = left_ankle - right_ankle
    return np.sum((hips - right_ankle) * span, axis=-1) / np.maximum(np.sum(span * span, axis=-1), 1e-9)


def weight_shifts(ratio: np.ndarray, fps: float, margin: float, min_s: float) -> int:
    """Shifts of weight between the feet in a standing clip: the side the pelvis stands over
    (:func:`support_ratio`: left above 0.5 + ``margin``, right below 0.5 - ``margin``, both
    between) changes from one held side to another, a side counting as held when the pelvis
    stays over it for ``min_s`` s (shorter stays are passages, not postures)."""
    r = np.asarray(ratio, dtype=float)
    side = np.where(r > 0.5 + margin, 1, np.where(r < 0.5 - margin, -1, 0))
    edges = np.flatnonzero(np.diff(side)) + 1
    starts, stops = np.concatenate([[0], edges]), np.concatenate([edges, [len(side)]])
    held = [side[a] for a, b in zip(starts, stops) if b - a >= max(1, int(round(min_s * fps)))]
    return int(sum(1 for a, b in zip(held[:-1], held[1:]) if a != b))
