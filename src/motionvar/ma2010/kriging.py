"""Universal Kriging (Ma et al. 2010, Sec. 6.1; Mukai & Kuriyama 2005; Huijbregts &
Matheron 1971).

S(c) = m(c) + sum_i lambda_i(c) r_i with sum_i lambda_i = 1. The trend m is a hyperplane
in the parameters fitted by least squares (Eq. 12-13); the residuals r_i = s_i - m(c_i)
are Kriged with weights from the bordered system

    [Lambda(c)'; kappa] = [[R, 1'], [1, 0]]^-1 [gamma(c)'; 1],   R_ij = gamma(||c_i - c_j||),

whose inverse is computed once when fitting (pseudo-inverse: examples with identical
parameters make R singular). The variogram gamma is fitted by weighted least squares to
the binned empirical semivariogram of the residuals, 0.5 * mean_d (r_id - r_jd)^2 against
||c_i - c_j||. Parameters are standardized per dimension before distances are taken
(the paper mixes centimetres and radians in [c, xi] and does not say how it scales them).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.optimize import least_squares
from scipy.spatial.distance import cdist, pdist


def _spherical(h: np.ndarray, s: float, r: float) -> np.ndarray:
    x = np.minimum(h / max(r, 1e-12), 1.0)
    return s * (1.5 * x - 0.5 * x**3)


# model -> (function of h and the parameters after the nugget, initial guess, lower bounds, upper bounds)
VARIOGRAM_MODELS = {
    "linear": (lambda h, s: s * h, lambda h, g: [g.max() / max(h.max(), 1e-12)], [0.0], [np.inf]),
    "power": (lambda h, s, a: s * h**a, lambda h, g: [g.max() / max(h.max(), 1e-12), 1.0], [0.0, 1e-3], [np.inf, 1.999]),
    "exponential": (lambda h, s, r: s * (1 - np.exp(-h / max(r, 1e-12))), lambda h, g: [g.max(), h.max() / 3], [0.0, 1e-6], [np.inf, np.inf]),
    "gaussian": (lambda h, s, r: s * (1 - np.exp(-((h / max(r, 1e-12)) ** 2))), lambda h, g: [g.max(), h.max() / 2], [0.0, 1e-6], [np.inf, np.inf]),
    "spherical": (_spherical, lambda h, g: [g.max(), h.max()], [0.0, 1e-6], [np.inf, np.inf]),
}


@dataclass(frozen=True)
class Variogram:
    """gamma(h) = nugget + f(h) for h > 0, gamma(0) = 0."""

    model: str
    nugget: float
    params: tuple[float, ...]

    def __call__(self, h: np.ndarray) -> np.ndarray:
        h = np.asarray(h, dtype=float)
        f = VARIOGRAM_MODELS[self.model][0]
        return np.where(h > 0, self.nugget + f(h, *self.params), 0.0)


def empirical_semivariogram(x: np.ndarray, r: np.ndarray, n_bins: int = 20) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Binned empirical semivariogram of residuals r (N, D) over parameters x (N, p).

    Returns the mean lag, the mean semivariance 0.5 * mean_d (r_i - r_j)^2 and the pair
    count of each non-empty bin (quantile bins of the pairwise distances)."""
    h = pdist(x)
    gram = r @ r.T / r.shape[1]
    sq = np.diag(gram)[:, None] + np.diag(gram)[None, :] - 2 * gram
    iu = np.triu_indices(len(x), k=1)
    g = 0.5 * np.maximum(sq[iu], 0.0)
    edges = np.unique(np.quantile(h, np.linspace(0, 1, n_bins + 1)))
    if len(edges) < 2:
        return np.array([h.mean()]), np.array([g.mean()]), np.array([len(h)])
    idx = np.clip(np.searchsorted(edges, h, side="right") - 1, 0, len(edges) - 2)
    counts = np.bincount(idx, minlength=len(edges) - 1)
    keep = counts > 0
    hm = np.bincount(idx, weights=h, minlength=len(edges) - 1)[keep] / counts[keep]
    gm = np.bincount(idx, weights=g, minlength=len(edges) - 1)[keep] / counts[keep]
    return hm, gm, counts[keep]


