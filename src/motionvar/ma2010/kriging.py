"""Universal Kriging (Ma et al. 2010, Sec. 6.1; Mukai & Kuriyama 2005; Huijbregts &
Matheron 1971).

S(c) = m(c) + sum_i lambda_i(c) r_i with sum_i lambda_i = 1. The trend m is a hyperplane
in the parameters fitted by least squares (Eq. 12-13); the residuals r_i = s_i - m(c_i)
are Kriged with weights from the bordered system

    [Lambda(c)'; kappa] = [[R, 1'], [1, 0]]^-1 [gamma(c)'; 1],   R_ij = gamma(||c_i - c_j||),

whose inverse is computed once when fitting (pseudo-inverse: examples with identical
parameters make R singular). Parameters are standardized per dimension before distances
are taken (the paper mixes centimetres and radians in [c, xi] and does not say how it
scales them).

The variogram gamma (one per interpolator, i.e. per joint group: Eq. 11 has one weight
lambda_i^I per example and group) is fitted to the binned empirical semivariogram of the
residuals, gamma(h) = 0.5 * mean_d w_d (r_id - r_jd)^2 over pairs at distance ~h:

- ``scale`` (the paper is silent on units; a clip vector mixes radians, key times in
  seconds and, for flight, root heights in cm): "sd" weighs each output dimension by
  1 / its variance (w_d = 1/sd_d^2, constant dimensions left out), so every varying
  dimension counts alike whatever its unit and a semivariance of ~1 means "as different
  as two unrelated examples"; "none" averages the raw squares (w_d = 1).
  The weights lambda do not change when gamma is multiplied by a constant, so only the
  shape of the semivariogram matters, and that is what the scaling changes.
- ``weights``: "cressie" fits by least squares weighted as Cressie (1985),
  sum_k N_k (gamma_hat_k / gamma(h_k) - 1)^2 (N_k pairs in bin k); "pairs" weighs the
  squared differences by N_k.
- ``model``: linear, power, exponential, gaussian or spherical, each with a nugget; "auto"
  fits linear, exponential, Gaussian and spherical and keeps the one with the least
  Akaike criterion n log(E/n) + 2k on the n binned points (E the weighted error, k the
  number of parameters with the nugget), ties to the simpler model.
- bins: quantiles of the pair distances up to half the largest (``max_lag``; the usual rule
  of Journel & Huijbregts 1978: longer lags have few pairs, at the edges of the sample),
  ``n_bins`` of them, or by default ~100 pairs each within 20-100 bins (:func:`bin_count`).

("linear", "none", "pairs", max_lag 1, 20 bins) is the plain single fit that the Ma 2010
variogram table (:mod:`.evaluations.variogram`, series "old") shows beside the chosen one.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from scipy.optimize import least_squares, nnls
from scipy.spatial.distance import cdist, pdist


def _spherical(h: np.ndarray, s: float, r: float) -> np.ndarray:
    x = np.minimum(h / max(r, 1e-12), 1.0)
    return s * (1.5 * x - 0.5 * x**3)


# model -> (function of h, the sill or slope s and the shape parameter (range or exponent),
# grid of the shape parameter to start from (given the largest lag; None: no shape), lower
# and upper bounds of [s, shape]). Fitted on gamma scaled to a maximum of 1 and lags in
# standardized parameter units.
VARIOGRAM_MODELS = {
    "linear": (lambda h, s: s * h, None, [0.0], [np.inf]),
    "power": (lambda h, s, a: s * h**a, lambda hmax: np.linspace(0.1, 1.9, 19), [0.0, 1e-3], [np.inf, 1.999]),
    "exponential": (
        lambda h, s, r: s * (1 - np.exp(-h / max(r, 1e-12))),
        lambda hmax: hmax * np.geomspace(1e-2, 10.0, 31),
        [0.0, 1e-6],
        [np.inf, np.inf],
    ),
    "gaussian": (
        lambda h, s, r: s * (1 - np.exp(-((h / max(r, 1e-12)) ** 2))),
        lambda hmax: hmax * np.geomspace(1e-2, 10.0, 31),
        [0.0, 1e-6],
        [np.inf, np.inf],
    ),
    "spherical": (_spherical, lambda hmax: hmax * np.geomspace(1e-2, 10.0, 31), [0.0, 1e-6], [np.inf, np.inf]),
}
AUTO_MODELS = ("linear", "exponential", "gaussian", "spherical")  # candidates of "auto"
VARIOGRAM_SCALES = ("sd", "none")
VARIOGRAM_WEIGHTS = ("cressie", "pairs")
MAX_LAG = 0.5  # bins cover lags up to this fraction of the largest (Journel & Huijbregts 1978)
PAIRS_PER_BIN, MIN_BINS, MAX_BINS = 100, 20, 100  # n_bins None: about this many pairs per bin, within these
_RANGE_MAX = 10.0  # the range is bounded at this many times the largest binned lag


@dataclass(frozen=True)
class Variogram:
    """gamma(h) = nugget + f(h) for h > 0, gamma(0) = 0."""

    model: str
    nugget: float
    params: tuple[float, ...]

    def __call__(self, h: np.ndarray) -> np.ndarray:
        h = np.asarray(h, dtype=float)
        return np.where(h > 0, self.curve(h), 0.0)

    def curve(self, h: np.ndarray) -> np.ndarray:
        """nugget + f(h), the limit from above (what a binned semivariogram estimates)."""
        return self.nugget + VARIOGRAM_MODELS[self.model][0](np.asarray(h, dtype=float), *self.params)

    def describe(self) -> dict[str, float | str]:
        """model, nugget, partial sill (or slope for linear/power), range (NaN when the
        model has none) and exponent (power only, else NaN)."""
        p = self.params
        bounded = self.model in ("exponential", "gaussian", "spherical")
        return {
            "model": self.model,
            "nugget": self.nugget,
            "partial_sill": p[0] if bounded else np.nan,
            "slope": np.nan if bounded else p[0],
            "range": p[1] if bounded else np.nan,
            "exponent": p[1] if self.model == "power" else np.nan,
        }


@dataclass(frozen=True)
class VariogramFit:
    """A fitted variogram with what it was fitted to: the binned empirical semivariogram
    (mean lag, semivariance, pairs per bin), every candidate model fitted (one, or the
    four of "auto") with its weighted error and Akaike criterion, and the settings."""

    variogram: Variogram
    lag: np.ndarray
    gamma: np.ndarray
    pairs: np.ndarray
    candidates: dict[str, Variogram] = field(default_factory=dict)
    error: dict[str, float] = field(default_factory=dict)
    aic: dict[str, float] = field(default_factory=dict)
    scale: str = "none"
    weights: str = "cressie"


def output_weights(r: np.ndarray, scale: str) -> np.ndarray:
    """(D,) weights w_d of the output dimensions in the semivariance (module docstring):
    "none" ones; "sd" 1 / variance, zero for (numerically) constant dimensions."""
    if scale not in VARIOGRAM_SCALES:
        raise ValueError(f"variogram scale must be one of {VARIOGRAM_SCALES}; got {scale!r}")
    r = np.asarray(r, dtype=float)
    if scale == "none":
        return np.ones(r.shape[1])
    sd = r.std(axis=0)
    varying = sd > 1e-8 * max(float(sd.max(initial=0.0)), 1e-300)
    return np.where(varying, 1.0 / np.where(varying, sd, 1.0) ** 2, 0.0)


def pair_semivariances(x: np.ndarray, r: np.ndarray, scale: str) -> tuple[np.ndarray, np.ndarray]:
    """Distance ||x_i - x_j|| and semivariance 0.5 * sum_d w_d (r_id - r_jd)^2 / n_d of every
    pair i < j (the variogram cloud; n_d = D, or the varying dimensions for "sd")."""
    x, r = np.asarray(x, dtype=float), np.asarray(r, dtype=float)
    w = output_weights(r, scale)
    n_d = max(int(np.count_nonzero(w)), 1) if scale == "sd" else r.shape[1]
    rw = r * np.sqrt(w)
    gram = rw @ rw.T / n_d
    sq = np.diag(gram)[:, None] + np.diag(gram)[None, :] - 2 * gram
    iu = np.triu_indices(len(x), k=1)
    return pdist(x), 0.5 * np.maximum(sq[iu], 0.0)


def bin_count(n_pairs: int) -> int:
    """Number of lag bins for ``n_pairs`` pairs when none is given: ~``PAIRS_PER_BIN`` pairs
    each, at least ``MIN_BINS`` (small samples: noisy bins rather than no shape) and at most
    ``MAX_BINS``. More pairs buy finer bins at short lags, where the structure is."""
    return int(np.clip(n_pairs // PAIRS_PER_BIN, MIN_BINS, MAX_BINS))


def empirical_semivariogram(
    x: np.ndarray,
    r: np.ndarray,
    n_bins: int | None,
    scale: str,
    max_lag: float = 1.0,
    pair_mask: np.ndarray | None = None,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Binned empirical semivariogram of residuals r (N, D) over parameters x (N, p).

    Returns the mean lag, the mean semivariance (:func:`pair_semivariances`) and the pair
    count of each non-empty bin (quantile bins of the pairwise distances up to
    ``max_lag`` times the largest one); ``pair_mask`` (pairs i < j in ``pdist`` order)
    keeps only some pairs (the cutoff stays that of all pairs)."""
    h, g = pair_semivariances(x, r, scale)
    keep = np.ones(len(h), dtype=bool) if pair_mask is None else np.asarray(pair_mask, dtype=bool)
    if keep.shape != h.shape:
        raise ValueError(f"empirical_semivariogram: pair_mask has {keep.shape} entries for {len(h)} pairs")
    if max_lag < 1.0 and len(h):
        keep = keep & (h <= max_lag * h.max())
    h, g = h[keep], g[keep]
    if len(h) == 0:
        return np.zeros(0), np.zeros(0), np.zeros(0, dtype=np.int64)
    edges = np.unique(np.quantile(h, np.linspace(0, 1, (bin_count(len(h)) if n_bins is None else n_bins) + 1)))
    if len(edges) < 2:
        return np.array([h.mean()]), np.array([g.mean()]), np.array([len(h)])
    idx = np.clip(np.searchsorted(edges, h, side="right") - 1, 0, len(edges) - 2)
    counts = np.bincount(idx, minlength=len(edges) - 1)
    keep = counts > 0
    hm = np.bincount(idx, weights=h, minlength=len(edges) - 1)[keep] / counts[keep]
    gm = np.bincount(idx, weights=g, minlength=len(edges) - 1)[keep] / counts[keep]
    return hm, gm, counts[keep]


