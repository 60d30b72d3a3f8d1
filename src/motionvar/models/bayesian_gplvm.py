"""Bayesian GPLVM, shared by two papers: the nonlinear baseline of Du 2022, Fig. 3.10-3.11
(wrapped for functional data in :mod:`motionvar.du2022.fda.functional_gplvm`) and the GPLVM
rival of Ma et al. 2010, Sec. 7.4 (:mod:`motionvar.ma2010.baselines.gplvm`).

The thesis used GPy's ``DPBayesianGPLVM`` (a Bayesian GPLVM with a discriminative prior on
the latent means, labels from k-means++ on joint-position splines, RBF kernel, L-BFGS-B,
PCA initialisation; Sec. 3.3.5). This is a compact torch version of the same model:

- Bayesian GPLVM of Titsias & Lawrence (2010): q(X) = prod_n N(mu_n, diag(S_n)), prior
  N(0, I), M inducing inputs Z, ARD RBF kernel k(x, x') = s_f^2 exp(-sum_q (x_q - x'_q)^2
  / (2 l_q^2)), Gaussian noise; the collapsed variational lower bound with the psi
  statistics psi0, Psi1, Psi2 (their Eq. 14 and 17, in the numerically stable form of
  GPflow's ``BayesianGPLVM.elbo``).
- Optional discriminative prior on the latent means (Urtasun & Darrell 2007, as GPy's
  ``DGPLVM`` prior): log p(mu) = -(1 / sigma_d^2) tr((S_b + 0.1 I)^-1 S_w) with between-
  and within-class scatter S_b, S_w of the labelled means.
- Initialisation as GPy's: PCA scores standardised per dimension, ARD lengthscales
  1 / (variance fraction / largest fraction), latent variances U(0, 0.1), inducing inputs
  a random subset of the initial means.
- All parameters by scipy's L-BFGS-B on the negative bound, gradients by torch autograd.

Cost: one bound-and-gradient evaluation is O(N M^2 Q + N M D) (Psi2 and Psi1^T Y). The full
SVD behind the PCA initialisation, O(N D min(N, D)), is done once per data matrix and
shared by later fits of the same Y at other latent dimensions (Fig. 3.10 fits d = 1..40 on
one data set), see :func:`pca_scores`; the result is bit-for-bit that of a fresh
``PCA(Q, svd_solver="full")``. The L-BFGS-B box is passed as a vectorised
``scipy.optimize.Bounds`` (a list of one tuple per parameter costs a few tenths of a second
per fit at N = 1480). The bound's arithmetic is deliberately left as it is: 200 L-BFGS-B
iterations from the same start are sensitive to rounding (a 1e-15 relative change of the
initial point, or 2 torch threads instead of 1, moves the final bound by 1e-4..1e-2 relative),
so any reordering of the floating-point work would change the fitted numbers.

Differences from GPy that a reader should know: outputs are centred and divided by one
global scale (so the noise variance starts at ``noise_init`` of the data variance); the
latent positions of new data are not inferred (``transform`` returns the training
latents only).
"""

from __future__ import annotations

import hashlib
import math

import numpy as np
from scipy.optimize import Bounds, minimize
from sklearn.decomposition import PCA

from ..core.progress import ProgressLog

# box constraints of the log-parameters (GPy constrains them positive); mu and Z are free
_LOG_BOUNDS: dict[str, tuple[float, float]] = {
    "log_S": (-12.0, 5.0),
    "log_sf2": (-8.0, 8.0),
    "log_ell": (-8.0, 12.0),
    "log_noise": (-12.0, 4.0),
}

# the last data matrix's full PCA: (key, mean, all components, all explained-variance ratios)
_PCA_CACHE: list[tuple[tuple, np.ndarray, np.ndarray, np.ndarray]] = []


def _torch():
    import torch

    return torch