def fit_variogram(x: np.ndarray, r: np.ndarray, model: str = "linear", n_bins: int = 20) -> Variogram:
    """Fit ``model`` (with a nugget >= 0) to the empirical semivariogram by least squares
    weighted by the pair counts; ``model='auto'`` takes the model with the least error."""
    if model == "auto":
        fits = [fit_variogram(x, r, m, n_bins) for m in VARIOGRAM_MODELS]
        hm, gm, cnt = empirical_semivariogram(x, r, n_bins)
        return min(fits, key=lambda v: float(np.sum(cnt * (v(hm) - gm) ** 2)))
    if model not in VARIOGRAM_MODELS:
        raise ValueError(f"fit_variogram: unknown variogram model {model!r} (choose from {sorted(VARIOGRAM_MODELS)} or 'auto')")
    if len(x) < 2:
        return Variogram(model, 0.0, tuple(VARIOGRAM_MODELS[model][1](np.ones(1), np.ones(1))))
    hm, gm, cnt = empirical_semivariogram(x, r, n_bins)
    f, init, lo, hi = VARIOGRAM_MODELS[model]
    w = np.sqrt(cnt / cnt.sum())
    scale = max(float(gm.max()), 1e-300)

    def resid(p: np.ndarray) -> np.ndarray:
        return w * (p[0] + f(hm, *p[1:]) - gm) / scale

    lower, upper = np.array([0.0, *lo]), np.array([np.inf, *hi])
    p0 = np.clip(np.array([0.0, *init(hm, gm)], dtype=float), lower, upper)
    sol = least_squares(resid, p0, bounds=(lower, upper))
    return Variogram(model, float(sol.x[0]), tuple(float(v) for v in sol.x[1:]))


class UniversalKriging:
    """Universal Kriging of vector-valued samples s_i (N, D) at parameters x_i (N, p)."""

    def __init__(self, variogram_model: str = "linear", n_bins: int = 20, standardize: bool = True):
        self.variogram_model = variogram_model
        self.n_bins = n_bins
        self.standardize = standardize

    def _scale(self, x: np.ndarray) -> np.ndarray:
        return (x - self.x_mean_) / self.x_scale_

    def fit(self, x: np.ndarray, y: np.ndarray) -> "UniversalKriging":
        """Fit the trend hyperplane, the variogram and the inverse bordered matrix."""
        x = np.asarray(x, dtype=float)
        y = np.asarray(y, dtype=float)
        x = x[:, None] if x.ndim == 1 else x
        if x.ndim != 2 or y.ndim != 2 or len(x) != len(y) or len(x) < 1:
            raise ValueError(f"UniversalKriging.fit: need x (N, p) and y (N, D); got {x.shape}, {y.shape}")
        if not (np.isfinite(x).all() and np.isfinite(y).all()):
            raise ValueError("UniversalKriging.fit: x and y must be finite")
        sd = x.std(axis=0)
        self.x_mean_ = x.mean(axis=0) if self.standardize else np.zeros(x.shape[1])
        self.x_scale_ = np.where(sd > 1e-12, sd, 1.0) if self.standardize else np.ones(x.shape[1])
        xs = self._scale(x)
        design = np.concatenate([np.ones((len(xs), 1)), xs], axis=1)
        self.trend_ = np.linalg.pinv(design) @ y  # Eq. 12-13: hyperplane coefficients
        self.residuals_ = y - design @ self.trend_
        self.x_ = xs
        self.variogram_ = fit_variogram(xs, self.residuals_, self.variogram_model, self.n_bins)
        n = len(xs)
        bordered = np.zeros((n + 1, n + 1))
        bordered[:n, :n] = self.variogram_(cdist(xs, xs))
        bordered[:n, n] = bordered[n, :n] = 1.0
        self.bordered_inv_ = np.linalg.pinv(bordered)  # precomputed once (Sec. 6.1)
        return self

    def weights(self, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Kriging weights lambda (M, N) and Lagrange multipliers kappa (M,) at x (M, p)."""
        xs = self._scale(np.atleast_2d(np.asarray(x, dtype=float)))
        rhs = np.concatenate([self.variogram_(cdist(xs, self.x_)), np.ones((len(xs), 1))], axis=1)
        sol = rhs @ self.bordered_inv_.T
        return sol[:, :-1], sol[:, -1]

    def trend(self, x: np.ndarray) -> np.ndarray:
        xs = self._scale(np.atleast_2d(np.asarray(x, dtype=float)))
        return self.trend_[0] + xs @ self.trend_[1:]

    def predict(self, x: np.ndarray) -> np.ndarray:
        """S(x) = m(x) + Lambda(x) R, shape (M, D)."""
        lam, _ = self.weights(x)
        return self.trend(x) + lam @ self.residuals_

    def kriging_variance(self, x: np.ndarray) -> np.ndarray:
        """(M,) Kriging variance sum_i lambda_i gamma_i + kappa, in units of the fitted
        semivariogram (Mukai & Kuriyama's reliability measure)."""
        xs = self._scale(np.atleast_2d(np.asarray(x, dtype=float)))
        g = self.variogram_(cdist(xs, self.x_))
        lam, kappa = self.weights(x)
        return np.sum(lam * g, axis=1) + kappa
