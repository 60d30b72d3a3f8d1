"""Du 2022 ch. 3 scaled FPCA (Eq. 3.6-3.8): the top-eigenvector layer, the observation objective, normalised and weighted FPCA, and the fit."""

import math

import numpy as np
import pytest
import torch
from fda_toy import make_clips

from motionvar.du2022.fda import (
    FPCA,
    SFPCA,
    FunctionalMotions,
    NormalizedFPCA,
    ObservationObjective,
    RootScaledFPCA,
    TopEigenvectors,
    WeightedFPCA,
    functional_std,
    observation_error,
    scatter_is_cheaper,
)


@pytest.mark.parametrize("solver", TopEigenvectors.SOLVERS)
def test_top_eigenvectors_gradient(solver):
    rng = np.random.default_rng(2)
    X = torch.as_tensor(rng.normal(size=(6, 3)), dtype=torch.float64)  # rank 3: repeated zero eigenvalues
    Y = torch.as_tensor(rng.normal(size=(6, 4)), dtype=torch.float64)

    def loss(x):
        u = TopEigenvectors.apply(x @ x.T, 2, solver)
        return ((u @ (u.T @ Y)) ** 2).sum()

    x = X.clone().requires_grad_(True)
    (g,) = torch.autograd.grad(loss(x), x)
    assert torch.all(torch.isfinite(g))
    eps = 1e-6
    num = np.zeros(X.shape)
    for idx in np.ndindex(*X.shape):
        e = torch.zeros_like(X)
        e[idx] = eps
        num[idx] = (loss(X + e) - loss(X - e)).item() / (2 * eps)
    assert np.allclose(g.numpy(), num, atol=1e-6)


def test_top_eigenvectors_solvers_agree():
    """The tridiagonal solver (only the kept eigenvectors transformed back, the backward pass
    in the tridiagonal basis) gives torch.linalg.eigh's subspace and gradient, on a
    rank-deficient matrix (repeated zero eigenvalues) and when every eigenvector is kept."""
    rng = np.random.default_rng(3)
    X = rng.normal(size=(60, 25))
    for A, n in ((X @ X.T, 5), (X.T @ X, 25), (np.array([[2.0]]), 1)):
        G = torch.as_tensor(rng.normal(size=(A.shape[0], n)))
        out = {}
        for solver in TopEigenvectors.SOLVERS:
            a = torch.as_tensor(A).requires_grad_(True)
            u = TopEigenvectors.apply(a, n, solver)
            (g,) = torch.autograd.grad((u @ (u.T @ G)).sum(), a)
            out[solver] = (u @ u.T).detach().numpy(), g.numpy()
        (p0, g0), (p1, g1) = out["full"], out["tridiagonal"]
        assert np.abs(p1 - p0).max() < 1e-10
        assert np.abs(g1 - g0).max() <= 1e-9 * max(np.abs(g0).max(), 1e-300)
    with pytest.raises(ValueError, match="solver must be one of"):
        TopEigenvectors.apply(torch.eye(3, dtype=torch.float64), 1, "lanczos")


def test_observation_objective_routes_and_solvers_agree(data):
    """Eq. 3.8 from the Gram or the scatter matrix, with either eigensolver: the same value
    and gradient to 1e-9 (relative)."""
    fd, _, _ = data
    w = np.random.default_rng(4).uniform(0.5, 2.0, fd.layout.n_functions)
    results = []
    for solver in TopEigenvectors.SOLVERS:
        obj = ObservationObjective(fd, 3, dtype=torch.float64, eigensolver=solver)
        for scatter in (None, obj.centred.T @ obj.centred):
            obj.scatter = scatter
            results.append(obj.value_and_grad(w))
    v0, g0 = results[0]
    for v, g in results[1:]:
        assert math.isclose(v, v0, rel_tol=1e-9)
        assert np.abs(g - g0).max() <= 1e-9 * np.abs(g0).max()


def test_scatter_or_gram_by_cost():
    assert scatter_is_cheaper(1_458, 1_005) and scatter_is_cheaper(1_458, 1_545)
    assert not scatter_is_cheaper(100, 1_545)  # few clips: the small Gram matrix
    with pytest.raises(ValueError, match="eigensolver must be one of"):
        SFPCA(2, eigensolver="lanczos")._check_params()


def test_observation_objective_value_and_gradient(data):
    fd, _, _ = data
    obj = ObservationObjective(fd, 3, dtype=torch.float64)
    # at w = 1 the objective is the FPCA reconstruction's mean squared joint error
    coefs = FPCA(3).fit(fd).reconstruct(fd)
    ref = np.mean(np.sum((fd.positions() - fd.positions(coefs)) ** 2, -1))
    w = np.ones(fd.layout.n_functions)
    value, grad = obj.value_and_grad(w)
    assert math.isclose(value, ref, rel_tol=1e-8)
    for d in (0, 4, 9, 17):
        e = np.zeros_like(w)
        e[d] = 1e-5
        num = (obj.value(w + e) - obj.value(w - e)) / 2e-5
        assert math.isclose(grad[d], num, rel_tol=1e-4, abs_tol=1e-6)
    assert abs(obj.value(3.7 * w) - value) < 1e-8 * value  # invariant to a global scale


