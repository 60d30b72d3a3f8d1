"""Motion primitive: a statistical model of structurally similar clips (Du 2022 Sec. 4.4.1).

Fitting follows the thesis step by step:

1. Temporal variation: every clip is warped to the canonical timeline of the
   median-length clip by dynamic time warping (:func:`motionvar.prep.warp_to_median`).
   The warping function f_i(t) (source frame per canonical frame, monotone) is kept.
2. Functional data: the warped clips are fitted by B-splines (Eq. 3.1-3.2,
   :class:`motionvar.du2022.fda.FunctionalMotions`); the warping function is "represented as a
   spline f(t) with the same basis functions as spatial data" and concatenated,
   Y'(t) = {p(t), q_1(t), ..., q_m(t), f(t)}.
3. Latent space: SFPCA (Sec. 3.3.4, Eq. 3.8; :class:`motionvar.du2022.fda.SFPCA`) chooses one
   weight per spatial function by the joint-position reconstruction error. The time
   function does not move any joint, so Eq. 3.8 cannot weigh it: it gets the weight that
   gives it the functional variance of an average weighted spatial function (our choice;
   the thesis does not say). The latent vectors s are the principal scores of the
   Gram-weighted, scaled coefficients of Y'(t) (Eq. 3.3-3.5 on diag(w) Y').
4. Density: a Gaussian mixture with full covariances (Eq. 4.1, scikit-learn EM) whose
   number of components K is the one with the lowest BIC over a configurable range (the
   thesis uses BIC; DFKI's code defaults to AIC).

The model keeps only what synthesis needs (mean, weights, eigenfunctions, GMM, bone
offsets): no motion data (Sec. 4.6.1, "Compactness"). Save/load is npz + json (no pickles,
:mod:`motionvar.io.model_file`).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from sklearn.mixture import GaussianMixture

import json
import math
from collections.abc import Sequence
from dataclasses import asdict, dataclass
from pathlib import Path

import numpy as np
import pandas as pd
from threadpoolctl import threadpool_limits

from ...core.motion import Motion
from ...core.progress import ProgressLog
from ...core.quaternions import qnormalize
from ...core.skeleton import Skeleton
from ...io.atomic import atomic_write
from ...io.dataset import MotionDataset
from ...io.model_file import load_model, model_base
from ...prep import apply_warp, warp_to_median
from ..fda import SFPCA, BSplineBasis, FunctionalMotions, frame_times
from .kinematics import chain_fk
from .settings import GraphSettings, ModelSettings

FORMAT_VERSION = 1


_MODEL = ModelSettings()  # the defaults of config du2022_graph.model


@dataclass(frozen=True)
class PrimitiveOptions:
    """Settings of :meth:`MotionPrimitive.fit`, saved with the model; built from config
    ``du2022_graph.model`` by :meth:`from_settings` (the defaults are :class:`~.settings.ModelSettings`').

    Attributes:
        n_basis: B-spline basis functions per function (Sec. 3.3.3).
        n_components: latent dimension (capped at the number of clips - 1).
        gmm_components: (min, max) number of Gaussians searched by BIC (Eq. 4.1).
        gmm_criterion: "bic" (thesis) or "aic" (DFKI's default).
        sfpca_max_iter: L-BFGS-B iterations of the SFPCA weights (0: the start weights).
        sfpca_weight_groups: "function" (thesis) or "joint" (DFKI).
        reg_covar: added to the GMM covariances' diagonals, relative to the mean variance of
            the latent dimensions (scikit-learn's is absolute; with few clips per component
            an absolute 1e-6 lets BIC pick near-singular components).
        sfpca_eval_frames: canonical frames at which SFPCA's objective runs FK (None: all).
        sfpca_eigensolver: SFPCA's eigensolver ("full" or "tridiagonal", the same to rounding).
        dtw_window: optional Sakoe-Chiba band of the DTW (frames; not a config key).
        seed: random state of the GMM fits and of sampling defaults (config ``du2022_graph.seed``).
    """

    n_basis: int = _MODEL.n_basis
    n_components: int = _MODEL.n_components
    gmm_components: tuple[int, int] = (_MODEL.gmm_min, _MODEL.gmm_max)
    gmm_criterion: str = _MODEL.gmm_criterion
    sfpca_max_iter: int = _MODEL.sfpca_max_iter
    sfpca_weight_groups: str = _MODEL.sfpca_weight_groups
    reg_covar: float = _MODEL.reg_covar
    sfpca_eval_frames: int | None = _MODEL.sfpca_eval_frames
    sfpca_eigensolver: str = _MODEL.sfpca_eigensolver
    dtw_window: int | None = None
    seed: int = GraphSettings.seed

    @classmethod
    def from_settings(cls, model: ModelSettings, seed: int) -> PrimitiveOptions:
        """The options of config ``du2022_graph.model`` with the section's ``seed``."""
        return cls(
            n_basis=model.n_basis,
            n_components=model.n_components,
            gmm_components=(model.gmm_min, model.gmm_max),
            gmm_criterion=model.gmm_criterion,
            sfpca_max_iter=model.sfpca_max_iter,
            sfpca_weight_groups=model.sfpca_weight_groups,
            reg_covar=model.reg_covar,
            sfpca_eval_frames=model.sfpca_eval_frames,
            sfpca_eigensolver=model.sfpca_eigensolver,
            seed=seed,
        )

    def validate(self) -> None:
        lo, hi = self.gmm_components
        if not (1 <= int(lo) <= int(hi)):
            raise ValueError(f"gmm_components must be (min, max) with 1 <= min <= max; got {self.gmm_components}")
        if self.gmm_criterion not in ("bic", "aic"):
            raise ValueError(f"gmm_criterion must be 'bic' or 'aic'; got {self.gmm_criterion!r}")
        if int(self.n_components) < 1:
            raise ValueError(f"n_components must be >= 1; got {self.n_components}")
        if int(self.n_basis) < 4:
            raise ValueError(f"n_basis must be >= 4 (cubic B-splines); got {self.n_basis}")


def select_gmm(
    X: np.ndarray, k_range: tuple[int, int], criterion: str = "bic", reg_covar: float = 1e-6, seed: int = 0
) -> tuple[GaussianMixture, dict[int, float]]:
    """Full-covariance GMMs for K = min..max (capped at the number of points) fitted by
    EM; returns the one with the lowest BIC (or AIC) and every K's score (Eq. 4.1)."""
    from sklearn.mixture import GaussianMixture

    lo, hi = int(k_range[0]), min(int(k_range[1]), len(X))
    if lo > hi:
        raise ValueError(f"GMM: {len(X)} latent points cannot fit {k_range[0]} components")
    best, scores = None, {}
    progress = ProgressLog(f"GMM ({len(X)} points, K = {lo}..{hi}) fit", hi - lo + 1)
    with threadpool_limits(1):  # small EM problems: BLAS threads only add overhead on a loaded machine
        for k in range(lo, hi + 1):
            gmm = GaussianMixture(k, covariance_type="full", reg_covar=reg_covar, random_state=seed, n_init=1).fit(X)
            scores[k] = float(gmm.bic(X) if criterion == "bic" else gmm.aic(X))
            progress(k - lo + 1, scores[k])
            if best is None or scores[k] < scores[best.n_components]:
                best = gmm
    return best, scores


def gmm_log_density(gmm: GaussianMixture, X: np.ndarray) -> np.ndarray:
    """(N,) log p(x) of Eq. 4.1 for a fitted full-covariance GaussianMixture at X (N, d).

    The operations of scikit-learn's ``score_samples`` (1.9: each component's log density
    from its precision Cholesky factor, then its log-sum-exp), so the same numbers, without
    its per-call input validation: that was two thirds of a call on the small batches of the
    Levenberg-Marquardt objective (Eq. 4.9). X must be finite (not checked here)."""
    n_components, d = gmm.means_.shape
    prec_chol = gmm.precisions_cholesky_
    log_det = np.sum(np.log(prec_chol.reshape(n_components, -1)[:, :: d + 1]), axis=1)
    log_prob = np.empty((len(X), n_components), dtype=X.dtype)
    for k in range(n_components):  # a loop over the (few) Gaussians; samples batched
        y = (X @ prec_chol[k]) - (gmm.means_[k] @ prec_chol[k])
        log_prob[:, k] = np.sum(np.square(y), axis=1)
    weighted = -0.5 * (d * math.log(2 * math.pi) + log_prob) + log_det + np.log(gmm.weights_)
    # log-sum-exp over the Gaussians as scikit-learn's: shifted by the maximum, whose terms are counted in m
    top = np.max(weighted, axis=1, keepdims=True)
    is_top = weighted == top
    rest = weighted.copy()
    rest[is_top] = -np.inf
    m = np.sum(is_top.astype(rest.dtype), axis=1, keepdims=True, dtype=rest.dtype)
    total = np.sum(np.exp(rest - np.where(np.isfinite(top), top, 0)), axis=1, keepdims=True, dtype=rest.dtype)
    total = np.where(total == 0, total, total / m)
    return np.squeeze(np.log1p(total) + np.log(m) + top, axis=1)


def primitive_clips(
    dataset: MotionDataset, primitive: str, source: str = "dataset"
) -> tuple[list[Motion], pd.DataFrame]:
    """(motions, metadata rows) of one primitive from a loaded dataset
    ; ValueError naming ``source`` (its file) and the
    primitives it has when there are fewer than 3 clips."""
    mask = (dataset.metadata["primitive"] == primitive).to_numpy()
    if mask.sum() < 3:
        have = dataset.metadata["primitive"].value_counts().to_dict()
        raise ValueError(
            f"{source}: {int(mask.sum())} clips of primitive {primitive!r} (need >= 3; config "
            f"du2022_graph.primitives / du2022_graph.search.primitives); clips per primitive: {have}"
        )
    pairs = dataset.select(mask)
    short = [f"{row['clip_id']} ({m.n_frames} frame(s))" for row, m in pairs if m.n_frames < 2]
    if short:
        raise ValueError(
            f"{source}: clips {', '.join(short)} of primitive {primitive!r} have fewer than 2 frames; "
            "DTW needs at least 2 (config prep.min_primitive_s drops such primitives)"
        )
    return [m for _, m in pairs], dataset.metadata[mask].reset_index(drop=True)


def functional_clips(
    motions: Sequence[Motion], n_basis: int, window: int | None, clip_ids: Sequence[str], name: str
) -> tuple[FunctionalMotions, np.ndarray]:
    """Steps 1-2 of :meth:`MotionPrimitive.fit`: the clips warped to the median-length clip by DTW
    (``window``) and fitted by ``n_basis`` B-splines, and (N, K, D + 1) coefficients of
    Y'(t) = {p(t), q_1(t), ..., q_m(t), f(t)}, the warping function f(t) (source frame per
    canonical frame) on the same basis. ``clip_ids`` name the clips in errors."""
    ref, warps = warp_to_median(motions, window=window, clip_ids=clip_ids)
    n_ref = motions[ref].n_frames
    if n_ref < n_basis:
        raise ValueError(f"primitive {name}: the canonical clip has {n_ref} frames, fewer than n_basis = {n_basis}")
    warped = [apply_warp(m, w, clip_id=c) for m, w, c in zip(motions, warps, clip_ids)]
    fd = FunctionalMotions.from_motions(warped, n_basis, n_frames=n_ref)
    time_coefs = fd.basis.fit(np.stack(warps)[..., None])  # (N, K, 1): f(t) in source frames
    return fd, np.concatenate([fd.coefs, time_coefs], axis=-1)


def _gmm_from_arrays(weights: np.ndarray, means: np.ndarray, covariances: np.ndarray) -> GaussianMixture:
    """A fitted GaussianMixture from its parameters (for :meth:`MotionPrimitive.load`)."""
    from sklearn.mixture import GaussianMixture

    gmm = GaussianMixture(len(weights), covariance_type="full")
    gmm.weights_, gmm.means_, gmm.covariances_ = weights, means, covariances
    prec = np.linalg.inv(covariances)
    gmm.precisions_ = prec
    gmm.precisions_cholesky_ = np.linalg.cholesky(prec)
    gmm.converged_, gmm.n_iter_, gmm.lower_bound_ = True, 0, 0.0
    gmm.n_features_in_ = means.shape[1]
    return gmm


class MotionPrimitive:
    """A motion primitive M(s): latent vector s -> motion (Sec. 4.4.1), with density p(s)
    (Eq. 4.1); a scikit-learn-style estimator: ``MotionPrimitive(name, options).fit(motions)``
    (see the module docstring for the steps).

    Parameters: ``name``, ``options`` (:class:`PrimitiveOptions`). Learned by :meth:`fit`:
    ``skeleton`` (names, parents, mean bone offsets), ``fps``, ``n_frames`` (canonical timeline),
    ``basis``, ``mean_`` (K, D + 1) mean coefficients of Y'(t), ``weights_`` (D + 1,) function
    weights (SFPCA's, then the time function's), ``components_`` (n, K (D + 1)) principal axes,
    ``explained_variance_ratio_``, ``gmm_`` (scikit-learn GaussianMixture), ``gmm_scores_``
    (K -> BIC/AIC), ``training_latent_`` (N, n) training scores (not saved: the model holds no
    data).
    """

    def __init__(self, name: str = "primitive", options: PrimitiveOptions | None = None) -> None:
        self.name = name
        self.options = options or PrimitiveOptions()
        self.training_latent_: np.ndarray | None = None

    def set_fitted(
        self,
        skeleton: Skeleton,
        fps: float,
        n_frames: int,
        basis: BSplineBasis,
        mean: np.ndarray,
        weights: np.ndarray,
        components: np.ndarray,
        gmm: GaussianMixture,
        explained_variance_ratio: np.ndarray | None = None,
        gmm_scores: dict[int, float] | None = None,
    ) -> MotionPrimitive:
        """Set the learned state (:meth:`fit`, or a saved model's, :meth:`load`); returns self."""
        self.skeleton = skeleton
        self.fps = float(fps)
        self.n_frames = int(n_frames)
        self.basis = basis
        self.mean_ = np.asarray(mean, dtype=float)
        self.weights_ = np.asarray(weights, dtype=float)
        self.components_ = np.asarray(components, dtype=float)
        self.gmm_ = gmm
        self.explained_variance_ratio_ = (
            np.zeros(len(components))
            if explained_variance_ratio is None
            else np.asarray(explained_variance_ratio, dtype=float)
        )
        self.gmm_scores_ = dict(gmm_scores or {})
        self._gram_sqrt, self._gram_isqrt = basis.gram_sqrt()
        K, D1 = self.mean_.shape
        # eigenfunction coefficients of Y'(t), unscaled: (n, K, D + 1)
        self._eig = np.einsum("kl,nld->nkd", self._gram_isqrt, self.components_.reshape(-1, K, D1)) / self.weights_
        self._maps: dict[tuple[int, ...], tuple[np.ndarray, np.ndarray]] = {}
        self._nll_ref: float | None = None
        return self

    # ---- fitting ---------------------------------------------------------------------
    def fit(self, motions: Sequence[Motion], clip_ids: Sequence[str] | None = None) -> MotionPrimitive:
        """Fit the primitive to aligned clips of one primitive (module docstring, steps 1-4);
        ``clip_ids`` name the clips in errors (else "<name> #<index>")."""
        opt, name = self.options, self.name
        opt.validate()
        if len(motions) < 3:
            raise ValueError(f"primitive {name}: need at least 3 clips to model; got {len(motions)}")
        ids = [f"{name} #{i}" for i in range(len(motions))] if clip_ids is None else list(clip_ids)
        fd, coefs = functional_clips(motions, opt.n_basis, opt.dtw_window, ids, name)
        n_ref = fd.n_frames
        n = int(min(opt.n_components, len(motions) - 1, fd.coefs.shape[1] * fd.coefs.shape[2]))
        sfpca = SFPCA(
            n_components=n,
            max_iter=opt.sfpca_max_iter,
            weight_groups=opt.sfpca_weight_groups,
            n_eval_frames=opt.sfpca_eval_frames,
            eigensolver=opt.sfpca_eigensolver,
        ).fit(fd)
        w_sp = sfpca.function_weights_
        gram_sqrt, _ = fd.basis.gram_sqrt()
        centred = np.einsum("kl,nld->nkd", gram_sqrt, coefs - coefs.mean(axis=0))
        var = (centred**2).sum(axis=(0, 1)) / len(coefs)  # functional variance per function
        w_t = np.sqrt(np.mean(var[:-1] * w_sp**2) / max(var[-1], 1e-12)) if var[-1] > 1e-12 else 1.0
        weights = np.append(w_sp, w_t)
        Z = (centred * weights).reshape(len(coefs), -1)
        _, sv, vt = np.linalg.svd(Z, full_matrices=False)
        comps = vt[:n]
        comps *= np.where(comps[np.arange(n), np.argmax(np.abs(comps), axis=1)] < 0, -1.0, 1.0)[:, None]
        evr = sv[:n] ** 2 / max(float(np.sum(sv**2)), 1e-300)
        latent = Z @ comps.T
        reg = opt.reg_covar * float(np.mean(np.var(latent, axis=0)))
        gmm, scores = select_gmm(latent, opt.gmm_components, opt.gmm_criterion, reg, opt.seed)
        sk = motions[0].skeleton.with_offsets(fd.offsets.mean(axis=0))
        self.set_fitted(
            sk,
            motions[0].fps,
            n_ref,
            fd.basis,
            coefs.mean(axis=0),
            weights,
            comps,
            gmm,
            explained_variance_ratio=evr,
            gmm_scores=scores,
        )
        self.training_latent_ = latent
        return self

    # ---- latent space ----------------------------------------------------------------
    @property
    def n_latent(self) -> int:
        return self.components_.shape[0]

    def training_latents(self, motions: Sequence[Motion], source: str = "dataset") -> np.ndarray:
        """(N, d) latent vectors of the clips this primitive was fitted to, recomputed from them
        (steps 1-3 of :meth:`fit` with the model's mean, weights and principal axes): the model
        keeps no data (Sec. 4.6.1). ValueError naming ``source`` when the clips are not the
        model's (their canonical length differs, or their scores are not centred)."""
        ids = [f"{source}: {self.name} #{i}" for i in range(len(motions))]
        fd, coefs = functional_clips(motions, self.basis.n_basis, self.options.dtw_window, ids, self.name)
        if fd.n_frames != self.n_frames:
            raise ValueError(
                f"{source}: the {len(motions)} clips of {self.name} are not the ones its model was fitted to "
                f"(median-length clip {fd.n_frames} frames, the model's canonical timeline {self.n_frames})"
            )
        gram_sqrt, _ = self.basis.gram_sqrt()
        scaled = np.einsum("kl,nld->nkd", gram_sqrt, coefs - self.mean_) * self.weights_
        latent = scaled.reshape(len(coefs), -1) @ self.components_.T
        if np.abs(latent.mean(axis=0)).max() > 1e-6 * max(float(latent.std()), 1.0):
            raise ValueError(
                f"{source}: the {len(motions)} clips of {self.name} are not the ones its model was fitted to "
                "(their latent scores are not centred on the model's mean)"
            )
        return latent

    @property
    def n_spatial(self) -> int:
        """D = 3 + 4 J spatial functions (the time function is function D)."""
        return self.mean_.shape[1] - 1

    def coefs(self, s: np.ndarray) -> np.ndarray:
        """(N, K, D + 1) coefficients of Y'(t) for latent vectors s (N, n) (back-projection)."""
        s = self._check_latent(s)
        return self.mean_ + np.einsum("bn,nkd->bkd", s, self._eig)

    def _check_latent(self, s: np.ndarray) -> np.ndarray:
        s = np.atleast_2d(np.asarray(s, dtype=float))
        if s.ndim != 2 or s.shape[1] != self.n_latent:
            raise ValueError(f"primitive {self.name}: latent vectors must be (N, {self.n_latent}); got {s.shape}")
        return s

    def sample(self, n: int, rng: np.random.Generator | int | None = None) -> np.ndarray:
        """(n, d) latent vectors drawn from the GMM (Eq. 4.1)."""
        rng = np.random.default_rng(rng)
        g = self.gmm_
        counts = rng.multinomial(int(n), g.weights_ / g.weights_.sum())
        out = [rng.multivariate_normal(g.means_[k], g.covariances_[k], size=c) for k, c in enumerate(counts) if c]
        s = np.concatenate(out) if out else np.zeros((0, self.n_latent))
        return s[rng.permutation(len(s))]

    def log_prob(self, s: np.ndarray) -> np.ndarray:
        """(N,) log p(s) under the GMM (Eq. 4.1; :func:`gmm_log_density`)."""
        s = self._check_latent(s)
        if not np.all(np.isfinite(s)):
            raise ValueError(f"primitive {self.name}: latent vectors contain NaN or infinity")
        return gmm_log_density(self.gmm_, s)

    def nll_reference(self) -> float:
        """min over the component means of -log p(s): an offset that makes the negative
        log-likelihood term of the MAP objective (Eq. 4.9) start near zero."""
        if self._nll_ref is None:
            self._nll_ref = float(-np.max(self.log_prob(self.gmm_.means_)))
        return self._nll_ref

    # ---- observation space -----------------------------------------------------------
    def frame_map(self, frames: Sequence[int]) -> tuple[np.ndarray, np.ndarray]:
        """Linear map from s to the spatial function values at canonical ``frames``:
        values = mean (F, D) + einsum(s, A (n, F, D)); cached per frame tuple."""
        key = tuple(int(f) for f in frames)
        if key not in self._maps:
            if any(not 0 <= f < self.n_frames for f in key):
                raise ValueError(
                    f"primitive {self.name}: frames {key} outside the canonical timeline [0, {self.n_frames - 1}]"
                )
            B = self.basis.design(frame_times(self.n_frames)[list(key)])
            D = self.n_spatial
            self._maps[key] = (B @ self.mean_[:, :D], np.einsum("fk,nkd->nfd", B, self._eig[..., :D]))
        return self._maps[key]

    def key_frame_pose(
        self, s: np.ndarray, frames: Sequence[int], joints: Sequence[int]
    ) -> tuple[np.ndarray, np.ndarray]:
        """Global positions (N, F, len(joints), 3) and rotations (N, F, len(joints), 4) of
        ``joints`` at canonical ``frames`` for latent vectors s: f_k(M(s)) of Eq. 4.2."""
        s = self._check_latent(s)
        mean, A = self.frame_map(frames)
        values = mean + np.einsum("bn,nfd->bfd", s, A)
        J = self.skeleton.n_joints
        root, quats = values[..., :3], qnormalize(values[..., 3:].reshape(*values.shape[:2], J, 4))
        return chain_fk(quats, root, self.skeleton.offsets, self.skeleton.parents, joints)

    def time_function(self, coefs: np.ndarray) -> np.ndarray:
        """(N, n_frames) warping functions (source frame per canonical frame), made
        monotone and starting at 0 (the spline fit need not be exactly monotone)."""
        f = self.basis.evaluate(coefs[..., -1:], self.n_frames)[..., 0]
        f = np.maximum.accumulate(f - f[:, :1], axis=1)
        return f

    def to_motions(self, s: np.ndarray, warp_time: bool = True) -> list[Motion]:
        """Back-project latent vectors to Motions (Sec. 4.5.2). With ``warp_time`` each
        clip is unwarped by its time function f(t) (its own length); otherwise on the
        canonical timeline."""
        coefs = self.coefs(s)
        D, J = self.n_spatial, self.skeleton.n_joints
        canon = frame_times(self.n_frames)
        out = []
        warps = self.time_function(coefs) if warp_time else None
        for i, c in enumerate(coefs):
            if warp_time and warps[i, -1] >= 1.0:
                f = warps[i]
                n_src = int(round(f[-1])) + 1
                u = np.interp(np.arange(n_src, dtype=float), f, canon)
            else:
                u = canon
            values = self.basis.design(np.clip(u, 0.0, 1.0)) @ c[:, :D]
            rot = qnormalize(values[:, 3:].reshape(-1, J, 4))
            out.append(Motion(skeleton=self.skeleton, root_pos=values[:, :3], rotations=rot, fps=self.fps))
        return out

    # ---- persistence -----------------------------------------------------------------
    def save(self, path: str | Path) -> list[Path]:
        """Write ``path``.npz (arrays) and ``path``.json (names, settings); returns both paths.

        Both go through :func:`motionvar.io.atomic.atomic_write` (no half-written file);
        the JSON is written without a trailing newline, as the models of Sec. 4.6.1's size
        table always were (:func:`~motionvar.io.model_file.save_model` adds one)."""
        base = model_base(path)
        g = self.gmm_
        arrays = dict(
            mean=self.mean_,
            weights=self.weights_,
            components=self.components_,
            explained_variance_ratio=self.explained_variance_ratio_,
            offsets=self.skeleton.offsets,
            parents=self.skeleton.parents,
            gmm_weights=g.weights_,
            gmm_means=g.means_,
            gmm_covariances=g.covariances_,
        )
        meta = dict(
            format_version=FORMAT_VERSION,
            name=self.name,
            joint_names=list(self.skeleton.names),
            fps=self.fps,
            n_frames=self.n_frames,
            n_basis=self.basis.n_basis,
            degree=self.basis.degree,
            gmm_scores={str(k): v for k, v in self.gmm_scores_.items()},
            options=asdict(self.options),
        )

        def write_npz(tmp: Path) -> None:
            with open(tmp, "wb") as fh:  # a file object: np.savez would append .npz to the name
                np.savez(fh, **arrays)

        npz = atomic_write(base.with_suffix(".npz"), write_npz)
        js = atomic_write(base.with_suffix(".json"), lambda tmp: tmp.write_text(json.dumps(meta, indent=1)))
        return [npz, js]

    @classmethod
    def load(cls, path: str | Path) -> "MotionPrimitive":
        """Read a primitive written by :meth:`save` (``path`` with or without suffix)."""
        base = model_base(path)
        try:
            a, meta = load_model(base)
        except (OSError, ValueError) as exc:
            raise ValueError(f"{base}: not a readable motion primitive ({exc})") from exc
        if meta.get("format_version") != FORMAT_VERSION:
            raise ValueError(
                f"{base.with_suffix('.json')}: format_version {meta.get('format_version')} (expected {FORMAT_VERSION})"
            )
        opts = dict(meta["options"])
        opts["gmm_components"] = tuple(opts["gmm_components"])
        sk = Skeleton(names=tuple(meta["joint_names"]), parents=a["parents"], offsets=a["offsets"])
        gmm = _gmm_from_arrays(a["gmm_weights"], a["gmm_means"], a["gmm_covariances"])
        return cls(meta["name"], PrimitiveOptions(**opts)).set_fitted(
            sk,
            meta["fps"],
            meta["n_frames"],
            BSplineBasis(meta["n_basis"], meta["degree"]),
            a["mean"],
            a["weights"],
            a["components"],
            gmm,
            explained_variance_ratio=a["explained_variance_ratio"],
            gmm_scores={int(k): v for k, v in meta["gmm_scores"].items()},
        )
