"""Scaled Functional PCA (SFPCA, Du 2022, Sec. 3.3.4, Eq. 3.6-3.8).

SFPCA scales every function of the motion (root translation channels, quaternion
components) by one weight w_d and runs FPCA on the scaled functions diag(w) Y(t). The
weights minimise the reconstruction error in observation space, i.e. of the joint
positions computed by forward kinematics f_k (Eq. 3.8):

    argmin_w (1/N) || f_k(Y(t)) - f_k(diag(w)^-1 V' V'^T diag(w) Y(t)) ||_F^2,

where V' are the leading eigenfunctions of diag(w) Y(t), recomputed at every evaluation.
As in the thesis the weights are found by L-BFGS-B (scipy), starting from the better of
the raw (w = 1) and the z-scored (w = 1 / sigma) functions.

Gradients: ``gradient="autograd"`` (default) differentiates the whole objective in torch:
forward kinematics (:func:`motionvar.core.fk_torch`) and the eigen-decomposition, through
the projector onto the leading eigenvectors (:class:`TopEigenvectors`, exact when the
n-th and (n+1)-th eigenvalues differ). ``gradient="finite_difference"`` is the thesis'
setting: scipy's L-BFGS-B with its own 2-point finite differences of the objective (one
evaluation per weight per gradient; float64 so that the difference quotients are not
rounding noise). Both minimise the same objective; ``benchmarks/fda_sfpca.py`` measures them.
"""

from __future__ import annotations

import time

import numpy as np
from scipy.optimize import minimize

from ...core.progress import ProgressLog
from .fpca import FPCA, functional_std, register_saved, zscore_weights
from .functions import FunctionalMotions
from .settings import SfpcaSettings


def _torch():
    import torch

    return torch


class TridiagonalEigen:
    """All eigenpairs of a symmetric matrix A = Q T Q^T, kept in the tridiagonal basis.

    LAPACK's Householder reduction (``dsytrd``) gives T and the reflectors of Q, and MRRR
    (``dstemr``, through :func:`scipy.linalg.eigh_tridiagonal`) T's eigenvectors Z in O(m^2).
    Only the eigenvectors that are asked for are transformed back (Q Z[:, cols]), which is
    what a full ``eigh`` spends most of its time on (2 m^3 flops)."""

    def __init__(self, A: np.ndarray) -> None:
        from scipy.linalg import eigh_tridiagonal
        from scipy.linalg.lapack import dsytrd, dsytrd_lwork

        m = A.shape[0]
        self.m = m
        if m == 1:
            self.reflectors, self.tau = None, None
            self.evals, self.Z = np.asarray(A, dtype=float).reshape(1).copy(), np.ones((1, 1))
            return
        lwork, info = dsytrd_lwork(m, lower=1)
        reflectors, d, e, tau, info = dsytrd(np.asfortranarray(A), lower=1, lwork=int(lwork))
        if info != 0:
            raise np.linalg.LinAlgError(f"dsytrd failed (info {info})")
        self.reflectors, self.tau = reflectors, tau
        self.evals, self.Z = eigh_tridiagonal(d, e)

    def apply_q(self, B: np.ndarray, transpose: bool = False) -> np.ndarray:
        """Q B, or Q^T B, for B (m, k): the reflectors act on rows 2..m (LAPACK's ``dormtr``
        for a lower reduction is ``dormqr`` on A[1:, :-1])."""
        from scipy.linalg.lapack import dormqr

        out = np.array(B, dtype=float, order="F")
        if self.m == 1 or out.shape[1] == 0:
            return out
        lwork = 64 * out.shape[1] + 65 * 64
        res, _, info = dormqr("L", "T" if transpose else "N", self.reflectors[1:, :-1], self.tau, out[1:], lwork)
        if info != 0:
            raise np.linalg.LinAlgError(f"dormqr failed (info {info})")
        out[1:] = res
        return out


