"""GPLVM baseline of Ma et al. 2010, Sec. 7.4: a GPLVM learned from the example poses,
driven along a helix in its latent space to make a long sequence. This module holds only
the helix.

The GPLVM is not the MAP GPLVM of [Law03] that the paper used but the project's shared
Bayesian GPLVM (:class:`motionvar.models.bayesian_gplvm.BayesianGPLVM`, Titsias &
Lawrence 2010), a stronger model: its latent means play the role of Lawrence's latent
points, its posterior mean maps latent points to poses
(:func:`motionvar.ma2010.comparison.gplvm_sequence`).
"""

from __future__ import annotations

import numpy as np


def helix_trajectory(
    latent: np.ndarray, n_samples: int, n_turns: float, phase: float = 0.0, radius_scale: float = 1.0
) -> np.ndarray:
    """A helix (M = n_samples, q) through a latent point cloud (N, q): a circle in the plane
    of the cloud's two main axes around its centre, with the cloud's mean radius (times
    ``radius_scale``), turning ``n_turns`` times, while the coordinate along the third axis
    rises across the cloud's extent (q >= 3). Ma et al. 2010 "roughly synthesize a motion
    sequence with a helix trajectory in the latent variable space" (Sec. 7.4)."""
    latent = np.asarray(latent, dtype=float)
    centre = latent.mean(axis=0)
    _, _, vt = np.linalg.svd(latent - centre, full_matrices=False)
    proj = (latent - centre) @ vt.T
    radius = radius_scale * np.mean(np.linalg.norm(proj[:, :2], axis=1))
    s = np.linspace(0.0, 1.0, n_samples)
    angle = 2 * np.pi * n_turns * s + phase
    coords = np.zeros((n_samples, latent.shape[1]))
    coords[:, 0] = radius * np.cos(angle)
    coords[:, 1] = radius * np.sin(angle)
    if latent.shape[1] >= 3:
        lo, hi = proj[:, 2].min(), proj[:, 2].max()
        coords[:, 2] = lo + (hi - lo) * s
    return centre + coords @ vt
