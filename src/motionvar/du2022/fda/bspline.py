"""Cubic B-spline basis with equally spaced knots on normalised time [0, 1]
(Du 2022, Sec. 3.3.3, Eq. 3.1).

Each sampled function {q_1, ..., q_n} is replaced by q(t) = sum_k c_k phi_k(t), K << n,
with the coefficients c fitted by least squares. The Gram matrix
W_kl = int phi_k(t) phi_l(t) dt gives the functional inner product of Eq. 3.5:
<x, y> = sum_i c_x,i^T W c_y,i.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from scipy.interpolate import BSpline


@dataclass(frozen=True)
class BSplineBasis:
    """K clamped B-spline basis functions of a given degree (3: cubic) on [0, 1] with
    equally spaced interior knots ("the motion data is sampled at a constant frame rate,
    we select equally-spaced knots", Sec. 3.3.3)."""

    n_basis: int
    degree: int = 3
    knots: np.ndarray = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        if int(self.n_basis) != self.n_basis or self.n_basis < self.degree + 1:
            raise ValueError(
                f"BSplineBasis: n_basis must be an integer >= degree + 1 = {self.degree + 1}; got {self.n_basis}"
            )
        n_inner = self.n_basis - self.degree + 1  # breakpoints including 0 and 1
        inner = np.linspace(0.0, 1.0, n_inner)
        knots = np.concatenate([np.zeros(self.degree), inner, np.ones(self.degree)])
        object.__setattr__(self, "knots", knots)

    def design(self, t: np.ndarray) -> np.ndarray:
        """(len(t), K) matrix of basis function values at times t in [0, 1]."""
        t = np.asarray(t, dtype=float)
        if t.ndim != 1 or np.any(t < 0.0) or np.any(t > 1.0):
            raise ValueError("BSplineBasis.design: t must be a 1-D array of times in [0, 1]")
        return BSpline.design_matrix(t, self.knots, self.degree).toarray()

    def design_frames(self, n_frames: int) -> np.ndarray:
        """(n_frames, K) design matrix at n equally spaced frames (first at 0, last at 1)."""
        return self.design(frame_times(n_frames))

    def gram(self) -> np.ndarray:
        """(K, K) Gram matrix int_0^1 phi_k phi_l dt, exact: Gauss-Legendre with
        degree + 1 nodes per knot span integrates the degree-2p products exactly."""
        nodes, weights = np.polynomial.legendre.leggauss(self.degree + 1)
        breaks = np.unique(self.knots)
        a, b = breaks[:-1, None], breaks[1:, None]
        t = (0.5 * (b - a) * nodes + 0.5 * (a + b)).ravel()
        w = (0.5 * (b - a) * weights).ravel()
        B = self.design(t)
        return (B * w[:, None]).T @ B

    def gram_sqrt(self) -> tuple[np.ndarray, np.ndarray]:
        """Symmetric square root W^(1/2) of the Gram matrix and its inverse W^(-1/2):
        Euclidean geometry of W^(1/2) c equals the functional geometry of c (Eq. 3.5)."""
        evals, evecs = np.linalg.eigh(self.gram())
        root = np.sqrt(evals)
        return (evecs * root) @ evecs.T, (evecs / root) @ evecs.T

    def fit(self, values: np.ndarray) -> np.ndarray:
        """Least-squares coefficients (..., K, D) of samples (..., T, D) taken at T equally
        spaced frames over [0, 1] (Eq. 3.1)."""
        values = np.asarray(values, dtype=float)
        T = values.shape[-2]
        if T < self.n_basis:
            raise ValueError(
                f"BSplineBasis.fit: {T} frames cannot determine {self.n_basis} basis coefficients "
                "(choose fewer basis functions or longer clips)"
            )
        pinv = np.linalg.pinv(self.design_frames(T))
        return np.einsum("kt,...td->...kd", pinv, values)

    def evaluate(self, coefs: np.ndarray, n_frames: int) -> np.ndarray:
        """Function values (..., n_frames, D) of coefficients (..., K, D) at equally spaced frames."""
        return np.einsum("tk,...kd->...td", self.design_frames(n_frames), coefs)


def frame_times(n_frames: int) -> np.ndarray:
    """Normalised times of n equally spaced frames: 0, 1/(n-1), ..., 1."""
    if n_frames < 2:
        raise ValueError(f"need at least 2 frames; got {n_frames}")
    return np.linspace(0.0, 1.0, int(n_frames))


def choose_n_basis(n_basis: np.ndarray, rmse: np.ndarray, min_relative_drop: float) -> int:
    """Cut-off rule of Sec. 3.3.3 ("increasing the number of basis functions will not
    significantly reduce the root mean squared error in joint space"): the smallest K from
    which on every further candidate lowers the RMSE by no more than ``min_relative_drop``
    of the current RMSE per added basis function (per function, so that the rule does not
    depend on the spacing of the candidates; "from which on", so that a flat step followed
    by a steep one is not taken for the cut-off). ``n_basis`` ascending; returns the
    largest K if the last step still drops significantly."""
    n_basis = np.asarray(n_basis)
    rmse = np.asarray(rmse, dtype=float)
    if n_basis.ndim != 1 or n_basis.shape != rmse.shape or len(n_basis) == 0:
        raise ValueError("choose_n_basis: n_basis and rmse must be 1-D arrays of the same non-zero length")
    if np.any(np.diff(n_basis) <= 0):
        raise ValueError(f"choose_n_basis: n_basis must be strictly ascending; got {n_basis.tolist()}")
    if not 0.0 <= min_relative_drop < 1.0:
        raise ValueError(f"choose_n_basis: min_relative_drop must be in [0, 1); got {min_relative_drop}")
    drops = (rmse[:-1] - rmse[1:]) / np.maximum(rmse[:-1], 1e-300) / np.diff(n_basis)
    significant = np.flatnonzero(drops > min_relative_drop)
    return int(n_basis[significant[-1] + 1]) if len(significant) else int(n_basis[0])