class TopEigenvectors:
    """The ``n`` leading eigenvectors (columns) of a symmetric matrix, differentiable for
    losses that depend only on the subspace they span (such as the reconstruction V V^T z
    of Eq. 3.3): the backward pass keeps only the cross terms between kept and dropped
    eigenvectors, 1 / (lambda_kept - lambda_dropped). Unlike differentiating
    ``torch.linalg.eigh`` itself it stays finite when dropped eigenvalues repeat (the zero
    eigenvalues of a rank-deficient data matrix) or kept ones are close.

    ``solver``: ``"tridiagonal"`` (:class:`TridiagonalEigen`: the dropped eigenvectors stay in
    the tridiagonal basis, where the backward pass uses them, and only the n kept ones are
    transformed back) or ``"full"`` (``torch.linalg.eigh``: every eigenvector). The same
    subspace and gradient to rounding; the tridiagonal one in about half the time at
    m = 1,500 (``benchmarks/fda_sfpca.py``)."""

    SOLVERS = ("tridiagonal", "full")
    _fn = None

    @classmethod
    def apply(cls, A, n: int, solver: str = SfpcaSettings.eigensolver):
        if cls._fn is None:
            torch = _torch()

            class _Top(torch.autograd.Function):
                @staticmethod
                def forward(ctx, A, n, solver):
                    ctx.n, ctx.solver = n, solver
                    if solver == "full":
                        evals, evecs = torch.linalg.eigh(A)
                        ctx.save_for_backward(evals, evecs)
                        return evecs[:, -n:]
                    eig = TridiagonalEigen(A.detach().numpy())
                    kept = torch.as_tensor(eig.apply_q(eig.Z[:, -n:]))
                    ctx.eig = eig
                    ctx.save_for_backward(kept)
                    return kept

                @staticmethod
                def backward(ctx, grad):
                    n = ctx.n
                    if ctx.solver == "full":
                        evals, evecs = ctx.saved_tensors
                        m = evals.shape[0]
                        if n >= m:
                            return torch.zeros_like(evecs), None, None
                        kept, dropped = evecs[:, -n:], evecs[:, :-n]
                        coupling = (dropped.T @ grad) / _gap(torch, evals, n)
                        gA = dropped @ coupling @ kept.T
                        return 0.5 * (gA + gA.T), None, None
                    (kept,) = ctx.saved_tensors
                    eig = ctx.eig
                    if n >= eig.m:
                        return torch.zeros((eig.m, eig.m), dtype=kept.dtype), None, None
                    evals = torch.as_tensor(eig.evals)
                    dropped_t = torch.as_tensor(eig.Z[:, :-n])  # dropped eigenvectors of T
                    coupling = (
                        dropped_t.T @ torch.as_tensor(eig.apply_q(grad.detach().numpy(), transpose=True))
                    ) / _gap(torch, evals, n)
                    gA = torch.as_tensor(eig.apply_q((dropped_t @ coupling).numpy())) @ kept.T
                    return 0.5 * (gA + gA.T), None, None

            cls._fn = _Top
        if solver not in cls.SOLVERS:
            raise ValueError(f"TopEigenvectors: solver must be one of {cls.SOLVERS}; got {solver!r}")
        return cls._fn.apply(A, n, solver)


def _gap(torch, evals, n: int):
    """lambda_kept - lambda_dropped (dropped x kept), floored at 1e-12 of the largest |lambda|."""
    gap = evals[-n:][None, :] - evals[:-n][:, None]
    floor = 1e-12 * torch.clamp(evals.abs().max(), min=1e-300)
    return torch.clamp(gap, min=floor)


def _qmul_jm(a, b):
    """Hamilton product of quaternions stored as (4, M) tensors (components first)."""
    torch = _torch()
    aw, ax, ay, az = a.unbind(0)
    bw, bx, by, bz = b.unbind(0)
    return torch.stack(
        (
            aw * bw - ax * bx - ay * by - az * bz,
            aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw,
        ),
        dim=0,
    )


