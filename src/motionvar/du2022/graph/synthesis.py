"""Constrained motion synthesis for one primitive: the MAP objective of Du 2022 Eq. 4.9,
minimised by Levenberg-Marquardt from the space-partitioning tree's best candidate
(Sec. 4.5.3).

Eq. 4.9: argmin_s O(s, c) - ln p(s), with O the constraint error of Eq. 4.2 and p the
GMM of Eq. 4.1. Levenberg-Marquardt minimises a sum of squared residuals; as in DFKI's
implementation the negative log-likelihood is added to each residual:

    r_i(s) = e_i(s) + lambda * max(-ln p(s) - L_ref, 0) / n_c,   i = 1 .. n_c,

with e_i the error of constraint i (cm or degrees), L_ref = min over the GMM means of
-ln p (so the likelihood term is about zero at the modes) and lambda the likelihood
weight. MINPACK's LM (scipy ``least_squares(method="lm")``) needs at least as many
residuals as unknowns: the vector is padded with zeros (which changes nothing in the
minimum). The Jacobian is the 2-point finite difference evaluated as one batch of d + 1
latent vectors (the same numbers as scipy's own, one vectorised call).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from scipy.optimize import least_squares

from .constraints import Constraint, Objective
from .primitive import MotionPrimitive


@dataclass
class MapResult:
    """Outcome of :func:`optimize_map`: the latent vector, per-constraint errors before
    and after, log p(s) before and after, LM's function evaluations and status."""

    latent: np.ndarray
    errors_before: np.ndarray
    errors_after: np.ndarray
    log_prob_before: float
    log_prob_after: float
    n_evals: int
    status: int


def map_residuals(primitive: MotionPrimitive, objective: Objective, S: np.ndarray,
                  likelihood_weight: float) -> np.ndarray:
    """(B, n_c) residuals r_i(s) of the module docstring for latent vectors S (B, d)."""
    err = objective.errors(S)
    nll = -primitive.log_prob(S) - primitive.nll_reference()
    return err + likelihood_weight * np.maximum(nll, 0.0)[:, None] / err.shape[1]


def optimize_map(primitive: MotionPrimitive, constraints: Sequence[Constraint], s0: np.ndarray,
                 likelihood_weight: float = 1.0, method: str = "lm", max_nfev: int = 200,
                 fd_step: float = 1e-4) -> MapResult:
    """Minimise Eq. 4.9 from ``s0`` with Levenberg-Marquardt ("lm") or scipy's "trf"."""
    if method not in ("lm", "trf"):
        raise ValueError(f"optimize_map: method must be 'lm' or 'trf'; got {method!r}")
    objective = Objective(primitive, constraints)
    d = primitive.n_latent
    s0 = np.asarray(s0, dtype=float).reshape(d)
    n_res = max(len(constraints), d) if method == "lm" else len(constraints)

    def pad(r: np.ndarray) -> np.ndarray:
        out = np.zeros(r.shape[:-1] + (n_res,))
        out[..., : r.shape[-1]] = r
        return out

    def fun(s: np.ndarray) -> np.ndarray:
        return pad(map_residuals(primitive, objective, s[None], likelihood_weight))[0]

    def jac(s: np.ndarray) -> np.ndarray:
        h = fd_step * np.maximum(1.0, np.abs(s))
        S = np.concatenate([s[None], s[None] + np.diag(h)])
        R = pad(map_residuals(primitive, objective, S, likelihood_weight))
        return ((R[1:] - R[0]) / h[:, None]).T

    before = objective.errors(s0[None])[0]
    result = least_squares(fun, s0, jac=jac, method=method, max_nfev=int(max_nfev))
    s = result.x
    after = objective.errors(s[None])[0]
    return MapResult(latent=s, errors_before=before, errors_after=after,
                     log_prob_before=float(primitive.log_prob(s0[None])[0]),
                     log_prob_after=float(primitive.log_prob(s[None])[0]),
                     n_evals=int(objective.n_evals), status=int(result.status))
