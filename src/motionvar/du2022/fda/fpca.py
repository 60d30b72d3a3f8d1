"""Functional PCA of motion clips (Du 2022, Sec. 3.3.4-3.3.5, Eq. 3.3-3.5) and its
normalised variant; the base of SFPCA (:mod:`motionvar.du2022.fda.sfpca`).

FPCA finds orthonormal eigenfunctions V(t) minimising (1/N) ||Y(t) - V V^T Y(t)||^2
(Eq. 3.3) under the functional inner product of Eq. 3.5, <x, y> = sum_i int x_i y_i dt.
With B-spline coefficients c (K per function) that inner product is c_x^T W c_y with the
Gram matrix W, so FPCA is an ordinary PCA of the W^(1/2)-weighted coefficients; the
eigenfunctions' coefficients are W^(-1/2) times the principal axes.

The scaled variants apply one weight per function first (the diagonal matrix W of
Eq. 3.8, here ``function_weights_`` to keep it apart from the Gram matrix): PCA of the
scaled functions diag(w) Y(t), and back-projection by diag(w)^(-1) V' V'^T diag(w) Y(t).
FPCA uses w = 1; normalised FPCA (Sec. 3.3.5) z-scores each function, w_d = 1 / sigma_d;
SFPCA optimises w (Eq. 3.8).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ...core.motion import Motion
from ...core.skeleton import Skeleton
from ...io.model_file import load_model, save_model
from .bspline import BSplineBasis
from .functions import FunctionalMotions, FunctionLayout

_SAVED_CLASSES: dict[str, type] = {}
SAVED_KIND = "du2022.fpca"  # the "kind" of a saved FPCA-family model's settings


def functional_std(X: FunctionalMotions) -> np.ndarray:
    """(D,) standard deviation of each function over clips and time:
    sigma_d^2 = (1/N) sum_i int_0^1 (y_id(t) - mean_d(t))^2 dt (Eq. 3.5 norm)."""
    centred = X.coefs - X.coefs.mean(axis=0)
    gram = X.basis.gram()
    var = np.einsum("nkd,kl,nld->d", centred, gram, centred) / X.n_clips
    return np.sqrt(np.maximum(var, 0.0))


def zscore_weights(std: np.ndarray, rel_floor: float = 1e-8) -> np.ndarray:
    """Z-score weights 1 / sigma_d; a function with (numerically) zero variance keeps
    weight 1, as scikit-learn's StandardScaler does."""
    std = np.asarray(std, dtype=float)
    tiny = std <= rel_floor * max(float(std.max(initial=0.0)), 1e-300)
    return np.where(tiny, 1.0, 1.0 / np.where(tiny, 1.0, std))


def _jsonable(value):
    """A constructor parameter as JSON (tuples as lists, numpy scalars as Python)."""
    if isinstance(value, np.generic):
        return value.item()
    if isinstance(value, tuple):
        return [_jsonable(v) for v in value]
    return value


def register_saved(cls: type) -> type:
    """Class decorator: lets :meth:`FPCA.load` restore instances of ``cls``."""
    _SAVED_CLASSES[cls.__name__] = cls
    return cls