def _qrot_jm(q, v):
    """Vectors v (3, M) rotated by unit quaternions q (4, M)."""
    torch = _torch()
    u = q[1:]
    t = 2.0 * torch.linalg.cross(u, v, dim=0)
    return v + q[:1] * t + torch.linalg.cross(u, t, dim=0)


def fk_joint_major(quats, root, offsets_jm, parents):
    """Joint positions (N, T, J, 3) of unit quaternions (N, T, J, 4), root positions
    (N, T, 3) and bone offsets ``offsets_jm`` (J, 3, N*T): :func:`motionvar.core.fk_torch`
    computed in a joint-major layout in which every joint's components are contiguous
    (N*T,) rows. The same operations in the same order as ``fk_torch``, so the positions
    and their gradients are bit-identical, in about 20 % less time (measured at N*T =
    44,400, the full walk_leftStance objective): elementwise kernels on contiguous rows
    instead of strided views of the (N, T, J, 4) array."""
    torch = _torch()
    N, T, J, _ = quats.shape
    rots = quats.permute(2, 3, 0, 1).reshape(J, 4, N * T).unbind(0)
    locs = offsets_jm.unbind(0)
    gpos = [root.permute(2, 0, 1).reshape(3, N * T)]
    grot = [rots[0]]
    for j in range(1, J):
        p = int(parents[j])
        grot.append(_qmul_jm(grot[p], rots[j]))
        gpos.append(gpos[p] + _qrot_jm(grot[p], locs[j]))
    return torch.stack(gpos).reshape(J, 3, N, T).permute(2, 3, 0, 1).contiguous()


def scatter_is_cheaper(n_clips: int, n_coefs: int) -> bool:
    """Whether Eq. 3.8's eigenvectors are cheaper from the (n_coefs)^2 scatter matrix than
    from the (n_clips)^2 Gram matrix. A decomposition costs ~m^3; the Gram route also
    multiplies n_clips^2 n_coefs three times (the matrix and its backward pass), about
    2 n_clips^2 n_coefs in the same units (measured single-threaded with the tridiagonal
    solver, 700-1,458 clips, 900-1,905 coefficients)."""
    return n_coefs**3 <= n_clips**3 + 2 * n_clips**2 * n_coefs


