"""Perlin noise [Per95] (used by the Ma 2010 and Egges 2004 baselines): 1-D gradient noise over time, for any number of channels, seeded.

Each channel has its own random gradients at integer lattice points of ``frequency *
time``; between lattice points the two gradient ramps are blended with Perlin's quintic
fade 6u^5 - 15u^4 + 10u^3 ("Improved noise", Perlin 2002). Octaves add finer noise at
``lacunarity`` times the frequency and ``persistence`` times the amplitude.
"""

from __future__ import annotations

import numpy as np


def _fade(u: np.ndarray) -> np.ndarray:
    return u * u * u * (u * (u * 6 - 15) + 10)


def perlin_noise(
    times: np.ndarray,
    n_channels: int,
    frequency: float,
    seed: int,
    octaves: int = 1,
    persistence: float = 0.5,
    lacunarity: float = 2.0,
) -> np.ndarray:
    """Noise (T, n_channels) in [-1, 1] at ``times`` (T,) (any unit; ``frequency`` is in
    lattice cells per that unit). Zero at lattice points of the first octave; the same
    seed gives the same noise."""
    times = np.asarray(times, dtype=float)
    if times.ndim != 1 or n_channels < 1 or frequency <= 0 or octaves < 1:
        raise ValueError(
            f"perlin_noise: need 1-D times, n_channels >= 1, frequency > 0, octaves >= 1; got "
            f"{times.shape}, {n_channels}, {frequency}, {octaves}"
        )
    rng = np.random.default_rng(seed)
    out = np.zeros((len(times), n_channels))
    amp, total = 1.0, 0.0
    for o in range(octaves):  # loop over octaves
        x = times * frequency * lacunarity**o
        base = np.floor(x.min()) if len(x) else 0.0
        x = x - base
        i0 = np.floor(x).astype(np.int64)
        u = (x - i0)[:, None]
        grads = rng.uniform(-1.0, 1.0, size=(int(i0.max(initial=0)) + 2, n_channels))
        g0, g1 = grads[i0], grads[i0 + 1]
        w = _fade(u)
        out += amp * 2.0 * ((1 - w) * g0 * u + w * g1 * (u - 1))
        total += amp
        amp *= persistence
    return out / total
