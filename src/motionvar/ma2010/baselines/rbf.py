"""Radial basis function interpolation with a linear term (Rose, Bodenheimer & Cohen 1998,
"Verbs and adverbs").

Rose et al. first fit a hyperplane (the linear term) to the examples by least squares,
then interpolate what it leaves with radial basis functions: a cubic B-spline centred on
each example, its support radius twice the distance to the nearest other example. The
weights solve Phi w = r exactly (least squares when Phi is singular). Parameters are
standardized per dimension, as for Kriging (:mod:`motionvar.ma2010.kriging`).
"""

from __future__ import annotations

import numpy as np
from scipy.spatial.distance import cdist


def cubic_bspline(r: np.ndarray) -> np.ndarray:
    """The uniform cubic B-spline of r = 2 d / radius (support |r| < 2), 2/3 at 0."""
    r = np.abs(r)
    return np.where(r < 1, 2 / 3 - r**2 + 0.5 * r**3, np.where(r < 2, (2 - r) ** 3 / 6, 0.0))


class RBFInterpolation:
    """f(x) = a_0 + a x + sum_i w_i B(2 ||x - x_i|| / radius_i), vector-valued.

    ``linear_rcond``: relative cut-off of the linear term's pseudo-inverse, as
    ``trend_rcond`` of :class:`motionvar.ma2010.kriging.UniversalKriging`."""

    def __init__(self, linear_rcond: float = 0.0):
        self.linear_rcond = linear_rcond

    def fit(self, x: np.ndarray, y: np.ndarray) -> "RBFInterpolation":
        x = np.asarray(x, dtype=float)
        x = x[:, None] if x.ndim == 1 else x
        y = np.asarray(y, dtype=float)
        if x.ndim != 2 or y.ndim != 2 or len(x) != len(y) or len(x) < 1:
            raise ValueError(f"RBFInterpolation.fit: need x (N, p) and y (N, D); got {x.shape}, {y.shape}")
        sd = x.std(axis=0)
        self.x_mean_, self.x_scale_ = x.mean(axis=0), np.where(sd > 1e-12, sd, 1.0)
        xs = (x - self.x_mean_) / self.x_scale_
        design = np.concatenate([np.ones((len(xs), 1)), xs], axis=1)
        self.linear_ = np.linalg.pinv(design, rcond=max(self.linear_rcond, 1e-15)) @ y
        resid = y - design @ self.linear_
        d = cdist(xs, xs)
        distinct = np.where(d > 1e-12, d, np.inf)
        nearest = distinct.min(axis=1)  # all examples at one point: unit radius (standardized units)
        self.radius_ = 2.0 * np.where(np.isfinite(nearest), nearest, 1.0)
        self.x_ = xs
        phi = cubic_bspline(2 * d / self.radius_[None, :])
        self.weights_ = np.linalg.lstsq(phi, resid, rcond=None)[0]
        return self

    def predict(self, x: np.ndarray) -> np.ndarray:
        xs = (np.atleast_2d(np.asarray(x, dtype=float)) - self.x_mean_) / self.x_scale_
        phi = cubic_bspline(2 * cdist(xs, self.x_) / self.radius_[None, :])
        return self.linear_[0] + xs @ self.linear_[1:] + phi @ self.weights_
