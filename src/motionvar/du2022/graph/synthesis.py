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
latent vectors (the same numbers as scipy's own, one vectorised call). MINPACK's iterates
differ in their last bits between runs (its BLAS kernels depend on memory alignment); the
objective sees the latent vectors on a grid of relative spacing 2^-20 (about 1e-6, far
below what moves a joint by a visible amount), so that such bits do not reach the tables.

Several steps together (Algorithm 1, line 9: "optimize all steps of current elementary
action"; Eq. 4.9 summed over the steps): :class:`StepChain` places the steps of a walk one
after another (each aligned primitive at the previous step's end: hips floor position and
facing at its last canonical frame) and evaluates every step's path constraint
(:class:`StepGoal`, world coordinates) on the chained placement, so that changing one
step moves all later ones. :func:`optimize_chain` minimises the stacked residuals of all
steps over their concatenated latent vectors with the same residual form (each step's
negative log-likelihood added to each of its residuals, as DFKI's
``obj_global_residual_vector_and_naturalness``) by scipy ``least_squares``; its padding
rows are a very weak pull towards the start instead of DFKI's zeros, which makes
Levenberg-Marquardt's step unique (see there).
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
    and after, log p(s) after, LM's function evaluations and status."""

    latent: np.ndarray
    errors_before: np.ndarray
    errors_after: np.ndarray
    log_prob_after: float
    n_evals: int
    status: int


GRID_BITS = 20  # relative grid of the latent vectors the objective sees (module docstring)
ANCHOR_WEIGHT = 1e-3  # the padding rows of optimize_chain: a pull towards the start (its docstring)


def on_grid(x: np.ndarray, bits: int = GRID_BITS) -> np.ndarray:
    """``x`` rounded to ``bits`` bits of mantissa (relative spacing 2^-bits; 0 stays 0)."""
    m, e = np.frexp(np.asarray(x, dtype=float))
    return np.ldexp(np.round(m * 2.0**bits) / 2.0**bits, e)


def map_residuals(
    primitive: MotionPrimitive, objective: Objective, S: np.ndarray, likelihood_weight: float
) -> np.ndarray:
    """(B, n_c) residuals r_i(s) of the module docstring for latent vectors S (B, d)."""
    err = objective.errors(S)
    nll = -primitive.log_prob(S) - primitive.nll_reference()
    return err + likelihood_weight * np.maximum(nll, 0.0)[:, None] / err.shape[1]


def optimize_map(
    primitive: MotionPrimitive,
    constraints: Sequence[Constraint],
    s0: np.ndarray,
    likelihood_weight: float,
    method: str,
    max_nfev: int,
    fd_step: float = 1e-4,
) -> MapResult:
    """Minimise Eq. 4.9 from ``s0`` with Levenberg-Marquardt ("lm") or scipy's "trf", at most
    ``max_nfev`` residual evaluations (config ``du2022_graph.synthesis``: ``likelihood_weight``,
    ``method``, ``max_nfev``)."""
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
        return pad(map_residuals(primitive, objective, on_grid(s)[None], likelihood_weight))[0]

    def jac(s: np.ndarray) -> np.ndarray:
        s = on_grid(s)
        h = fd_step * np.maximum(1.0, np.abs(s))
        S = np.concatenate([s[None], s[None] + np.diag(h)])
        R = pad(map_residuals(primitive, objective, S, likelihood_weight))
        return ((R[1:] - R[0]) / h[:, None]).T

    before = objective.errors(s0[None])[0]
    result = least_squares(fun, on_grid(s0), jac=jac, method=method, max_nfev=int(max_nfev))
    s = on_grid(result.x)
    after = objective.errors(s[None])[0]
    return MapResult(
        latent=s,
        errors_before=before,
        errors_after=after,
        log_prob_after=float(primitive.log_prob(s[None])[0]),
        n_evals=int(objective.n_evals),
        status=int(result.status),
    )


_UP = np.array([0.0, 1.0, 0.0])


@dataclass(frozen=True)
class StepGoal:
    """The path constraint of one step in world coordinates (Sec. 4.5.1): the hips' floor
    position ``target_xz`` (x, z) and the heading ``direction`` (a floor direction
    (x, 0, z)) at the step's last canonical frame."""

    target_xz: np.ndarray
    direction: np.ndarray

    def __post_init__(self) -> None:
        t = np.asarray(self.target_xz, dtype=float).reshape(2)
        d = np.asarray(self.direction, dtype=float).reshape(3)
        if not (np.all(np.isfinite(t)) and np.all(np.isfinite(d)) and np.hypot(d[0], d[2]) > 0):
            raise ValueError(f"step goal: a finite floor target and a non-zero floor direction; got {t}, {d}")
        object.__setattr__(self, "target_xz", t)
        object.__setattr__(self, "direction", d)


def rotate_floor(v: np.ndarray, heading: np.ndarray) -> np.ndarray:
    """Floor vectors (..., 2) of a step's aligned frame (x, z; heading +x) in the world
    frame of a step placed with floor heading (..., 2) (unit; ``place_motion``'s turn)."""
    return np.stack(
        [
            v[..., 0] * heading[..., 0] - v[..., 1] * heading[..., 1],
            v[..., 0] * heading[..., 1] + v[..., 1] * heading[..., 0],
        ],
        axis=-1,
    )


def step_end_local(
    primitive: MotionPrimitive, S: np.ndarray, hips: int, left_hip: int, right_hip: int
) -> tuple[np.ndarray, np.ndarray]:
    """Hips floor position (B, 2) and unit facing (B, 2) (up x (left hip -> right hip), as
    the heading constraint) at the last canonical frame of latent vectors S (B, d), in the
    step's aligned frame."""
    pos, _ = primitive.key_frame_pose(S, [primitive.n_frames - 1], [hips, left_hip, right_hip])
    across = pos[:, 0, 2] - pos[:, 0, 1]
    facing = np.stack([across[:, 2], -across[:, 0]], axis=-1)
    return pos[:, 0, 0][:, [0, 2]], facing / np.linalg.norm(facing, axis=-1, keepdims=True)


class StepChain:
    """Steps of a walk placed one after another (module docstring), from the floor
    position ``start_xz`` and heading ``start_heading`` (x, z) of the first step's start.

    ``ends(X)`` gives the chained world end positions and facings (B, K, 2) for stacked
    latent vectors X (B, sum d_k); ``errors(X)`` the per-step constraint errors (B, K, 2):
    hips floor distance to the goal (cm) and heading error (degrees), the same numbers as
    the step's own position and heading :class:`~.constraints.Constraint` in its aligned
    frame; ``residuals(X, w)`` adds each step's likelihood term as :func:`map_residuals`.
    """

    def __init__(
        self,
        primitives: Sequence[MotionPrimitive],
        goals: Sequence[StepGoal],
        start_xz: np.ndarray,
        start_heading: np.ndarray,
        hips: int,
        left_hip: int,
        right_hip: int,
    ) -> None:
        if len(primitives) != len(goals) or not primitives:
            raise ValueError(
                f"step chain: one goal per step and at least one step; got {len(primitives)} steps, {len(goals)} goals"
            )
        self.primitives, self.goals = list(primitives), list(goals)
        self.joints = (int(hips), int(left_hip), int(right_hip))
        h = np.asarray(start_heading, dtype=float).reshape(-1)
        h = h[[0, 2]] if len(h) == 3 else h
        self.start_xz = np.asarray(start_xz, dtype=float).reshape(2)
        self.start_heading = h / np.linalg.norm(h)
        self.sizes = [p.n_latent for p in self.primitives]
        self.offsets = np.concatenate([[0], np.cumsum(self.sizes)])
        self.n_evals = 0

    @property
    def n_steps(self) -> int:
        return len(self.primitives)

    def split(self, x: np.ndarray) -> list[np.ndarray]:
        """The latent vectors of each step from a stacked vector (n,) or batch (B, n)."""
        return [x[..., a:b] for a, b in zip(self.offsets[:-1], self.offsets[1:])]

    def ends(self, X: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        X = np.atleast_2d(np.asarray(X, dtype=float))
        if X.shape[1] != self.offsets[-1]:
            raise ValueError(f"step chain: stacked latent vectors must have {self.offsets[-1]} values; got {X.shape}")
        self.n_evals += len(X)
        B = len(X)
        pos = np.broadcast_to(self.start_xz, (B, 2))
        head = np.broadcast_to(self.start_heading, (B, 2))
        out_p, out_h = np.empty((B, self.n_steps, 2)), np.empty((B, self.n_steps, 2))
        for k, (prim, S) in enumerate(zip(self.primitives, self.split(X))):  # a loop over steps, not frames
            loc, face = step_end_local(prim, S, *self.joints)
            pos, head = pos + rotate_floor(loc, head), rotate_floor(face, head)
            out_p[:, k], out_h[:, k] = pos, head
        return out_p, out_h

    def errors(self, X: np.ndarray) -> np.ndarray:
        pos, head = self.ends(X)
        target = np.stack([g.target_xz for g in self.goals])
        goal_angle = np.array([np.arctan2(g.direction[2], g.direction[0]) for g in self.goals])
        d_pos = np.linalg.norm(pos - target, axis=-1)
        a = np.arctan2(head[..., 1], head[..., 0]) - goal_angle
        return np.stack([d_pos, np.degrees(np.abs((a + np.pi) % (2 * np.pi) - np.pi))], axis=-1)

    def nll(self, X: np.ndarray) -> np.ndarray:
        """(B, K) negative log-likelihood of each step above its primitive's reference."""
        X = np.atleast_2d(X)
        return np.stack([-p.log_prob(S) - p.nll_reference() for p, S in zip(self.primitives, self.split(X))], axis=-1)

    def residuals(self, X: np.ndarray, likelihood_weight: float) -> np.ndarray:
        err = self.errors(X)
        lik = likelihood_weight * np.maximum(self.nll(X), 0.0) / err.shape[-1]
        return (err + lik[..., None]).reshape(len(err), -1)


@dataclass
class ChainResult:
    """Outcome of :func:`optimize_chain`: the latent vector of each step, per-step
    constraint errors (K, 2) before and after, log p of each step after,
    residual evaluations (latent vectors of the chain) and least_squares' status."""

    latents: list[np.ndarray]
    errors_before: np.ndarray
    errors_after: np.ndarray
    log_prob_after: np.ndarray
    n_evals: int
    status: int

    def cost(self, which: str = "after") -> float:
        """Sum of squared constraint errors (without the likelihood term)."""
        e = self.errors_after if which == "after" else self.errors_before
        return float(np.sum(e**2))


def optimize_chain(
    chain: StepChain,
    latents: Sequence[np.ndarray],
    likelihood_weight: float,
    method: str,
    max_nfev: int,
    fd_step: float = 1e-4,
    anchor_weight: float = ANCHOR_WEIGHT,
) -> ChainResult:
    """Algorithm 1, line 9: minimise Eq. 4.9 summed over the steps of ``chain`` (module
    docstring) over their latent vectors together, from ``latents`` (one per step).

    The problem has two residuals per step and a latent vector of d per step: MINPACK needs
    at least as many residuals as unknowns, and with DFKI's zero padding its Gauss-Newton
    step is not unique (it picks one by its pivoted QR, which jumps with the last bits of
    the input: runs of the same config differed by up to 0.2 cm per step). The padding rows
    here are ``anchor_weight`` * (x - start) instead, a pull towards the start so weak that
    it changes the cost by (1e-3 * shift)^2 but makes the step unique (0 gives DFKI's zeros)."""
    if method not in ("lm", "trf"):
        raise ValueError(f"optimize_chain: method must be 'lm' or 'trf'; got {method!r}")
    if len(latents) != chain.n_steps:
        raise ValueError(f"optimize_chain: {chain.n_steps} steps but {len(latents)} start vectors")
    x0 = on_grid(np.concatenate([np.asarray(s, dtype=float).reshape(-1) for s in latents]))

    def stack(r: np.ndarray, X: np.ndarray) -> np.ndarray:
        return np.concatenate([r, anchor_weight * (X - x0)], axis=-1) if method == "lm" else r

    def fun(x: np.ndarray) -> np.ndarray:
        X = on_grid(x)[None]
        return stack(chain.residuals(X, likelihood_weight), X)[0]

    def jac(x: np.ndarray) -> np.ndarray:
        x = on_grid(x)
        h = fd_step * np.maximum(1.0, np.abs(x))
        X = np.concatenate([x[None], x[None] + np.diag(h)])
        R = stack(chain.residuals(X, likelihood_weight), X)
        return ((R[1:] - R[0]) / h[:, None]).T

    before = chain.errors(x0[None])[0]
    result = least_squares(fun, x0, jac=jac, method=method, max_nfev=int(max_nfev))
    x = on_grid(result.x)
    after = chain.errors(x[None])[0]
    lp_after = -(chain.nll(x[None])[0] + np.array([p.nll_reference() for p in chain.primitives]))
    return ChainResult(
        latents=[v.copy() for v in chain.split(x)],
        errors_before=before,
        errors_after=after,
        log_prob_after=lp_after,
        n_evals=int(chain.n_evals),
        status=int(result.status),
    )