def test_observation_objective_scatter_path_and_constant_functions():
    """More clips than coefficients: the objective decomposes the scatter matrix instead of
    the Gram matrix; a function constant over all clips is left out and has no gradient."""
    clips, _ = make_clips(120, seed=5)
    fd = FunctionalMotions.from_motions(clips, n_basis=4)
    fd.coefs[:, :, 7] = 0.25  # one constant function
    obj = ObservationObjective(fd, 3, dtype=torch.float64)
    assert obj.scatter is not None and 7 not in obj.active_functions
    coefs = FPCA(3).fit(fd).reconstruct(fd)
    ref = np.mean(np.sum((fd.positions() - fd.positions(coefs)) ** 2, -1))
    value, grad = obj.value_and_grad(np.ones(fd.layout.n_functions))
    assert math.isclose(value, ref, rel_tol=1e-8) and grad[7] == 0.0
    model = SFPCA(3, max_iter=3).fit(fd)
    assert np.all(np.isfinite(model.function_weights_)) and model.loss_ <= model.loss_raw_ + 1e-9


def test_normalized_fpca_variants(data, tmp_path):
    """Normalized FPCA's SD floor scales functions that hardly move as if they moved that much
    (the z-score as written gives them up to 1 / their SD); root-scaled FPCA divides only the root
    translation by its largest absolute value, as the author's pipeline."""
    fd, _, _ = data
    sd = functional_std(fd)
    floor = float(np.quantile(sd[sd > 0], 0.5))
    written, floored = NormalizedFPCA(3).fit(fd), NormalizedFPCA(3, sd_floor=floor).fit(fd)
    np.testing.assert_allclose(floored.function_weights_, 1.0 / np.maximum(sd, floor))
    assert written.function_weights_.max() > floored.function_weights_.max() == pytest.approx(1.0 / floor)
    floored.save(tmp_path / "n")
    assert FPCA.load(tmp_path / "n").sd_floor == floor
    root = RootScaledFPCA(3).fit(fd)
    values = np.einsum("tk,nkd->ntd", fd.basis.design_frames(fd.n_frames), fd.coefs[:, :, :3])
    np.testing.assert_allclose(root.function_weights_[:3], 1.0 / np.abs(values).max(axis=(0, 1)))
    assert np.all(root.function_weights_[3:] == 1.0)


def test_nested_reconstruction_and_weighted_fpca(data):
    fd, _, _ = data
    big = FPCA(8).fit(fd)
    assert np.allclose(big.reconstruct(fd, 3), FPCA(3).fit(fd).reconstruct(fd), atol=1e-8)
    with pytest.raises(ValueError, match="n_components must be in"):
        big.reconstruct(fd, 9)
    s = SFPCA(3, max_iter=3).fit(fd)
    w = WeightedFPCA(6, s.function_weights_).fit(fd)
    assert np.allclose(w.reconstruct(fd, 3), s.reconstruct(fd), atol=1e-8)
    with pytest.raises(ValueError, match="positive finite"):
        WeightedFPCA(3, -s.function_weights_).fit(fd)
    with pytest.raises(ValueError, match="reference positions"):
        observation_error(fd, fd.coefs, reference=np.zeros((2, 3)))


def test_sfpca_improves_observation_error(data):
    fd, _, _ = data
    n = 3
    model = SFPCA(n, max_iter=10).fit(fd)
    assert model.init_ in ("raw", "normalized")
    assert model.loss_ <= min(model.loss_raw_, model.loss_normalized_) + 1e-9
    err = observation_error(fd, model.reconstruct(fd))
    assert err < observation_error(fd, FPCA(n).fit(fd).reconstruct(fd))
    assert err < observation_error(fd, NormalizedFPCA(n).fit(fd).reconstruct(fd))
    assert math.isclose(np.exp(np.mean(np.log(model.function_weights_))), 1.0)


def test_sfpca_finite_differences_and_joint_groups(data):
    fd, _, _ = data
    small = fd.subset(np.arange(20))
    fd_model = SFPCA(2, gradient="finite_difference", max_iter=2).fit(small)
    assert fd_model.loss_ <= min(fd_model.loss_raw_, fd_model.loss_normalized_) + 1e-9
    joint = SFPCA(2, weight_groups="joint", max_iter=5).fit(small)
    w = joint.function_weights_[3:].reshape(-1, 4)
    assert np.allclose(w, w[:, :1])  # one weight per joint quaternion


def test_stall_test_stops_only_after_a_flat_window():
    from motionvar.du2022.fda.sfpca import StallTest

    class Step:
        def __init__(self, fun):
            self.fun = fun

    stall = StallTest(window=3, rtol=1e-2)
    for f in (10.0, 9.0, 8.99, 8.98, 8.5, 8.49, 8.48):  # a pause, then a drop: not converged
        stall(Step(f))
    assert not stall.stopped
    with pytest.raises(StopIteration):
        stall(Step(8.47))  # 8.5 -> 8.47 over 3 iterations: 0.35 % <= 1 %
    assert stall.stopped


def test_sfpca_stall_window_stops_early_and_only_when_flat(data):
    fd, _, _ = data
    full = SFPCA(3, max_iter=30, tol=1e-12).fit(fd)
    early = SFPCA(3, max_iter=30, tol=1e-12, stop_window=3, stop_rtol=1e-2).fit(fd)
    assert early.stop_ == "window" and early.converged_ and early.n_iter_ < full.n_iter_
    assert early.loss_ <= full.loss_ * 1.05  # stopped on a plateau, near the longer run's optimum
    never = SFPCA(3, max_iter=30, tol=1e-12, stop_window=3, stop_rtol=0.0).fit(fd)
    assert never.n_iter_ == full.n_iter_ and never.loss_ == full.loss_  # rtol 0: only a rise stops it


def test_sfpca_bad_params(data):
    fd, _, _ = data
    with pytest.raises(ValueError, match="gradient must be one of"):
        SFPCA(2, gradient="adam").fit(fd)
    with pytest.raises(ValueError, match="bounds"):
        SFPCA(2, bounds=(2.0, 3.0)).fit(fd)
    with pytest.raises(ValueError, match="stop_window"):
        SFPCA(2, stop_window=-1).fit(fd)