def _full_pca(Y: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Mean, all min(N, D) components and explained-variance ratios of sklearn's
    ``PCA(svd_solver="full")`` on Y, cached for the last Y (keyed by a hash of its bytes)."""
    Y = np.ascontiguousarray(Y, dtype=float)
    key = (Y.shape, hashlib.blake2b(Y.data, digest_size=20).digest())
    if _PCA_CACHE and _PCA_CACHE[0][0] == key:
        return _PCA_CACHE[0][1:]
    pca = PCA(n_components=None, svd_solver="full").fit(Y)
    out = (pca.mean_, pca.components_, pca.explained_variance_ratio_)
    for a in out:
        a.setflags(write=False)  # shared by later fits
    _PCA_CACHE[:] = [(key, *out)]
    return out


def pca_scores(Y: np.ndarray, n_components: int) -> tuple[np.ndarray, np.ndarray]:
    """(scores (N, Q), explained-variance ratios (Q,)) of the first Q principal components of
    Y: the numbers of ``PCA(Q, svd_solver="full").fit(Y)``'s ``transform(Y)`` and
    ``explained_variance_ratio_``, bit for bit (the same SVD and sign convention; components
    kept contiguous and projected as sklearn's ``transform`` does), but the SVD is made once
    for repeated fits of the same Y."""
    Y = np.ascontiguousarray(Y, dtype=float)
    mean, components, ratio = _full_pca(Y)
    C = components[:n_components].copy()
    X = Y @ C.T
    X -= mean.reshape(1, -1) @ C.T
    return X, ratio[:n_components].copy()


def psi_statistics(mu, S, Z, sf2, ell):
    """psi0 (scalar), Psi1 (N, M), Psi2 (M, M) of the ARD RBF kernel under q(X)
    (Titsias & Lawrence 2010, Eq. 15-16), summed over n for psi0 and Psi2."""
    torch = _torch()
    ell2 = ell**2
    N, M = mu.shape[0], Z.shape[0]
    psi0 = N * sf2
    d1 = ell2 + S  # (N, Q)
    diff = mu[:, None, :] - Z[None, :, :]
    log_psi1 = -0.5 * torch.log(d1 / ell2).sum(-1, keepdim=True) - 0.5 * (diff**2 / d1[:, None, :]).sum(-1)
    psi1 = sf2 * torch.exp(log_psi1)
    d2 = ell2 + 2.0 * S
    zbar = 0.5 * (Z[:, None, :] + Z[None, :, :]).reshape(M * M, -1)
    dz = (Z[:, None, :] - Z[None, :, :]).reshape(M * M, -1)
    term_z = -(dz**2 / (4.0 * ell2)).sum(-1)  # (M*M,)
    quad = (mu**2 / d2).sum(-1, keepdim=True) - 2.0 * (mu / d2) @ zbar.T + (1.0 / d2) @ (zbar**2).T
    log_det = -0.5 * torch.log(d2 / ell2).sum(-1, keepdim=True)
    psi2 = sf2**2 * torch.exp(term_z) * torch.exp(log_det - quad).sum(0)
    return psi0, psi1, psi2.reshape(M, M)


def rbf_ard(X1, X2, sf2, ell):
    torch = _torch()
    d = (X1[:, None, :] - X2[None, :, :]) / ell
    return sf2 * torch.exp(-0.5 * (d**2).sum(-1))


def jitter_cholesky(A, jitter: float, tries: int = 6):
    """Cholesky factor of A, adding jitter * mean(diag A) to the diagonal (times 10 per
    failed try) when A is numerically not positive definite (GPy's ``jitchol``)."""
    torch = _torch()
    L, info = torch.linalg.cholesky_ex(A)
    if int(info) == 0:
        return L
    eye = torch.eye(A.shape[0], dtype=A.dtype)
    scale = torch.diagonal(A).mean().detach()
    for k in range(tries):
        L, info = torch.linalg.cholesky_ex(A + (jitter * 10.0**k) * scale * eye)
        if int(info) == 0:
            return L
    raise torch.linalg.LinAlgError("matrix not positive definite even with jitter")


def discriminative_log_prior(mu, onehot, sigma2: float):
    """GPy ``DGPLVM`` prior (Urtasun & Darrell 2007): -(1/sigma2) tr((S_b + 0.1 I)^-1 S_w)."""
    torch = _torch()
    N, Q = mu.shape
    counts = onehot.sum(0)
    means = (onehot.T @ mu) / counts[:, None]  # (C, Q)
    m0 = mu.mean(0)
    between = means - m0
    Sb = (between.T * (counts / N)) @ between
    within = mu - onehot @ means
    Sw = within.T @ within / N
    eye = torch.eye(Q, dtype=mu.dtype)
    return -torch.trace(torch.linalg.solve(Sb + 0.1 * eye, Sw)) / sigma2


class BayesianGPLVM:
    """Bayesian GPLVM on a data matrix Y (N, P), sklearn-style (see module docstring).

    Args:
        n_components: latent dimension Q.
        n_inducing: number of inducing inputs M (capped at N).
        max_iter: L-BFGS-B iterations.
        noise_init: initial noise variance as a fraction of the (scaled) data variance.
        discriminative_sigma2: sigma^2 of the discriminative prior (None: no prior).
        random_state: seed of the initial latent variances and inducing inputs.
        jitter: added to the diagonal of K_uu.

    Fitted attributes: ``latent_mean_`` (N, Q), ``latent_variance_`` (N, Q),
    ``inducing_`` (M, Q), ``lengthscales_`` (Q,), ``signal_variance_``,
    ``noise_variance_`` (in scaled units), ``bound_`` (final lower bound incl. prior),
    ``n_iter_``, ``y_mean_``, ``y_scale_``.
    """

    def __init__(
        self,
        n_components: int = 20,
        n_inducing: int = 30,
        max_iter: int = 300,
        noise_init: float = 0.01,
        discriminative_sigma2: float | None = None,
        random_state: int = 0,
        jitter: float = 1e-4,
    ) -> None:
        self.n_components = n_components
        self.n_inducing = n_inducing
        self.max_iter = max_iter
        self.noise_init = noise_init
        self.discriminative_sigma2 = discriminative_sigma2
        self.random_state = random_state
        self.jitter = jitter

    def _init_params(self, Y: np.ndarray) -> dict[str, np.ndarray]:
        N = Y.shape[0]
        Q = int(self.n_components)
        rng = np.random.default_rng(self.random_state)
        X, ratio = pca_scores(Y, Q)
        X = (X - X.mean(0)) / np.where(X.std(0) > 0, X.std(0), 1.0)
        fracs = ratio / ratio.max()
        M = min(int(self.n_inducing), N)
        return {
            "mu": X,
            "log_S": np.log(rng.uniform(1e-3, 0.1, size=X.shape)),
            "Z": X[rng.permutation(N)[:M]].copy(),
            "log_sf2": np.array([0.0]),
            "log_ell": np.log(1.0 / np.maximum(fracs, 1e-6)),
            "log_noise": np.array([math.log(self.noise_init)]),
        }

    def _bound(self, p, Y, YY: float, onehot):
        """Collapsed lower bound (Titsias & Lawrence 2010) + log discriminative prior."""
        torch = _torch()
        N, D = Y.shape
        mu, S = p["mu"], torch.exp(p["log_S"])
        sf2, ell, noise = torch.exp(p["log_sf2"][0]), torch.exp(p["log_ell"]), torch.exp(p["log_noise"][0])
        Z = p["Z"]
        M = Z.shape[0]
        psi0, psi1, psi2 = psi_statistics(mu, S, Z, sf2, ell)
        Kuu = rbf_ard(Z, Z, sf2, ell) + (self.jitter * sf2) * torch.eye(M, dtype=Y.dtype)
        L = jitter_cholesky(Kuu, self.jitter)
        sigma = torch.sqrt(noise)
        A = torch.linalg.solve_triangular(L, psi1.T, upper=False) / sigma
        tmp = torch.linalg.solve_triangular(L, psi2, upper=False)
        AAT = torch.linalg.solve_triangular(L, tmp.T, upper=False) / noise
        B = AAT + torch.eye(M, dtype=Y.dtype)
        LB = jitter_cholesky(B, self.jitter)
        c = torch.linalg.solve_triangular(LB, A @ Y, upper=False) / sigma
        bound = -0.5 * N * D * torch.log(2 * math.pi * noise)
        bound = bound - D * torch.log(torch.diagonal(LB)).sum()
        bound = bound - 0.5 * YY / noise + 0.5 * (c**2).sum()
        bound = bound - 0.5 * D * (psi0 / noise - torch.diagonal(AAT).sum())
        bound = bound - 0.5 * (S + mu**2 - 1.0 - torch.log(S)).sum()
        if onehot is not None:
            bound = bound + discriminative_log_prior(mu, onehot, float(self.discriminative_sigma2))
        return bound, (L, LB, c)

    def fit(self, Y: np.ndarray, labels: np.ndarray | None = None) -> "BayesianGPLVM":
        torch = _torch()
        Y = np.asarray(Y, dtype=float)
        if Y.ndim != 2 or not np.all(np.isfinite(Y)):
            raise ValueError(f"BayesianGPLVM.fit: Y must be a finite 2-D array; got shape {Y.shape}")
        N, P = Y.shape
        if not 1 <= int(self.n_components) <= min(N, P):
            raise ValueError(f"BayesianGPLVM: n_components must be in [1, {min(N, P)}]; got {self.n_components}")
        onehot = None
        if self.discriminative_sigma2 is not None:
            if labels is None or len(labels) != N:
                raise ValueError("BayesianGPLVM: the discriminative prior needs one label per row of Y")
            _, codes = np.unique(np.asarray(labels), return_inverse=True)
            onehot = torch.as_tensor(np.eye(codes.max() + 1)[codes], dtype=torch.float64)
        self.y_mean_ = Y.mean(0)
        self.y_scale_ = float(np.sqrt(np.mean((Y - self.y_mean_) ** 2))) or 1.0
        Yn = (Y - self.y_mean_) / self.y_scale_
        Yt = torch.as_tensor(Yn, dtype=torch.float64)
        YY = float(np.sum(Yn**2))
        init = self._init_params(Yn)
        names = list(init)
        shapes = [init[k].shape for k in names]
        sizes = [int(np.prod(s)) for s in shapes]

        def unpack(theta):
            out, i = {}, 0
            for k, s, n in zip(names, shapes, sizes):
                out[k] = theta[i : i + n].reshape(s)
                i += n
            return out

        scale = 1.0 / (N * P)  # the bound per output value: same optimum, O(1) numbers

        def fun(theta):
            t = torch.as_tensor(theta, dtype=torch.float64).requires_grad_(True)
            try:
                bound, _ = self._bound(unpack(t), Yt, YY, onehot)
            except torch.linalg.LinAlgError:
                return 1e300, np.zeros_like(theta)
            (g,) = torch.autograd.grad(-bound * scale, t)
            return float(-bound.detach()) * scale, g.numpy()

        theta0 = np.concatenate([init[k].ravel() for k in names])
        # keep variances, lengthscales and noise in a sane range (GPy constrains them positive)
        lims = [_LOG_BOUNDS.get(k, (-np.inf, np.inf)) for k in names]
        bounds = Bounds(np.repeat([lo for lo, _ in lims], sizes), np.repeat([hi for _, hi in lims], sizes))
        progress = ProgressLog(f"Bayesian GPLVM ({N} points) L-BFGS-B iteration", int(self.max_iter), at_most=True)
        res = minimize(
            fun,
            theta0,
            jac=True,
            method="L-BFGS-B",
            bounds=bounds,
            callback=progress.scipy_callback(),
            options={"maxiter": int(self.max_iter)},
        )
        p = unpack(torch.as_tensor(res.x, dtype=torch.float64))
        with torch.no_grad():
            bound, (L, LB, c) = self._bound(p, Yt, YY, onehot)
            # predictive mean at x*: k(x*, Z) L^-T LB^-T c
            w = torch.linalg.solve_triangular(LB.T, c, upper=True)
            w = torch.linalg.solve_triangular(L.T, w, upper=True)
        self.latent_mean_ = p["mu"].numpy().copy()
        self.latent_variance_ = np.exp(p["log_S"].numpy())
        self.inducing_ = p["Z"].numpy().copy()
        self.signal_variance_ = math.exp(float(p["log_sf2"][0]))
        self.lengthscales_ = np.exp(p["log_ell"].numpy())
        self.noise_variance_ = math.exp(float(p["log_noise"][0]))
        self.bound_ = float(bound)
        self.n_iter_ = int(res.nit)
        self.converged_ = bool(res.success)
        self.message_ = str(res.message)
        self._predict_weights = w.numpy()
        return self

    def fit_transform(self, Y: np.ndarray, labels: np.ndarray | None = None) -> np.ndarray:
        return self.fit(Y, labels).latent_mean_

    def predict(self, latent: np.ndarray) -> np.ndarray:
        """Posterior mean of the outputs (N*, P) at latent points (N*, Q) (the inverse map)."""
        torch = _torch()
        if not hasattr(self, "latent_mean_"):
            raise RuntimeError("BayesianGPLVM is not fitted yet: call fit first")
        X = torch.as_tensor(np.atleast_2d(latent), dtype=torch.float64)
        K = rbf_ard(
            X, torch.as_tensor(self.inducing_), torch.tensor(self.signal_variance_), torch.as_tensor(self.lengthscales_)
        ).numpy()
        return self.y_mean_ + self.y_scale_ * (K @ self._predict_weights)