@register_saved
class FPCA:
    """Functional PCA with the functional inner product (Eq. 3.3-3.5), sklearn-style.

    Args:
        n_components: number of eigenfunctions kept (the latent dimension).

    Fitted attributes: ``mean_`` (K, D) mean function coefficients; ``function_weights_``
    (D,) the scaling diag(w) (ones here); ``components_`` (n, K*D) orthonormal principal
    axes of the Gram-weighted scaled coefficients; ``eigenfunctions_`` (n, K, D) B-spline
    coefficients of the eigenfunctions of the scaled functions; ``explained_variance_``,
    ``explained_variance_ratio_``, ``singular_values_``; ``basis_``, ``layout_``,
    ``n_frames_``, ``parents_``, ``offsets_mean_`` (what back-projection to motions needs).
    """

    def __init__(self, n_components: int = 20) -> None:
        self.n_components = n_components

    # ---- fitting -------------------------------------------------------------------
    def _weights(self, X: FunctionalMotions) -> np.ndarray:
        return np.ones(X.layout.n_functions)

    def fit(self, X: FunctionalMotions, y=None) -> "FPCA":
        self._check_fit_input(X)
        self._fit_weighted(X, self._weights(X))
        return self

    def fit_transform(self, X: FunctionalMotions, y=None) -> np.ndarray:
        return self.fit(X).transform(X)

    def _check_fit_input(self, X: FunctionalMotions) -> None:
        if not isinstance(X, FunctionalMotions):
            raise TypeError(f"{type(self).__name__}.fit expects FunctionalMotions; got {type(X).__name__}")
        n_max = min(X.n_clips, X.coefs.shape[1] * X.coefs.shape[2])
        if not (isinstance(self.n_components, (int, np.integer)) and 1 <= self.n_components <= n_max):
            raise ValueError(
                f"{type(self).__name__}: n_components must be an integer in [1, {n_max}] "
                f"for {X.n_clips} clips; got {self.n_components}"
            )

    def _fit_weighted(self, X: FunctionalMotions, weights: np.ndarray) -> None:
        """PCA of the Gram-weighted, function-scaled coefficients (Eq. 3.3 on diag(w) Y)."""
        from sklearn.decomposition import PCA  # only fitting needs scikit-learn (a slow import)

        self.basis_ = X.basis
        self.layout_ = X.layout
        self.n_frames_ = int(X.n_frames)
        self.parents_ = np.asarray(X.parents)
        self.offsets_mean_ = X.offsets.mean(axis=0)
        self.function_weights_ = np.asarray(weights, dtype=float)
        self.mean_ = X.coefs.mean(axis=0)
        self._gram_sqrt, self._gram_isqrt = X.basis.gram_sqrt()
        pca = PCA(n_components=int(self.n_components), svd_solver="full")
        pca.fit(self._scaled(X.coefs))
        self.components_ = pca.components_
        self.explained_variance_ = pca.explained_variance_
        self.explained_variance_ratio_ = pca.explained_variance_ratio_
        self.singular_values_ = pca.singular_values_
        K, D = self.mean_.shape
        self.eigenfunctions_ = np.einsum("kl,nld->nkd", self._gram_isqrt, self.components_.reshape(-1, K, D))

    # ---- transforms ----------------------------------------------------------------
    def _scaled(self, coefs: np.ndarray) -> np.ndarray:
        """(N, K*D) W^(1/2) (c - mean) scaled by the function weights."""
        z = np.einsum("kl,nld->nkd", self._gram_sqrt, coefs - self.mean_) * self.function_weights_
        return z.reshape(len(coefs), -1)

    def _coefs(self, X: FunctionalMotions | np.ndarray) -> np.ndarray:
        if not hasattr(self, "components_"):
            raise RuntimeError(f"{type(self).__name__} is not fitted yet: call fit first")
        coefs = X.coefs if isinstance(X, FunctionalMotions) else np.asarray(X, dtype=float)
        if coefs.ndim != 3 or coefs.shape[1:] != self.mean_.shape:
            raise ValueError(
                f"expected coefficients (N, {self.mean_.shape[0]}, {self.mean_.shape[1]}); got {coefs.shape}"
            )
        return coefs

    def transform(self, X: FunctionalMotions | np.ndarray) -> np.ndarray:
        """(N, n_components) latent scores of functional clips or coefficients (N, K, D)."""
        return self._scaled(self._coefs(X)) @ self.components_.T

    def inverse_transform(self, scores: np.ndarray) -> np.ndarray:
        """(N, K, D) B-spline coefficients of diag(w)^(-1) V V^T (scores) + mean (Eq. 3.8)."""
        scores = np.atleast_2d(np.asarray(scores, dtype=float))
        if scores.shape[-1] != self.components_.shape[0]:
            raise ValueError(f"expected scores (N, {self.components_.shape[0]}); got {scores.shape}")
        K, D = self.mean_.shape
        z = (scores @ self.components_).reshape(-1, K, D) / self.function_weights_
        return self.mean_ + np.einsum("kl,nld->nkd", self._gram_isqrt, z)

    def reconstruct(self, X: FunctionalMotions | np.ndarray, n_components: int | None = None) -> np.ndarray:
        """Coefficients after projection to the latent space and back; with
        ``n_components`` only the leading ones of the fitted eigenfunctions (they are
        nested, so one fit serves every smaller dimension)."""
        n = self.components_.shape[0] if n_components is None else int(n_components)
        if not 1 <= n <= self.components_.shape[0]:
            raise ValueError(f"n_components must be in [1, {self.components_.shape[0]}]; got {n_components}")
        scores = self._scaled(self._coefs(X)) @ self.components_[:n].T
        K, D = self.mean_.shape
        z = (scores @ self.components_[:n]).reshape(-1, K, D) / self.function_weights_
        return self.mean_ + np.einsum("kl,nld->nkd", self._gram_isqrt, z)

    def to_motions(
        self,
        scores: np.ndarray,
        fps: float,
        skeleton: Skeleton | None = None,
        joint_names: tuple[str, ...] | None = None,
    ) -> list[Motion]:
        """Back-project latent scores to Motions on the canonical timeline (``n_frames_``).

        ``skeleton`` defaults to the mean bone offsets of the training clips (then
        ``joint_names`` names its joints; generic names otherwise)."""
        coefs = self.inverse_transform(scores)
        if skeleton is None:
            J = self.layout_.n_joints
            names = tuple(joint_names) if joint_names is not None else tuple(f"joint{j}" for j in range(J))
            skeleton = Skeleton(names=names, parents=self.parents_, offsets=self.offsets_mean_)
        fd = FunctionalMotions(
            coefs=coefs,
            basis=self.basis_,
            layout=self.layout_,
            offsets=np.broadcast_to(skeleton.offsets, (len(coefs), *skeleton.offsets.shape)),
            parents=skeleton.parents,
            n_frames=self.n_frames_,
        )
        return fd.to_motions(skeleton, fps)

    # ---- persistence ---------------------------------------------------------------
    _SAVED_ARRAYS = (
        "parents_",
        "offsets_mean_",
        "function_weights_",
        "mean_",
        "components_",
        "explained_variance_",
        "explained_variance_ratio_",
        "singular_values_",
    )
    _EXTRA_SAVED: tuple[str, ...] = ()  # fitted scalars kept in the JSON settings
    _OPTIONAL_SAVED: tuple[str, ...] = ()  # fitted scalars kept when present (older files may lack them)
    _SAVED_PARAMS: tuple[str, ...] = ()  # constructor parameters kept in the settings ("params")

    def save(self, path: str | Path) -> list[Path]:
        """Write the fitted model as ``<base>.npz`` (arrays) and ``<base>.json`` (class and
        sizes) with :func:`motionvar.io.model_file.save_model` (``path`` with or without
        suffix); returns both paths."""
        if not hasattr(self, "components_"):
            raise RuntimeError(f"{type(self).__name__} is not fitted yet: nothing to save")
        settings = {
            "kind": SAVED_KIND,
            "class_name": type(self).__name__,
            "n_components": int(self.n_components),
            "n_basis": int(self.basis_.n_basis),
            "degree": int(self.basis_.degree),
            "n_joints": int(self.layout_.n_joints),
            "n_frames": int(self.n_frames_),
        }
        for name in self._EXTRA_SAVED + tuple(n for n in self._OPTIONAL_SAVED if hasattr(self, n)):
            value = getattr(self, name)
            settings[name] = value.item() if isinstance(value, np.generic) else value
        if self._SAVED_PARAMS:
            settings["params"] = {name: _jsonable(getattr(self, name)) for name in self._SAVED_PARAMS}
        arrays = {name: np.asarray(getattr(self, name)) for name in self._SAVED_ARRAYS}
        return save_model(path, arrays, settings)

    @classmethod
    def load(cls, path: str | Path) -> "FPCA":
        """Read a model written by :meth:`save` (returns the saved class)."""
        a, settings = load_model(path, kind=SAVED_KIND)
        name = settings.get("class_name", "")
        if name not in _SAVED_CLASSES:
            raise ValueError(f"{path}: unknown model class {name!r}")
        model = _SAVED_CLASSES[name].__new__(_SAVED_CLASSES[name])
        model.n_components = int(settings["n_components"])
        model.basis_ = BSplineBasis(int(settings["n_basis"]), int(settings["degree"]))
        model.layout_ = FunctionLayout(int(settings["n_joints"]))
        model.n_frames_ = int(settings["n_frames"])
        missing = [n for n in (*model._SAVED_ARRAYS, *model._EXTRA_SAVED) if n not in a and n not in settings]
        if missing:
            raise ValueError(f"{path}: saved {name} lacks {missing}")
        for n in model._SAVED_ARRAYS:
            setattr(model, n, a[n])
        for n in model._EXTRA_SAVED + tuple(n for n in model._OPTIONAL_SAVED if n in settings):
            setattr(model, n, settings[n])
        model._gram_sqrt, model._gram_isqrt = model.basis_.gram_sqrt()
        K, D = model.mean_.shape
        model.eigenfunctions_ = np.einsum("kl,nld->nkd", model._gram_isqrt, model.components_.reshape(-1, K, D))
        model._restore_params()
        for n, value in settings.get("params", {}).items():
            if n in model._SAVED_PARAMS:
                setattr(model, n, tuple(value) if isinstance(value, list) else value)
        return model

    def _restore_params(self) -> None:
        """Set constructor parameters not saved (defaults) after :meth:`load`; those in
        ``_SAVED_PARAMS`` are then set from the file."""

    def check_fitted_on(self, X: FunctionalMotions, source: str = "model") -> None:
        """ValueError naming ``source`` unless this model was fitted on the clips ``X``
        (same basis and functions, and the same mean coefficients, exactly): a model read
        from a file must belong to the data it is used with."""
        if not hasattr(self, "mean_"):
            raise RuntimeError(f"{type(self).__name__} is not fitted yet")
        if self.mean_.shape != X.coefs.shape[1:] or not np.array_equal(self.mean_, X.coefs.mean(axis=0)):
            raise ValueError(
                f"{source}: fitted on other clips than those given ({X.n_clips} clips, "
                f"coefficients {X.coefs.shape[1:]}; the model's {self.mean_.shape}): rerun the rule "
                f"that wrote it"
            )


