"""Linear-Gaussian dynamic Bayesian networks after Lau, Bar-Joseph & Kuffner 2009,
"Modeling spatial and temporal variation in motion data".

Two networks over the degrees of freedom (DOFs) of a pose vector:
- the prior network for the first two frames: every DOF of frame 1 is Gaussian; every
  DOF of frame 2 is linear-Gaussian given its parents in frame 1;
- the transition network: every DOF of frame t is linear-Gaussian given its parents
  among the DOFs of frames t-1 and t-2.
Parents are chosen per DOF by LARS-Lasso with the BIC (scikit-learn ``LassoLarsIC``; Lau
et al. search structures with a BIC-like score), then the weights are refitted by least
squares and the residual variance estimated. Sampling unrolls the transition network
for as many frames as asked, far beyond the length of the examples (Sec. 7.4 of Ma 2010).
"""

from __future__ import annotations

import warnings
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from sklearn.exceptions import ConvergenceWarning
from sklearn.linear_model import LassoLarsIC

from ...core.progress import ProgressLog


@dataclass(frozen=True)
class LinearGaussianNode:
    parents: np.ndarray  # indices into the parent-candidate vector
    weights: np.ndarray
    bias: float
    sigma: float


def _fit_nodes(inputs: np.ndarray, targets: np.ndarray, max_parents: int) -> list[LinearGaussianNode]:
    """One linear-Gaussian node per target column; parents chosen by LassoLarsIC (BIC).
    The noise variance the BIC needs comes from one least-squares fit of all targets on
    all candidates (what LassoLarsIC would otherwise refit for every target)."""
    mu, sd = inputs.mean(axis=0), inputs.std(axis=0)
    sd = np.where(sd > 1e-12, sd, 1.0)
    z = (inputs - mu) / sd
    full = np.concatenate([z, np.ones((len(z), 1))], axis=1)
    resid = targets - full @ np.linalg.lstsq(full, targets, rcond=None)[0]
    noise = np.maximum((resid**2).sum(axis=0) / max(len(z) - full.shape[1], 1), 1e-12)
    gram = (z - z.mean(axis=0)).T @ (z - z.mean(axis=0))  # shared by every target's LARS path
    nodes = []
    progress = ProgressLog(f"DBN ({len(z)} samples) node", targets.shape[1])
    for d in range(targets.shape[1]):  # loop over DOFs
        progress(d)  # d nodes done
        y = targets[:, d]
        if np.std(y) < 1e-12:
            nodes.append(LinearGaussianNode(np.zeros(0, np.int64), np.zeros(0), float(y.mean()), 0.0))
            continue
        with warnings.catch_warnings():  # LARS reports collinear candidates (consecutive frames) as it drops them
            warnings.simplefilter("ignore", ConvergenceWarning)
            lasso = LassoLarsIC(criterion="bic", max_iter=max_parents, noise_variance=noise[d], precompute=gram).fit(
                z, y
            )
        parents = np.flatnonzero(lasso.coef_)[:max_parents]
        design = np.concatenate([inputs[:, parents], np.ones((len(y), 1))], axis=1)
        coef = np.linalg.lstsq(design, y, rcond=None)[0]
        resid = y - design @ coef
        sigma = float(np.sqrt(resid @ resid / max(len(y) - design.shape[1], 1)))
        nodes.append(LinearGaussianNode(parents, coef[:-1], float(coef[-1]), sigma))
    progress(len(nodes))
    return nodes


def _as_matrices(nodes: list[LinearGaussianNode], n_inputs: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Dense weights (D, n_inputs), biases (D,), noise SDs (D,) of a set of nodes."""
    W = np.zeros((len(nodes), n_inputs))
    for d, node in enumerate(nodes):
        W[d, node.parents] = node.weights
    return W, np.array([n.bias for n in nodes]), np.array([n.sigma for n in nodes])


class LauDBN:
    """Prior and transition networks learned from example sequences (T_i, D)."""

    def __init__(self, max_parents: int = 8):
        self.max_parents = max_parents

    def fit(self, sequences: Sequence[np.ndarray]) -> "LauDBN":
        seqs = [np.asarray(s, dtype=float) for s in sequences]
        if not seqs or any(s.ndim != 2 or len(s) < 3 for s in seqs) or len({s.shape[1] for s in seqs}) != 1:
            raise ValueError("LauDBN.fit: need sequences (T_i >= 3, D) with one D")
        first = np.stack([s[0] for s in seqs])
        self.first_mean_ = first.mean(axis=0)
        self.first_sd_ = first.std(axis=0)
        prev1 = np.concatenate([s[:-1] for s in seqs])
        nxt1 = np.concatenate([s[1:] for s in seqs])
        self.prior_ = _as_matrices(_fit_nodes(prev1, nxt1, self.max_parents), prev1.shape[1])
        lagged = np.concatenate([np.concatenate([s[1:-1], s[:-2]], axis=1) for s in seqs])
        target = np.concatenate([s[2:] for s in seqs])
        self.transition_ = _as_matrices(_fit_nodes(lagged, target, self.max_parents), lagged.shape[1])
        return self

    def sample(self, n_frames: int, rng: np.random.Generator) -> np.ndarray:
        """Unroll the networks for ``n_frames`` frames: (n_frames, D)."""
        D = len(self.first_mean_)
        out = np.zeros((n_frames, D))
        out[0] = self.first_mean_ + self.first_sd_ * rng.standard_normal(D)
        W, b, s = self.prior_
        if n_frames > 1:
            out[1] = W @ out[0] + b + s * rng.standard_normal(D)
        W, b, s = self.transition_
        noise = rng.standard_normal((n_frames, D)) * s
        for t in range(2, n_frames):  # the DBN is unrolled frame by frame (inherently sequential)
            out[t] = W @ np.concatenate([out[t - 1], out[t - 2]]) + b + noise[t]
        return out
