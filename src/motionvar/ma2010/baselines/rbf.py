"""Radial basis function interpolation with a linear term (Rose, Cohen & Bodenheimer 1998,
"Verbs and adverbs"), as Mukai & Kuriyama 2005 compare it with universal Kriging.

Rose et al. first fit a hyperplane (the linear term) to the examples by least squares,
then interpolate what it leaves with radial basis functions: a cubic B-spline centred on
each example, its support radius twice the distance to the nearest other example. The
weights solve Phi w = r exactly (least squares when Phi is singular). Parameters are
standardized per dimension, as for Kriging (:mod:`motionvar.ma2010.kriging`).

An example of Rose et al. is one motion at one style. Cycles cut from one walk are near-copies
at almost one style: each its own example, their kernels shrink to the distance between them
and reach no other style (away from them the interpolation is the hyperplane alone), and
solving exactly for their small differences swings the interpolant. ``groups`` makes such
examples one (their mean style and mean output), so that each kernel spans the distance to
the nearest other walk.
"""

from __future__ import annotations

import numpy as np
from scipy.spatial.distance import cdist


def cubic_bspline(r: np.ndarray) -> np.ndarray:
    """The uniform cubic B-spline of r = 2 d / radius (support |r| < 2), 2/3 at 0."""
    r = np.abs(r)
    return np.where(r < 1, 2 / 3 - r**2 + 0.5 * r**3, np.where(r < 2, (2 - r) ** 3 / 6, 0.0))


def support_radii(xs: np.ndarray) -> np.ndarray:
    """(N,) support radius of the kernel of each of the examples ``xs`` (N, p) (standardized
    units): twice the distance to the nearest other example (Rose et al. 1998); an example with
    no other elsewhere: twice a unit distance."""
    d = cdist(xs, xs)
    nearest = np.where(d > 1e-12, d, np.inf).min(axis=1)
    return 2.0 * np.where(np.isfinite(nearest), nearest, 1.0)


def group_means(values: np.ndarray, groups: np.ndarray) -> np.ndarray:
    """(G, ...) mean of ``values`` (N, ...) over each of the G groups labelled 0..G-1 by ``groups`` (N,)."""
    out = np.zeros((groups.max() + 1,) + values.shape[1:])
    np.add.at(out, groups, values)
    return out / np.bincount(groups).reshape((-1,) + (1,) * (values.ndim - 1))


class RBFInterpolation:
    """f(x) = a_0 + a x + sum_i w_i B(2 ||x - x_i|| / radius_i), vector-valued.

    ``linear_rcond``: relative cut-off of the linear term's pseudo-inverse, as
    ``trend_rcond`` of :class:`motionvar.ma2010.kriging.UniversalKriging`."""

    def __init__(self, linear_rcond: float = 0.0):
        self.linear_rcond = linear_rcond

    def fit(self, x: np.ndarray, y: np.ndarray, groups: np.ndarray | None = None) -> "RBFInterpolation":
        """Fit to examples at x (N, p) with outputs y (N, D). ``groups`` (N,) labels examples that
        are one (the cycles of one walk): one kernel at their mean style, fitted to their mean
        residual (default: every example its own)."""
        x = np.asarray(x, dtype=float)
        x = x[:, None] if x.ndim == 1 else x
        y = np.asarray(y, dtype=float)
        if x.ndim != 2 or y.ndim != 2 or len(x) != len(y) or len(x) < 1:
            raise ValueError(f"RBFInterpolation.fit: need x (N, p) and y (N, D); got {x.shape}, {y.shape}")
        if groups is not None and len(groups) != len(x):
            raise ValueError(f"RBFInterpolation.fit: {len(groups)} group labels for {len(x)} examples")
        label = np.arange(len(x)) if groups is None else np.unique(np.asarray(groups), return_inverse=True)[1]
        sd = x.std(axis=0)
        self.x_mean_, self.x_scale_ = x.mean(axis=0), np.where(sd > 1e-12, sd, 1.0)
        xs = (x - self.x_mean_) / self.x_scale_
        design = np.concatenate([np.ones((len(xs), 1)), xs], axis=1)
        self.linear_ = np.linalg.pinv(design, rcond=max(self.linear_rcond, 1e-15)) @ y
        self.x_ = group_means(xs, label)
        resid = group_means(y - design @ self.linear_, label)
        self.radius_ = support_radii(self.x_)
        phi = cubic_bspline(2 * cdist(self.x_, self.x_) / self.radius_[None, :])
        self.weights_ = np.linalg.lstsq(phi, resid, rcond=None)[0]
        return self

    def _kernels(self, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        xs = (np.atleast_2d(np.asarray(x, dtype=float)) - self.x_mean_) / self.x_scale_
        return xs, cubic_bspline(2 * cdist(xs, self.x_) / self.radius_[None, :])

    def predict(self, x: np.ndarray) -> np.ndarray:
        xs, phi = self._kernels(x)
        return self.linear_[0] + xs @ self.linear_[1:] + phi @ self.weights_

    def reaches(self, x: np.ndarray) -> np.ndarray:
        """(M,) whether some kernel's support reaches each of x (M, p): elsewhere the prediction is
        the linear term alone."""
        return (self._kernels(x)[1] > 0).any(axis=1)
