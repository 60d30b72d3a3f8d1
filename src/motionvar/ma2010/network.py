"""Parameter propagation network (Ma et al. 2010, Sec. 5.3, Eq. 10, Fig. 5).

A linear-Gaussian Bayesian network over the style parameters c = (c_1..c_d) and the
latent variation parameters xi_I of the joint groups:
    v_j = sum_{v_i in Pa(v_j)} w_ij v_i + eps_j,   eps_j ~ N(mu_j, sigma_j^2)      (Eq. 10)
w_ij and mu_j come from least squares with a pseudo-inverse, sigma_j^2 from the residuals.

Structures (Fig. 5 is not in the text; this is our reading of "lower-first" and
"upper-first", chaining the groups that are connected in the skeleton, whose
dependencies the network is meant to recover):
- lower-first (D_l >= D_u): c -> legs -> upper body -> {left arm, right arm}
- upper-first (D_l <  D_u): c -> upper body -> {left arm, right arm, legs}
The node "c" stands for all d style parameters.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

STYLE = "c"
LOWER_FIRST: dict[str, tuple[str, ...]] = {
    "legs": (STYLE,),
    "upper_body": ("legs",),
    "left_arm": ("upper_body",),
    "right_arm": ("upper_body",),
}
UPPER_FIRST: dict[str, tuple[str, ...]] = {
    "upper_body": (STYLE,),
    "left_arm": ("upper_body",),
    "right_arm": ("upper_body",),
    "legs": ("upper_body",),
}


def choose_structure(d_lower: float, d_upper: float) -> dict[str, tuple[str, ...]]:
    """Fig. 5: the lower-first structure when D_l >= D_u (Eq. 3), else upper-first."""
    return dict(LOWER_FIRST if d_lower >= d_upper else UPPER_FIRST)


@dataclass(frozen=True)
class NodeModel:
    """One node of Eq. 10: its parents, weights w (one per parent value), mu and sigma^2."""

    parents: tuple[str, ...]
    weights: np.ndarray
    mu: float
    sigma2: float


class PropagationNetwork:
    """Eq. 10, fitted by least squares with a pseudo-inverse; samples xi given c.

    Nodes are fitted and sampled in the order of ``structure`` (parents first).
    """

    def __init__(self, structure: Mapping[str, tuple[str, ...]]):
        seen = {STYLE}
        for node, parents in structure.items():
            missing = [p for p in parents if p not in seen]
            if missing:
                raise ValueError(f"PropagationNetwork: node {node!r} has parents {missing} not defined before it")
            seen.add(node)
        self.structure = dict(structure)
        self.nodes_: dict[str, NodeModel] = {}

    @property
    def groups(self) -> list[str]:
        return list(self.structure)

    def _parent_values(self, parents: tuple[str, ...], c: np.ndarray, values: Mapping[str, np.ndarray]) -> np.ndarray:
        cols = [c if p == STYLE else values[p][:, None] for p in parents]
        return np.concatenate(cols, axis=1) if cols else np.zeros((len(c), 0))

    def fit(self, c: np.ndarray, xi: Mapping[str, np.ndarray]) -> "PropagationNetwork":
        """Fit every node from the examples' style parameters c (N, d) and latent
        variation parameters xi (group -> (N,))."""
        c = np.asarray(c, dtype=float)
        c = c[:, None] if c.ndim == 1 else c
        n = len(c)
        for node, parents in self.structure.items():
            if node not in xi or len(xi[node]) != n:
                raise ValueError(f"PropagationNetwork.fit: need {n} values of xi for group {node!r}")
            X = np.concatenate([self._parent_values(parents, c, xi), np.ones((n, 1))], axis=1)
            y = np.asarray(xi[node], dtype=float)
            coef = np.linalg.pinv(X) @ y
            resid = y - X @ coef
            dof = max(n - X.shape[1], 1)
            self.nodes_[node] = NodeModel(parents, coef[:-1], float(coef[-1]), float(resid @ resid / dof))
        return self

    def sample(
        self,
        c: np.ndarray,
        rng: np.random.Generator | None = None,
        fixed: Mapping[str, float | np.ndarray] | None = None,
        noise: bool = True,
    ) -> dict[str, np.ndarray]:
        """xi of every group for style parameters c (M, d), by ancestral sampling.

        Args:
            rng: random generator (needed when ``noise``).
            fixed: groups whose xi the user sets by hand (Sec. 1: "advanced users can
                manually specify the latent variation parameters"); their children
                propagate from the given value.
            noise: draw eps_j ~ N(mu_j, sigma_j^2); False gives the conditional mean.
        """
        if not self.nodes_:
            raise RuntimeError("PropagationNetwork.sample: call fit first")
        c = np.asarray(c, dtype=float)
        c = c[None, :] if c.ndim == 1 else c
        if noise and rng is None:
            raise ValueError("PropagationNetwork.sample: noise=True needs an rng")
        fixed = dict(fixed or {})
        unknown = set(fixed) - set(self.structure)
        if unknown:
            raise ValueError(f"PropagationNetwork.sample: unknown groups {sorted(unknown)}")
        out: dict[str, np.ndarray] = {}
        for node, m in self.nodes_.items():
            if node in fixed:
                out[node] = np.broadcast_to(np.asarray(fixed[node], dtype=float), (len(c),)).copy()
                continue
            mean = self._parent_values(m.parents, c, out) @ m.weights + m.mu
            eps = rng.standard_normal(len(c)) * np.sqrt(m.sigma2) if noise else 0.0
            out[node] = mean + eps
        return out