def _default_params(model: str, s: float = 1.0) -> tuple[float, ...]:
    """Sill or slope ``s`` and a shape of 1: the variogram of too few examples to fit one."""
    return (s,) if VARIOGRAM_MODELS[model][1] is None else (s, 1.0)


def _fit_model(model: str, hm: np.ndarray, gm: np.ndarray, cnt: np.ndarray, weights: str) -> tuple[np.ndarray, float]:
    """Parameters [nugget, s, *shape] and weighted error of ``model`` on gamma scaled to max 1.

    Starts from the best point of a grid over the shape parameter (for each shape the
    nugget and s are a non-negative linear least-squares fit, Cressie's weights taken at
    the data), then refines all parameters with ``least_squares``."""
    f, grid, lo, hi = VARIOGRAM_MODELS[model]
    lower = np.array([0.0, *lo])
    upper = np.array([np.inf, *hi])
    if model in ("exponential", "gaussian", "spherical"):  # a range parameter
        upper[2] = _RANGE_MAX * max(float(hm.max()), 1e-6)
    if weights == "cressie":
        w = np.sqrt(cnt)
        w_lin = w / np.maximum(gm, 1e-9)  # sqrt(N) (gamma_hat - gamma) / gamma_hat ~ sqrt(N) (gamma_hat / gamma - 1)

        def resid(p: np.ndarray) -> np.ndarray:
            return w * (gm / np.maximum(p[0] + f(hm, *p[1:]), 1e-9) - 1.0)
    else:
        w = w_lin = np.sqrt(cnt / cnt.sum())

        def resid(p: np.ndarray) -> np.ndarray:
            return w * (p[0] + f(hm, *p[1:]) - gm)

    shapes = [()] if grid is None else [(q,) for q in grid(max(float(hm.max()), 1e-6))]
    starts = []
    for shape in shapes:  # loop over <= 31 grid values
        basis = np.column_stack([np.ones_like(hm), f(hm, 1.0, *shape)])
        coef = nnls(basis * w_lin[:, None], gm * w_lin)[0]
        p = np.clip(np.array([*coef, *shape]), lower, np.minimum(upper, 1e12))
        starts.append((float(np.sum(resid(p) ** 2)), p))
    p0 = min(starts, key=lambda c: c[0])[1]
    sol = least_squares(resid, p0, bounds=(lower, upper))
    return sol.x, float(2 * sol.cost)


