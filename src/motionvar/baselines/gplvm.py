"""A MAP Gaussian process latent variable model (Lawrence 2003) in torch, and the helix
trajectory through its latent space that Ma et al. 2010 (Sec. 7.4) use to make long
sequences from it.

Model: Y (N, D), centred, = f(X) + noise with an independent GP per output dimension
sharing one RBF kernel k(x, x') = s^2 exp(-||x - x'||^2 / (2 l^2)) + b^2 delta. The latent
points X (N, q) (initialized by PCA) and the kernel's log-parameters maximize
    log p(Y | X) + log p(X) = -D/2 log|K| - 1/2 tr(K^-1 Y Y') - 1/2 ||X||^2 + const
with Adam. New poses are the GP posterior mean at latent points.
"""

from __future__ import annotations

import numpy as np


class GPLVM:
    """MAP GPLVM (Lawrence 2003).

    Args:
        latent_dim: q.
        n_iter: Adam steps.
        lr: Adam learning rate.
        seed: torch seed (the optimization is otherwise deterministic).
    """

    def __init__(self, latent_dim: int = 3, n_iter: int = 300, lr: float = 0.05, seed: int = 0):
        self.latent_dim = latent_dim
        self.n_iter = n_iter
        self.lr = lr
        self.seed = seed

    def fit(self, y: np.ndarray) -> "GPLVM":
        import torch

        y = np.asarray(y, dtype=float)
        if y.ndim != 2 or len(y) <= self.latent_dim:
            raise ValueError(f"GPLVM.fit: need Y (N, D) with N > latent_dim; got {y.shape}")
        torch.manual_seed(self.seed)
        self.mean_ = y.mean(axis=0)
        self.scale_ = float(y.std()) or 1.0
        yc = torch.as_tensor((y - self.mean_) / self.scale_, dtype=torch.float64)
        u, s, _ = np.linalg.svd(yc.numpy(), full_matrices=False)
        x0 = u[:, : self.latent_dim] * s[: self.latent_dim] / np.sqrt(len(y))
        x0 = x0 / (x0.std(axis=0, keepdims=True) + 1e-12)
        X = torch.tensor(x0, dtype=torch.float64, requires_grad=True)
        log_l = torch.tensor(0.0, dtype=torch.float64, requires_grad=True)
        log_s = torch.tensor(0.0, dtype=torch.float64, requires_grad=True)
        log_b = torch.tensor(np.log(0.1), dtype=torch.float64, requires_grad=True)
        opt = torch.optim.Adam([X, log_l, log_s, log_b], lr=self.lr)
        yyt = yc @ yc.T
        n, d = yc.shape
        eye = torch.eye(n, dtype=torch.float64)
        for _ in range(self.n_iter):  # optimizer steps
            opt.zero_grad()
            K = self._kernel(X, X, log_l, log_s) + (torch.exp(2 * log_b) + 1e-6) * eye
            L = torch.linalg.cholesky(K)
            alpha = torch.cholesky_solve(yyt, L)
            nll = d * torch.log(torch.diagonal(L)).sum() + 0.5 * torch.trace(alpha) + 0.5 * (X**2).sum()
            nll.backward()
            opt.step()
        with torch.no_grad():
            K = self._kernel(X, X, log_l, log_s) + (torch.exp(2 * log_b) + 1e-6) * eye
            self.alpha_ = torch.cholesky_solve(yc, torch.linalg.cholesky(K)).numpy()
        self.latent_ = X.detach().numpy()
        self.log_l_, self.log_s_ = float(log_l.detach()), float(log_s.detach())
        self.neg_log_likelihood_ = float(nll.detach())
        return self

    @staticmethod
    def _kernel(a, b, log_l, log_s):
        import torch

        sq = (a * a).sum(-1)[:, None] + (b * b).sum(-1)[None, :] - 2.0 * a @ b.T  # cdist's backward is slow
        sq = torch.clamp(sq, min=0.0)
        return torch.exp(2 * log_s) * torch.exp(-0.5 * sq / torch.exp(2 * log_l))

    def predict(self, x: np.ndarray) -> np.ndarray:
        """Posterior mean poses (M, D) at latent points x (M, q)."""
        x = np.atleast_2d(np.asarray(x, dtype=float))
        sq = ((x[:, None, :] - self.latent_[None]) ** 2).sum(-1)
        k = np.exp(2 * self.log_s_) * np.exp(-0.5 * sq / np.exp(2 * self.log_l_))
        return k @ self.alpha_ * self.scale_ + self.mean_


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
