"""Bayesian GPLVM on functional motion data: the nonlinear baseline of Du 2022, Fig. 3.10-3.11
(the model itself is :class:`motionvar.models.bayesian_gplvm.BayesianGPLVM`)."""

from __future__ import annotations

import numpy as np

from ...models.bayesian_gplvm import BayesianGPLVM
from .functions import FunctionalMotions


class FunctionalGPLVM:
    """:class:`BayesianGPLVM` on functional motion data: the outputs are the Gram-weighted
    B-spline coefficients W^(1/2) c (so that Euclidean distances are the functional
    distances of Eq. 3.5, the feature space FPCA works in), the same input as FPCA.

    ``transform`` returns the latent means of the training clips (Bayesian GPLVM infers
    no latent positions for new data here); ``inverse_transform`` maps latent points back
    to B-spline coefficients (N, K, D)."""

    def __init__(self, n_components: int = 20, **gplvm_kwargs) -> None:
        self.n_components = n_components
        self.gplvm_kwargs = gplvm_kwargs

    def fit(self, X: FunctionalMotions, labels: np.ndarray | None = None) -> "FunctionalGPLVM":
        self._gram_sqrt, self._gram_isqrt = X.basis.gram_sqrt()
        self._shape = X.coefs.shape[1:]
        self._train = X.coefs
        Y = np.einsum("kl,nld->nkd", self._gram_sqrt, X.coefs).reshape(X.n_clips, -1)
        self.gplvm_ = BayesianGPLVM(self.n_components, **self.gplvm_kwargs).fit(Y, labels)
        return self

    def transform(self, X: FunctionalMotions) -> np.ndarray:
        if X.coefs.shape != self._train.shape or not np.array_equal(X.coefs, self._train):
            raise NotImplementedError("FunctionalGPLVM.transform: only the training clips have latent positions")
        return self.gplvm_.latent_mean_

    def fit_transform(self, X: FunctionalMotions, labels: np.ndarray | None = None) -> np.ndarray:
        return self.fit(X, labels).gplvm_.latent_mean_

    def inverse_transform(self, latent: np.ndarray) -> np.ndarray:
        z = self.gplvm_.predict(latent).reshape(-1, *self._shape)
        return np.einsum("kl,nld->nkd", self._gram_isqrt, z)

    def reconstruct(self, X: FunctionalMotions) -> np.ndarray:
        return self.inverse_transform(self.transform(X))
