"""Timing profiles and random signals for the synthetic generator, vectorised over frames.

- :func:`minimum_jerk`: the minimum-jerk position profile 10τ³ − 15τ⁴ + 6τ⁵ of
  point-to-point arm movements (Flash & Hogan 1985), zero velocity and acceleration at
  both ends.
- :func:`colored_noise`: stationary low-pass Gaussian noise, built in the frequency domain
  (no loop over frames), for postural sway and small posture variations.
- :func:`subject_rng`: a generator seeded by a subject's identity, for personal traits
  that the shared :class:`~motionvar.synth.subjects.Subject` does not list (posture
  details of idle standing, lifting strategy); the same subject always gets the same ones.
"""

from __future__ import annotations

import zlib

import numpy as np

from .subjects import Subject


def minimum_jerk(tau: np.ndarray | float) -> np.ndarray:
    """Minimum-jerk profile s(τ) = 10τ³ − 15τ⁴ + 6τ⁵ of τ clipped to [0, 1]."""
    t = np.clip(np.asarray(tau, dtype=float), 0.0, 1.0)
    return t**3 * (10.0 + t * (-15.0 + 6.0 * t))


def colored_noise(
    n: int, fps: float, corner_hz: float, rng: np.random.Generator, channels: int = 1, order: int = 2
) -> np.ndarray:
    """(n, channels) zero-mean Gaussian noise with unit RMS per channel and a low-pass
    spectrum |H(f)| = 1 / (1 + (f / corner_hz)^order): most power below ``corner_hz``.

    Built by shaping white noise in the frequency domain (``rfft``/``irfft``), so it is
    stationary and vectorised over frames. Each channel is rescaled to exactly unit RMS.
    """
    if n < 2:
        raise ValueError(f"colored_noise: n must be >= 2; got {n}")
    if not corner_hz > 0:
        raise ValueError(f"colored_noise: corner_hz must be positive; got {corner_hz}")
    white = rng.standard_normal((n, channels))
    spec = np.fft.rfft(white, axis=0)
    f = np.fft.rfftfreq(n, d=1.0 / fps)
    gain = 1.0 / (1.0 + (f / corner_hz) ** order)
    gain[0] = 0.0
    x = np.fft.irfft(spec * gain[:, None], n=n, axis=0)
    x -= x.mean(axis=0)
    return x / np.maximum(np.sqrt(np.mean(x**2, axis=0)), 1e-12)


def subject_rng(subject: Subject, purpose: str) -> np.random.Generator:
    """A generator that depends only on the subject (its id and bone lengths) and ``purpose``.

    Used for personal traits beyond those in :class:`Subject`: they persist across all of
    the subject's clips and differ between subjects, without touching the shared module.
    """
    key = [
        zlib.crc32(purpose.encode()),
        zlib.crc32(subject.subject_id.encode()),
        zlib.crc32(np.ascontiguousarray(subject.skeleton.offsets, dtype=np.float64).tobytes()),
    ]
    return np.random.default_rng(key)


def submovements(tau: np.ndarray | float, onset: float, duration: float) -> tuple[np.ndarray, np.ndarray]:
    """Minimum-jerk profiles (each 0 → 1) of the primary and the secondary sub-movement of an
    aimed movement over τ in [0, 1] (Meyer et al. 1988; Novak, Miller & Houk 2002): the
    secondary starts ``onset`` × the primary's duration after it (before its end when
    ``onset`` < 1: overlapping) and lasts ``duration`` × it; the primary's duration is set
    so that the later of the two ends at τ = 1."""
    span = max(1.0, onset + duration)  # the whole movement, in primary durations
    t = np.asarray(tau, dtype=float) * span
    return minimum_jerk(t), minimum_jerk((t - onset) / duration)