def fit_semivariogram(
    x: np.ndarray,
    r: np.ndarray,
    model: str,
    n_bins: int | None,
    scale: str,
    weights: str = "cressie",
    max_lag: float = MAX_LAG,
) -> VariogramFit:
    """Fit ``model`` (with a nugget >= 0) to the binned empirical semivariogram of the
    residuals r (N, D) at parameters x (N, p); "auto" chooses among :data:`AUTO_MODELS`
    (module docstring). Returns the fit with the binned semivariogram it was fitted to."""
    if model != "auto" and model not in VARIOGRAM_MODELS:
        raise ValueError(
            f"fit_variogram: unknown variogram model {model!r} (choose from {sorted(VARIOGRAM_MODELS)} or 'auto')"
        )
    if weights not in VARIOGRAM_WEIGHTS:
        raise ValueError(f"fit_variogram: variogram weights must be one of {VARIOGRAM_WEIGHTS}; got {weights!r}")
    output_weights(np.zeros((1, 1)), scale)  # validates scale
    names = AUTO_MODELS if model == "auto" else (model,)
    x, r = np.asarray(x, dtype=float), np.asarray(r, dtype=float)
    if len(x) < 2:
        v = Variogram(names[0], 0.0, _default_params(names[0]))
        empty = np.zeros(0)
        return VariogramFit(v, empty, empty, np.zeros(0, dtype=int), {v.model: v}, scale=scale, weights=weights)
    hm, gm, cnt = empirical_semivariogram(x, r, n_bins, scale, max_lag)
    if len(hm) == 0:  # every pair beyond the cutoff (two examples): use them all
        hm, gm, cnt = empirical_semivariogram(x, r, n_bins, scale, 1.0)
    gmax = float(gm.max())
    if gmax <= 1e-300:  # residuals all alike (the trend explains the samples): any variogram works
        v = Variogram(names[0], 0.0, _default_params(names[0], 0.0))
        return VariogramFit(v, hm, gm, cnt, {v.model: v}, scale=scale, weights=weights)
    candidates, error, aic = {}, {}, {}
    for name in names:
        p, err = _fit_model(name, hm, gm / gmax, cnt, weights)
        p = p * np.r_[gmax, gmax, np.ones(len(p) - 2)]  # nugget and sill/slope back to gamma units
        candidates[name] = Variogram(name, float(p[0]), tuple(float(v) for v in p[1:]))
        error[name] = err
        aic[name] = len(hm) * np.log(max(err, 1e-300) / len(hm)) + 2 * len(p)
    best = min(names, key=lambda m: (round(aic[m], 9), names.index(m)))
    return VariogramFit(candidates[best], hm, gm, cnt, candidates, error, aic, scale, weights)