class ObservationObjective:
    """Eq. 3.8 as a function of the function weights w: the mean squared joint-position
    error (cm^2, over clips, frames and joints) of the FPCA reconstruction of diag(w) Y(t)
    with ``n_components`` eigenfunctions.

    Args:
        X: the clips' functional data.
        n_components: latent dimension.
        n_eval_frames: canonical frames at which f_k is evaluated (default ``X.n_frames``).
        dtype: torch dtype of the forward kinematics (float32 is 2x faster, docs/stack.md);
            the eigen-decomposition is always float64.
        eigensolver: how the leading eigenvectors are computed (:class:`TopEigenvectors`).
    """

    def __init__(
        self,
        X: FunctionalMotions,
        n_components: int,
        n_eval_frames: int | None = None,
        dtype=None,
        eigensolver: str = SfpcaSettings.eigensolver,
    ) -> None:
        torch = _torch()
        self.torch = torch
        self.eigensolver = eigensolver
        self.dtype = dtype or torch.float32
        self.n_components = int(n_components)
        T = int(n_eval_frames or X.n_frames)
        N, K, D = X.coefs.shape
        # Functions that are the same in every clip (e.g. joints a rig never moves) have a
        # zero column in the data: their weights change nothing, so the PCA leaves them out
        # (an exact shortcut) and they are reconstructed as their mean.
        std = functional_std(X)
        self.active = torch.as_tensor(np.flatnonzero(std > 1e-12 * max(float(std.max()), 1e-300)))
        Da = len(self.active)
        self.shape = (N, K, D, Da)
        gram_sqrt, gram_isqrt = X.basis.gram_sqrt()
        mean = X.coefs.mean(axis=0)
        centred = np.einsum("kl,nld->nkd", gram_sqrt, X.coefs - mean)[:, :, self.active.numpy()]
        self.centred = torch.as_tensor(centred.reshape(N, K * Da), dtype=torch.float64)
        # the same eigenvectors come from the scatter matrix diag(w) C0 diag(w) (C0 computed
        # once) or from the clips' Gram matrix z z^T (rebuilt at every evaluation, and its
        # backward pass two more N x N x K*Da products): the cheaper of the two
        self.scatter = self.centred.T @ self.centred if scatter_is_cheaper(N, K * Da) else None
        design = X.basis.design_frames(T)
        self.eval_matrix = torch.as_tensor(design @ gram_isqrt, dtype=self.dtype)
        self.mean_values = torch.as_tensor(design @ mean, dtype=self.dtype)
        self.target = torch.as_tensor(X.positions(n_frames=T), dtype=self.dtype)
        self.offsets = torch.as_tensor(X.offsets[:, None], dtype=self.dtype)
        self.parents = np.asarray(X.parents)
        self.n_joints = X.layout.n_joints
        # the bone offsets per joint and coordinate over all (clip, frame) pairs, contiguous:
        # the layout of :func:`fk_joint_major`
        J = self.n_joints
        self.offsets_jm = self.offsets.expand(N, T, J, 3).permute(2, 3, 0, 1).reshape(J, 3, N * T).contiguous()

    @property
    def active_functions(self) -> np.ndarray:
        """Indices of the functions that vary between clips (the others have no effect)."""
        return self.active.numpy()

    def loss(self, w):
        """Torch scalar objective for torch weights ``w`` (D,) (differentiable)."""
        torch = self.torch
        N, K, D, Da = self.shape
        wa = w[self.active]
        w_rep = wa.repeat(K)  # per (k, d) coefficient, flattened k-major like the data
        z = self.centred * w_rep
        n = min(self.n_components, min(N, K * Da))
        if self.scatter is not None:
            v = TopEigenvectors.apply(self.scatter * torch.outer(w_rep, w_rep), n, self.eigensolver)
            z_hat = (z @ v) @ v.T
        else:  # leading eigenvectors of the smaller Gram matrix
            u = TopEigenvectors.apply(z @ z.T, n, self.eigensolver)
            z_hat = u @ (u.T @ z)
        c_active = (z_hat / w_rep).reshape(N, K, Da).to(self.dtype)
        c_hat = torch.zeros((N, K, D), dtype=self.dtype).index_copy(2, self.active, c_active)
        values = torch.einsum("tk,nkd->ntd", self.eval_matrix, c_hat) + self.mean_values
        root = values[..., :3]
        quats = values[..., 3:].reshape(N, values.shape[1], self.n_joints, 4)
        quats = quats * torch.rsqrt((quats * quats).sum(-1, keepdim=True))
        pos = fk_joint_major(quats, root, self.offsets_jm, self.parents)
        return ((pos - self.target) ** 2).sum(-1).mean()

    def value(self, w: np.ndarray) -> float:
        with self.torch.no_grad():
            return float(self.loss(self.torch.as_tensor(w, dtype=self.torch.float64)))

    def value_and_grad(self, w: np.ndarray) -> tuple[float, np.ndarray]:
        wt = self.torch.as_tensor(w, dtype=self.torch.float64).requires_grad_(True)
        loss = self.loss(wt)
        (grad,) = self.torch.autograd.grad(loss, wt)
        return float(loss.detach()), grad.numpy().astype(float)


class StallTest:
    """L-BFGS-B callback (scipy's ``intermediate_result`` form) that ends the run, by
    raising StopIteration, once the objective fell by at most ``rtol`` (relative) over the
    last ``window`` iterations."""

    def __init__(self, window: int, rtol: float) -> None:
        self.window, self.rtol = window, rtol
        self.history: list[float] = []
        self.stopped = False

    def __call__(self, intermediate_result) -> None:
        self.history.append(float(intermediate_result.fun))
        if self.window and len(self.history) > self.window:
            before, now = self.history[-1 - self.window], self.history[-1]
            if before - now <= self.rtol * abs(before):
                self.stopped = True
                raise StopIteration


