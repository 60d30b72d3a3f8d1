"""GPLVM baseline of Ma et al. 2010, Sec. 7.4: a GPLVM [Law03] learned from the example
poses, driven along a helix in its latent space to make a long sequence.

The GPLVM itself is the project's Bayesian GPLVM (:class:`motionvar.du2022.fda.functional_gplvm.BayesianGPLVM`,
Titsias & Lawrence 2010, written for Du 2022): its latent means play the role of the
latent points of Lawrence's MAP GPLVM, its posterior mean maps latent points to poses.
This module adds the helix.
"""

from __future__ import annotations

import numpy as np


def helix_trajectory(latent: np.ndarray, n_samples: int, n_turns: float, phase: float = 0.0, radius_scale: float = 1.0) -> np.ndarray:
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