def fit_variogram(
    x: np.ndarray,
    r: np.ndarray,
    model: str,
    n_bins: int | None,
    scale: str,
    weights: str = "cressie",
    max_lag: float = MAX_LAG,
) -> Variogram:
    """The variogram of :func:`fit_semivariogram`."""
    return fit_semivariogram(x, r, model, n_bins, scale, weights, max_lag).variogram


class UniversalKriging:
    """Universal Kriging of vector-valued samples s_i (N, D) at parameters x_i (N, p).

    ``variogram_model``, ``variogram_scale``, ``variogram_weights``: see the module
    docstring (config ma2010.model.variogram_model, variogram_scale; the weights are Cressie's in
    every model, "pairs" only in the variogram table's plain fit).
    ``trend_rcond``: singular values of the trend's design [1, c] below ``trend_rcond`` x the
    largest count as zero in the pseudo-inverse (0: numerical precision only, the literal
    Eq. 12-13). Parameters that vary together (the two support strides of a symmetric walk)
    leave a thin direction whose hyperplane slope fits noise; a cut drops it."""

    def __init__(
        self,
        variogram_model: str,
        n_bins: int | None = None,
        standardize: bool = True,
        *,
        variogram_scale: str,
        variogram_weights: str = "cressie",
        max_lag: float = MAX_LAG,
        trend_rcond: float = 0.0,
    ):
        if variogram_model != "auto" and variogram_model not in VARIOGRAM_MODELS:
            raise ValueError(
                f"UniversalKriging: unknown variogram model {variogram_model!r} "
                f"(choose from {sorted(VARIOGRAM_MODELS)} or 'auto')"
            )
        if variogram_scale not in VARIOGRAM_SCALES:
            raise ValueError(
                f"UniversalKriging: variogram_scale must be one of {VARIOGRAM_SCALES}; got {variogram_scale!r}"
            )
        if variogram_weights not in VARIOGRAM_WEIGHTS:
            raise ValueError(
                f"UniversalKriging: variogram_weights must be one of {VARIOGRAM_WEIGHTS}; got {variogram_weights!r}"
            )
        self.variogram_model = variogram_model
        self.n_bins = n_bins
        self.standardize = standardize
        self.variogram_scale = variogram_scale
        self.variogram_weights = variogram_weights
        self.max_lag = max_lag
        if not 0.0 <= trend_rcond < 1.0:
            raise ValueError(f"UniversalKriging: trend_rcond must be in [0, 1); got {trend_rcond!r}")
        self.trend_rcond = trend_rcond

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
        # Eq. 12-13: hyperplane coefficients by pseudo-inverse; with trend_rcond > 0 the
        # directions of the parameter cloud thinner than trend_rcond x its widest carry no trend
        self.trend_ = np.linalg.pinv(design, rcond=max(self.trend_rcond, 1e-15)) @ y
        self.residuals_ = y - design @ self.trend_
        # dimensions the trend explains up to rounding are constant (else "sd" would scale noise up)
        exact = self.residuals_.std(axis=0) <= 1e-10 * max(float(y.std(axis=0).max(initial=0.0)), 1e-300)
        self.residuals_[:, exact] = 0.0
        self.x_ = xs
        self.variogram_fit_ = fit_semivariogram(
            xs,
            self.residuals_,
            self.variogram_model,
            self.n_bins,
            self.variogram_scale,
            self.variogram_weights,
            self.max_lag,
        )
        self.variogram_ = self.variogram_fit_.variogram
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
        semivariogram (Mukai & Kuriyama's reliability measure; with ``variogram_scale``
        "sd", in variances of the output dimensions)."""
        xs = self._scale(np.atleast_2d(np.asarray(x, dtype=float)))
        g = self.variogram_(cdist(xs, self.x_))
        lam, kappa = self.weights(x)
        return np.sum(lam * g, axis=1) + kappa