@register_saved
class NormalizedFPCA(FPCA):
    """FPCA of z-scored functions (Sec. 3.3.5: "normalizes the input features to have 0
    mean and 1 standard deviation before applying FPCA"): w_d = 1 / max(sigma_d, ``sd_floor``)
    with sigma_d the functional standard deviation of function d (:func:`functional_std`).
    ``sd_floor`` 0: the z-score as written (a function that never moves keeps weight 1); above
    0, functions that hardly move are scaled as if they moved that much, instead of weights up
    to 1e4 that blow their noise up to the scale of the motion."""

    _SAVED_PARAMS = ("sd_floor",)

    def __init__(self, n_components: int = 20, sd_floor: float = 0.0) -> None:
        super().__init__(n_components)
        self.sd_floor = sd_floor

    def _weights(self, X: FunctionalMotions) -> np.ndarray:
        return zscore_weights(np.maximum(functional_std(X), self.sd_floor))

    def _restore_params(self) -> None:
        self.sd_floor = 0.0


@register_saved
class RootScaledFPCA(FPCA):
    """FPCA with only the root translation scaled, as the author's pipeline prepares its data
    (DeepMotionModeling ``motion_analysis/prepare_data.py: scale_root_channels``; DFKI's
    ``scaled_fpca``): each root channel divided by its largest absolute value over the clips
    and the canonical frames, the joint quaternions left as they are."""

    def _weights(self, X: FunctionalMotions) -> np.ndarray:
        values = np.einsum("tk,nkd->ntd", X.basis.design_frames(X.n_frames), X.coefs[:, :, :3])
        largest = np.abs(values).max(axis=(0, 1))
        weights = np.ones(X.layout.n_functions)
        weights[:3] = 1.0 / np.where(largest > 0, largest, 1.0)
        return weights


@register_saved
class WeightedFPCA(FPCA):
    """FPCA of functions scaled by given weights (e.g. SFPCA weights optimised for another
    number of components): diag(w) Y(t), back-projected with diag(w)^(-1) (Eq. 3.8)."""

    def __init__(self, n_components: int = 20, function_weights: np.ndarray | None = None) -> None:
        super().__init__(n_components)
        self.function_weights = function_weights

    def _weights(self, X: FunctionalMotions) -> np.ndarray:
        w = np.asarray(self.function_weights, dtype=float) if self.function_weights is not None else None
        if w is None or w.shape != (X.layout.n_functions,) or not np.all(np.isfinite(w) & (w > 0)):
            raise ValueError(f"WeightedFPCA: function_weights must be {X.layout.n_functions} positive finite numbers")
        return w

    def _restore_params(self) -> None:
        self.function_weights = self.function_weights_