@register_saved
class SFPCA(FPCA):
    """Scaled FPCA (Eq. 3.8), sklearn-style.

    The options that config ``du2022_fda.sfpca`` sets default to :class:`.settings.SfpcaSettings`'s
    (:func:`motionvar.du2022.fda.sfpca_for` builds an SFPCA from those settings).

    Args:
        n_components: latent dimension (weights are optimised for this number of
            eigenfunctions, as in the thesis).
        weight_groups: ``"function"`` (faithful: one weight per function, D = 3 + 4J) or
            ``"joint"`` (one weight for the root translation and one per joint quaternion,
            as DFKI's implementation).
        gradient: ``"autograd"`` or ``"finite_difference"`` (thesis; see module docstring).
        max_iter: L-BFGS-B iterations.
        tol: L-BFGS-B ``ftol`` (relative reduction of the objective).
        bounds: (low, high) of the weights relative to the initial weights.
        n_eval_frames: canonical frames for f_k in the objective (default: all).
        init: ``"best"`` (thesis: the better of raw and z-scored), ``"raw"`` or ``"normalized"``.
        stop_window, stop_rtol: besides L-BFGS-B's own tests, stop once the objective fell by
            at most ``stop_rtol`` (relative) over the last ``stop_window`` iterations (0: off,
            the thesis' setting: it states no stopping rule). L-BFGS-B's ``ftol`` compares one
            iteration with the next; a window is less easily fooled by a slow creep, but a
            long plateau before a drop still passes for convergence (measured at full size:
            d = 5 fell 8 % after 10 flat iterations), hence off by default.
        eigensolver: how the objective's leading eigenvectors are computed at each evaluation
            (:class:`TopEigenvectors`: ``"tridiagonal"`` or ``"full"``; the same to rounding).

    Fitted attributes (besides FPCA's): ``init_`` ("raw" or "normalized"), ``loss_raw_``,
    ``loss_normalized_``, ``loss_`` (objective at the optimum, cm^2), ``n_iter_``,
    ``n_evals_``, ``fit_time_s_``, ``converged_``, ``stop_`` (what stopped it: ``"window"``
    for the stall test above, else L-BFGS-B's message).
    """

    _EXTRA_SAVED = ("init_", "loss_raw_", "loss_normalized_", "loss_", "n_iter_")
    _OPTIONAL_SAVED = ("n_evals_", "converged_", "fit_time_s_", "stop_")
    _SAVED_PARAMS = (
        "weight_groups",
        "gradient",
        "max_iter",
        "tol",
        "bounds",
        "n_eval_frames",
        "init",
        "stop_window",
        "stop_rtol",
        "eigensolver",
    )

    def __init__(
        self,
        n_components: int = 20,
        weight_groups: str = SfpcaSettings.weight_groups,
        gradient: str = SfpcaSettings.gradient,
        max_iter: int = SfpcaSettings.max_iter,
        tol: float = SfpcaSettings.tol,
        bounds: tuple[float, float] = (1e-3, 1e3),
        n_eval_frames: int | None = None,
        init: str = "best",
        stop_window: int = SfpcaSettings.stop_window,
        stop_rtol: float = SfpcaSettings.stop_rtol,
        eigensolver: str = SfpcaSettings.eigensolver,
    ) -> None:
        super().__init__(n_components)
        self.weight_groups = weight_groups
        self.gradient = gradient
        self.max_iter = max_iter
        self.tol = tol
        self.bounds = bounds
        self.n_eval_frames = n_eval_frames
        self.init = init
        self.stop_window = stop_window
        self.stop_rtol = stop_rtol
        self.eigensolver = eigensolver

    def _restore_params(self) -> None:
        SFPCA.__init__(self, self.n_components)

    def fit_summary(self) -> str:
        """One line on the fit: start weights, iterations (and whether the stall window
        ended them), loss."""
        stalled = " (flat window)" if getattr(self, "stop_", "") == "window" else ""
        return f"init {self.init_}, {self.n_iter_} it{stalled}, loss {self.loss_:.4g} cm^2"

    def _check_params(self) -> None:
        choices = {
            "weight_groups": ("function", "joint"),
            "gradient": ("autograd", "finite_difference"),
            "init": ("best", "raw", "normalized"),
            "eigensolver": TopEigenvectors.SOLVERS,
        }
        for name, allowed in choices.items():
            if getattr(self, name) not in allowed:
                raise ValueError(f"SFPCA: {name} must be one of {allowed}; got {getattr(self, name)!r}")
        lo, hi = self.bounds
        if not 0 < lo <= 1 <= hi:
            raise ValueError(f"SFPCA: bounds must satisfy 0 < low <= 1 <= high; got {self.bounds}")
        if int(self.max_iter) < 0:
            raise ValueError(f"SFPCA: max_iter must be >= 0; got {self.max_iter}")
        if int(self.stop_window) < 0 or not float(self.stop_rtol) >= 0:
            raise ValueError(f"SFPCA: stop_window and stop_rtol must be >= 0; got {self.stop_window}, {self.stop_rtol}")

    def fit(self, X: FunctionalMotions, y=None) -> "SFPCA":
        self._check_fit_input(X)
        self._check_params()
        torch = _torch()
        start = time.perf_counter()
        fd = self.gradient == "finite_difference"
        objective = ObservationObjective(
            X,
            self.n_components,
            self.n_eval_frames,
            dtype=torch.float64 if fd else torch.float32,
            eigensolver=self.eigensolver,
        )
        groups = np.arange(X.layout.n_functions) if self.weight_groups == "function" else X.layout.function_groups()
        n_params = int(groups.max()) + 1
        raw = np.ones(X.layout.n_functions)
        # z-scoring per weight group: sigma_g^2 = mean variance of the group's functions
        group_var = np.bincount(groups, weights=functional_std(X) ** 2) / np.bincount(groups)
        normalized = zscore_weights(np.sqrt(group_var))[groups]
        self.loss_raw_ = objective.value(raw) if self.init != "normalized" else np.nan
        self.loss_normalized_ = objective.value(normalized) if self.init != "raw" else np.nan
        if self.init == "raw" or (self.init == "best" and self.loss_raw_ <= self.loss_normalized_):
            self.init_, w0 = "raw", raw
        else:
            self.init_, w0 = "normalized", normalized

        # only groups with a function that varies between clips have an effect (exact shortcut)
        free = np.unique(groups[objective.active_functions])

        def weights(u: np.ndarray) -> np.ndarray:
            scale = np.ones(n_params)
            scale[free] = u
            return w0 * scale[groups]

        if fd:

            def fun(u):
                return objective.value(weights(u))

            jac = None
        else:

            def fun(u):
                value, grad_w = objective.value_and_grad(weights(u))
                return value, np.bincount(groups, weights=grad_w * w0, minlength=n_params)[free]

            jac = True
        stall = StallTest(int(self.stop_window), float(self.stop_rtol))
        progress = ProgressLog(f"SFPCA ({len(free)} weights) L-BFGS-B iteration", int(self.max_iter), at_most=True)

        def callback(intermediate_result) -> None:
            progress(loss=float(intermediate_result.fun))
            if stall.window:
                stall(intermediate_result)

        result = minimize(
            fun,
            np.ones(len(free)),
            jac=jac,
            method="L-BFGS-B",
            bounds=[self.bounds] * len(free),
            callback=callback,
            options={"maxiter": int(self.max_iter), "ftol": float(self.tol)},
        )
        w = weights(result.x)
        self.loss_ = float(result.fun) if np.isfinite(result.fun) else objective.value(w)
        self.n_iter_ = int(result.nit)
        self.n_evals_ = int(result.nfev)
        self.converged_ = bool(result.success) or stall.stopped
        self.stop_ = "window" if stall.stopped else str(result.message)
        self._fit_weighted(X, w / np.exp(np.mean(np.log(w))))  # scale-free: geometric mean 1
        self.fit_time_s_ = time.perf_counter() - start
        return self
