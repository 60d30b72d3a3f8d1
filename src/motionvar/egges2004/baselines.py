"""The two alternatives Egges et al. 2004 set their method against (Sec. 1, 6):

- looping a recorded clip ("very repetitive and inflexible", Sec. 1);
- one-dimensional Perlin noise on (a subset of) the principal components (Sec. 6),
  around a base posture, with a frequency and amplitudes chosen by hand — the paper's
  point being that its own method needs no such choices.
"""

from __future__ import annotations

import numpy as np

from ..core.noise import perlin_noise


def loop_frames(clip: np.ndarray, n_frames: int) -> np.ndarray:
    """(n_frames, ...) the clip played again and again from its start."""
    clip = np.asarray(clip)
    if len(clip) == 0 or n_frames < 1:
        raise ValueError(f"loop_frames: need a non-empty clip and n_frames >= 1; got {len(clip)}, {n_frames}")
    return clip[np.arange(n_frames) % len(clip)]


def perlin_pcs(
    base: np.ndarray,
    sds: np.ndarray,
    frequency_hz: float,
    n_frames: int,
    fps: float,
    seed: int,
    octaves: int = 2,
) -> np.ndarray:
    """(n_frames, D) postures: ``base`` (D,) plus Perlin noise [Per85] on the leading
    PCs, scaled so that PC i varies with standard deviation ``sds[i]``
    (len(sds) <= D) over the sequence."""
    base = np.asarray(base, dtype=float)
    sds = np.asarray(sds, dtype=float)
    if sds.ndim != 1 or sds.size > base.size or n_frames < 2:
        raise ValueError(
            f"perlin_pcs: need at most {base.size} SDs and n_frames >= 2; got shape {sds.shape}, {n_frames}"
        )
    noise = perlin_noise(np.arange(n_frames) / fps, sds.size, frequency_hz, seed, octaves)
    noise = noise - noise.mean(axis=0)
    noise /= np.where(noise.std(axis=0) > 0, noise.std(axis=0), 1.0)
    out = np.broadcast_to(base, (n_frames, base.size)).copy()
    out[:, : sds.size] += sds * noise
    return out
