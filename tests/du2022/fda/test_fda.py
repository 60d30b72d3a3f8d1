"""Functional data analysis (Du 2022, ch. 3): B-splines, FPCA, normalised FPCA, SFPCA, GPLVM."""

import json
import math
import re

import matplotlib.pyplot as plt
import numpy as np
import pandas as pd
import pytest
import torch
from claim_checks import check_value_bound
from scipy.integrate import simpson

from motionvar.claims import judge_claims
from motionvar.core import Motion, Skeleton
from motionvar.core.quaternions import quat_about_axis
from motionvar.du2022.claims import CLAIMS
from motionvar.du2022.fda import (
    FPCA,
    SFPCA,
    BayesianGPLVM,
    BSplineBasis,
    FunctionalGPLVM,
    FunctionalMotions,
    NormalizedFPCA,
    ObservationObjective,
    RootScaledFPCA,
    TopEigenvectors,
    WeightedFPCA,
    align_quaternion_signs,
    bspline_fit_rmse,
    canonical_primitives,
    choose_basis_sizes,
    choose_n_basis,
    feature_error,
    functional_primitive,
    functional_std,
    knn_accuracy,
    latent_separation,
    n_basis_of,
    observation_error,
    scatter_is_cheaper,
)
from motionvar.du2022.fda.evaluations import (
    curves_table,
    evaluate_fig3_9,
    evaluate_fig3_10,
    evaluate_fig3_11,
    evaluate_table3_1,
    reconstruction_curves,
)
from motionvar.du2022.fda.evaluations.table3_1 import smallest_dim
from motionvar.du2022.fda.figures import draw_fig3_9, draw_fig3_10, draw_fig3_11, draw_table3_1
from motionvar.du2022.fda.settings import BasisSettings, FdaSettings


def chain_skeleton(n_joints=5, scale=1.0):
    """A small branching rig: root, spine, head, and two arms of one joint each."""
    names = tuple(f"j{i}" for i in range(n_joints))
    parents = np.array([-1, 0, 1, 1, 1][:n_joints])
    offsets = np.array([[0, 0, 0], [0, 20, 0], [0, 25, 0], [15, 20, 0], [-15, 20, 0]][:n_joints], float) * scale
    return Skeleton(names=names, parents=parents, offsets=offsets)


def make_clips(n=60, seed=0, n_joints=5, classes=3, lengths=(30, 45)):
    """Smooth clips whose joint angles depend on a class (pose offset) and random phases."""
    rng = np.random.default_rng(seed)
    axes = rng.normal(size=(n_joints, 3))
    clips, labels = [], []
    for i in range(n):
        c = i % classes
        T = int(rng.integers(*lengths))
        t = np.linspace(0, 1, T)
        phase = rng.uniform(0, 2 * np.pi)
        angles = 0.5 * np.sin(2 * np.pi * t[:, None] + phase + np.arange(n_joints)) * rng.uniform(0.5, 1.0)
        angles += 0.6 * c * (np.arange(n_joints) % 2)[None] + 0.05 * rng.normal(size=(1, n_joints))
        q = np.stack([quat_about_axis(axes[j], angles[:, j]) for j in range(n_joints)], axis=1)
        root = np.stack([t * rng.uniform(80, 120), 90 + 2 * np.sin(4 * np.pi * t), t * 10 * rng.normal()], -1)
        sk = chain_skeleton(n_joints, rng.uniform(0.9, 1.1))
        clips.append(Motion(skeleton=sk, root_pos=root, rotations=q, fps=120.0))
        labels.append(c)
    return clips, np.array(labels)


@pytest.fixture(scope="module")
def data():
    clips, labels = make_clips()
    return FunctionalMotions.from_motions(clips, n_basis=8), labels, clips


# ---- B-splines (Eq. 3.1) ------------------------------------------------------------


def test_bspline_fit_reproduces_splines_and_gram_is_exact():
    basis = BSplineBasis(7)
    rng = np.random.default_rng(0)
    coefs = rng.normal(size=(3, 7, 2))
    values = basis.evaluate(coefs, 40)
    assert np.allclose(basis.fit(values), coefs, atol=1e-10)
    t = np.linspace(0, 1, 20001)
    B = basis.design(t)
    dense = simpson(B[:, :, None] * B[:, None, :], x=t, axis=0)
    assert np.allclose(basis.gram(), dense, atol=1e-9)
    assert math.isclose(basis.gram().sum(), 1.0, abs_tol=1e-12)  # partition of unity
    root, iroot = basis.gram_sqrt()
    assert np.allclose(root @ root, basis.gram(), atol=1e-12) and np.allclose(root @ iroot, np.eye(7), atol=1e-9)


def test_bspline_bad_input():
    with pytest.raises(ValueError, match="n_basis"):
        BSplineBasis(3)
    with pytest.raises(ValueError, match="frames cannot determine"):
        BSplineBasis(10).fit(np.zeros((8, 2)))
    with pytest.raises(ValueError, match=r"\[0, 1\]"):
        BSplineBasis(5).design(np.array([0.5, 1.2]))


def test_choose_n_basis_cut_off_rule():
    ks = np.array([5, 10, 15, 20, 25])
    rmse = np.array([4.0, 1.0, 0.5, 0.48, 0.47])
    assert choose_n_basis(ks, rmse, 0.02) == 15  # 15 -> 20 drops 4 %, 0.8 % per added function
    assert choose_n_basis(ks, rmse, 0.12) == 10  # 10 -> 15 drops 50 %, 10 % per added function
    assert choose_n_basis(ks, rmse, 0.0) == 25
    assert choose_n_basis(np.array([5, 6]), np.array([1.0, 0.9]), 0.12) == 5  # 10 % for one function
    # a flat first step followed by a steep one is not the cut-off
    assert choose_n_basis(np.array([5, 6, 8, 10]), np.array([1.35, 1.32, 0.85, 0.84]), 0.05) == 8
    with pytest.raises(ValueError, match="ascending"):
        choose_n_basis(ks[::-1], rmse, 0.1)


def test_bspline_rmse_decreases_with_k(data):
    _, _, clips = data
    rmse = bspline_fit_rmse(clips, [4, 6, 10, 14])
    assert all(a > b for a, b in zip(rmse, rmse[1:]))
    assert bspline_fit_rmse(clips, 6) == pytest.approx(rmse[1])
    assert rmse[-1] < 0.1  # cm: smooth clips are represented almost exactly


# ---- motion parameterisation (Eq. 3.2, Sec. 3.2.1) -----------------------------------


def test_quaternion_signs_continuous_within_and_across_clips():
    rng = np.random.default_rng(1)
    T, J = 20, 3
    base = quat_about_axis([0, 1, 0], np.linspace(0, 1, T))[:, None].repeat(J, 1)
    clips = []
    for _ in range(4):
        flips = np.where(rng.random((T, J, 1)) < 0.4, -1.0, 1.0)
        clips.append(base * flips)
    fixed = align_quaternion_signs(clips)
    for q in fixed:
        assert np.allclose(q, fixed[0])
        assert np.all(np.sum(q[1:] * q[:-1], -1) > 0)


def test_functional_motions_positions_and_motions(data):
    fd, _, clips = data
    assert fd.coefs.shape == (60, 8, 3 + 4 * 5)
    pos = fd.positions()
    assert pos.shape == (60, fd.n_frames, 5, 3)
    # the first clip's functional positions at its own frames match its frames closely
    first = fd.subset(np.array([0])).positions(n_frames=clips[0].n_frames)[0]
    assert np.max(np.abs(first - clips[0].positions())) < 0.5
    motions = fd.to_motions(clips[0].skeleton, fps=120.0)
    assert len(motions) == 60 and motions[0].n_frames == fd.n_frames
    assert np.allclose(np.linalg.norm(motions[3].rotations, axis=-1), 1.0)


def test_functional_motions_bad_input():
    clips, _ = make_clips(4)
    with pytest.raises(ValueError, match="clip 1 has 5 frames"):
        FunctionalMotions.from_motions([clips[0], clips[1].slice(0, 5)], n_basis=8)
    other = Motion(
        skeleton=chain_skeleton(4), root_pos=np.zeros((30, 3)), rotations=np.tile([1.0, 0, 0, 0], (30, 4, 1)), fps=120
    )
    with pytest.raises(ValueError, match="clip 1 has another skeleton topology"):
        FunctionalMotions.from_motions([clips[0], other], n_basis=8)
    bad = clips[2].copy()
    bad.root_pos[3, 0] = np.nan
    with pytest.raises(ValueError, match="clip 1 has non-finite"):
        FunctionalMotions.from_motions([clips[0], bad], n_basis=8)
    with pytest.raises(ValueError, match="no clips"):
        FunctionalMotions.from_motions([], n_basis=8)


# ---- FPCA (Eq. 3.3-3.5) ----------------------------------------------------------------


def reference_explained_variance_ratio(fd, n, points_per_span=40):
    """Independent FPCA: PCA of densely sampled curves with Simpson quadrature weights."""
    breaks = np.unique(fd.basis.knots)
    t = np.unique(np.concatenate([np.linspace(a, b, points_per_span + 1) for a, b in zip(breaks[:-1], breaks[1:])]))
    h = np.diff(breaks)[0] / points_per_span
    w = np.ones_like(t)
    w[1:-1:2], w[2:-1:2] = 4, 2
    w *= h / 3
    curves = np.einsum("tk,nkd->ntd", fd.basis.design(t), fd.coefs)
    x = (curves * np.sqrt(w)[None, :, None]).reshape(fd.n_clips, -1)
    x -= x.mean(0)
    s = np.linalg.svd(x, compute_uv=False) ** 2
    return s[:n] / s.sum()


def test_fpca_matches_dense_quadrature_reference(data):
    fd, _, _ = data
    model = FPCA(10).fit(fd)
    assert np.allclose(model.explained_variance_ratio_, reference_explained_variance_ratio(fd, 10), atol=1e-6)


def test_fpca_eigenfunctions_orthonormal_and_full_rank_round_trip(data):
    fd, _, _ = data
    model = FPCA(6).fit(fd)
    G = fd.basis.gram()
    inner = np.einsum("ikd,kl,jld->ij", model.eigenfunctions_, G, model.eigenfunctions_)  # Eq. 3.5
    assert np.allclose(inner, np.eye(6), atol=1e-10)
    full = FPCA(59).fit(fd)  # N - 1 components span the centred data
    assert np.allclose(full.reconstruct(fd), fd.coefs, atol=1e-8)
    z = full.transform(fd)
    assert np.allclose(full.transform(full.inverse_transform(z)), z, atol=1e-8)


def test_fpca_is_optimal_in_feature_space(data):
    """Eq. 3.3: FPCA minimises the mean squared functional error; scaled variants cannot beat it."""
    fd, _, _ = data
    G = fd.basis.gram()

    def mse(c):
        d = fd.coefs - c
        return np.einsum("nkd,kl,nld->", d, G, d) / fd.n_clips

    for n in (1, 3, 6):
        assert mse(FPCA(n).fit(fd).reconstruct(fd)) <= mse(NormalizedFPCA(n).fit(fd).reconstruct(fd)) + 1e-12


def test_normalized_fpca_weights(data):
    fd, _, _ = data
    std = functional_std(fd)
    model = NormalizedFPCA(3).fit(fd)
    assert np.allclose(model.function_weights_, 1.0 / std)
    # a constant function (zero variance) keeps weight 1 instead of dividing by zero
    const = fd.with_coefs(fd.coefs.copy())
    const.coefs[:, :, 5] = 0.3
    w = NormalizedFPCA(3).fit(const).function_weights_
    assert w[5] == 1.0 and np.all(np.isfinite(w))


def test_fpca_bad_input(data):
    fd, _, _ = data
    with pytest.raises(ValueError, match="n_components must be an integer in"):
        FPCA(61).fit(fd)
    with pytest.raises(RuntimeError, match="not fitted"):
        FPCA(3).transform(fd)
    with pytest.raises(TypeError, match="FunctionalMotions"):
        FPCA(3).fit(np.zeros((5, 8, 23)))
    model = FPCA(3).fit(fd)
    with pytest.raises(ValueError, match="expected coefficients"):
        model.transform(np.zeros((5, 7, 23)))


def test_save_load_round_trip(tmp_path, data):
    """Models are saved as .npz arrays + .json settings (motionvar.io.model_file)."""
    fd, _, clips = data
    for model in (FPCA(4).fit(fd), SFPCA(4, max_iter=3).fit(fd)):
        path = tmp_path / f"{type(model).__name__}.npz"
        files = model.save(path)
        assert sorted(f.name for f in files) == sorted([path.name, path.with_suffix(".json").name])
        settings = json.loads(path.with_suffix(".json").read_text())
        assert settings["class_name"] == type(model).__name__ and settings["n_basis"] == 8
        back = FPCA.load(path.with_suffix(""))
        assert type(back) is type(model)
        assert np.allclose(back.transform(fd), model.transform(fd))
        assert np.allclose(back.inverse_transform(model.transform(fd)), model.reconstruct(fd))
        motions = back.to_motions(model.transform(fd)[:2], fps=120.0, skeleton=clips[0].skeleton)
        assert len(motions) == 2 and motions[0].n_frames == fd.n_frames
    assert back.init_ == model.init_ and back.n_iter_ == model.n_iter_ and back.loss_ == model.loss_
    (tmp_path / "bad.npz").write_bytes(b"not a zip")
    (tmp_path / "bad.json").write_text(json.dumps({"kind": "du2022.fpca", "class_name": "FPCA"}))
    with pytest.raises(ValueError, match="bad.npz"):
        FPCA.load(tmp_path / "bad.npz")
    with pytest.raises(FileNotFoundError, match="missing.npz: model file missing"):
        FPCA.load(tmp_path / "missing.npz")


# ---- SFPCA (Eq. 3.6-3.8) ------------------------------------------------------------


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


# ---- Bayesian GPLVM -------------------------------------------------------------------


def test_gplvm_bound_matches_exact_gp_marginal_likelihood():
    """With q(X) collapsed to points and Z = X, the Titsias bound equals the exact GP
    log marginal likelihood minus the KL term."""
    rng = np.random.default_rng(3)
    N, Q, D = 12, 2, 3
    X = rng.normal(size=(N, Q))
    Y = rng.normal(size=(N, D))
    model = BayesianGPLVM(Q, n_inducing=N, jitter=1e-9)
    S = np.full((N, Q), 1e-12)
    p = {
        "mu": torch.as_tensor(X),
        "log_S": torch.as_tensor(np.log(S)),
        "Z": torch.as_tensor(X),
        "log_sf2": torch.tensor([0.3], dtype=torch.float64),
        "log_ell": torch.tensor([0.1, -0.2], dtype=torch.float64),
        "log_noise": torch.tensor([math.log(0.2)], dtype=torch.float64),
    }
    bound, _ = model._bound(p, torch.as_tensor(Y), float(np.sum(Y**2)), None)
    kl = 0.5 * np.sum(S + X**2 - 1 - np.log(S))
    sf2, ell = math.exp(0.3), np.exp([0.1, -0.2])
    d = (X[:, None] - X[None]) / ell
    C = sf2 * np.exp(-0.5 * np.sum(d**2, -1)) + 0.2 * np.eye(N)
    _, logdet = np.linalg.slogdet(C)
    exact = -0.5 * (D * N * math.log(2 * math.pi) + D * logdet + np.trace(Y.T @ np.linalg.solve(C, Y)))
    assert math.isclose(float(bound) + kl, exact, rel_tol=1e-5)


def test_gplvm_pca_init_matches_sklearn_and_shares_one_svd(monkeypatch):
    """The PCA initialisation is sklearn's PCA(Q, svd_solver="full") for every Q, and fits of
    the same data at several latent dimensions (Fig. 3.10's d = 1..40) make one SVD; the fit
    is the same whether the SVD was cached or not."""
    from sklearn.decomposition import PCA

    from motionvar.models import bayesian_gplvm as bg

    rng = np.random.default_rng(5)
    Y = rng.normal(size=(40, 6)) @ rng.normal(size=(6, 30)) + 0.1 * rng.normal(size=(40, 30))
    for q in (1, 4, 30):
        pca = PCA(q, svd_solver="full").fit(Y)
        X, ratio = bg.pca_scores(Y, q)
        np.testing.assert_allclose(X, pca.transform(Y), rtol=0, atol=1e-12)
        np.testing.assert_allclose(ratio, pca.explained_variance_ratio_, rtol=1e-12)
    fits = []
    real_fit = PCA.fit
    monkeypatch.setattr(PCA, "fit", lambda self, *a, **k: fits.append(1) or real_fit(self, *a, **k))
    bg._PCA_CACHE.clear()
    models = [BayesianGPLVM(q, n_inducing=6, max_iter=5).fit(Y) for q in (2, 3, 2)]
    assert len(fits) == 1
    assert np.array_equal(models[0].latent_mean_, models[2].latent_mean_)
    bg._PCA_CACHE.clear()
    fresh = BayesianGPLVM(3, n_inducing=6, max_iter=5).fit(Y)
    assert len(fits) == 2 and fresh.bound_ == models[1].bound_
    assert np.array_equal(fresh.latent_mean_, models[1].latent_mean_)


def test_functional_gplvm_reconstructs(data):
    fd, labels, _ = data
    g = FunctionalGPLVM(4, n_inducing=15, max_iter=60).fit(fd)
    z = g.transform(fd)
    assert z.shape == (60, 4)
    err = feature_error(fd, g.reconstruct(fd))
    mean_only = feature_error(fd, np.broadcast_to(fd.coefs.mean(0), fd.coefs.shape))
    assert err < mean_only
    with pytest.raises(NotImplementedError):
        g.transform(fd.subset(np.arange(5)))
    with pytest.raises(ValueError, match="one label per row"):
        BayesianGPLVM(2, discriminative_sigma2=1.0).fit(np.zeros((10, 4)) + np.arange(4))
    dp = FunctionalGPLVM(3, n_inducing=10, max_iter=20, discriminative_sigma2=1.0).fit(fd, labels)
    assert np.all(np.isfinite(dp.transform(fd)))


# ---- latent-space measures (Fig. 3.11) --------------------------------------------------


def test_knn_accuracy_and_separation():
    rng = np.random.default_rng(4)
    labels = np.repeat([0, 1, 2], 20)
    apart = rng.normal(size=(60, 3)) * 0.1 + np.eye(3)[labels] * 5
    assert knn_accuracy(apart, labels) == 1.0
    sep = latent_separation(apart, labels)
    assert sep["silhouette"] > 0.9
    mixed = rng.normal(size=(60, 3))
    assert latent_separation(mixed, labels)["silhouette"] < 0.2
    with pytest.raises(ValueError, match="two distinct labels"):
        latent_separation(apart, np.zeros(60))


# ---- the primitives of a dataset and the evaluations (Fig. 3.9-3.11, Table 3.1) --------


class StandInDataset:
    """What the evaluations use of motionvar.io.MotionDataset: ``metadata`` and ``motion(i)``."""

    def __init__(self, motions, metadata):
        self.motions, self.metadata = list(motions), metadata.reset_index(drop=True)

    def motion(self, i):
        return self.motions[i]


@pytest.fixture(scope="module")
def prep_dataset():
    """Two primitives of two behaviours (with generator-style labels) and one too small."""
    clips, labels = make_clips(40, seed=7, lengths=(28, 40))
    variants = np.array(["forward", "left", "right"])[labels]
    primitive = np.array(["walk_leftStance"] * 24 + ["pick_reach"] * 14 + ["pick_retrieve"] * 2)
    meta = pd.DataFrame(
        {
            "clip_id": [f"c{i:02d}" for i in range(40)],
            "behaviour": [p.split("_")[0] for p in primitive],
            "primitive": primitive,
            "variant": variants,
            "n_frames": [c.n_frames for c in clips],
            "fps": 120.0,
        }
    )
    return StandInDataset(clips, meta)


@pytest.fixture(scope="module")
def canonical_dataset(prep_dataset):
    motions, meta = canonical_primitives(prep_dataset, ["walk", "pick"], min_clips=3, time_warping="dtw")
    return StandInDataset(motions, meta)


def test_canonical_primitives(prep_dataset, canonical_dataset):
    meta = canonical_dataset.metadata
    assert sorted(meta["primitive"].unique()) == ["pick_reach", "walk_leftStance"]  # pick_retrieve: 2 < 3 clips
    for primitive, g in meta.groupby("primitive"):
        lengths = {canonical_dataset.motion(i).n_frames for i in g.index}
        ref = prep_dataset.metadata.set_index("clip_id").loc[g["canonical_reference"].iloc[0]]
        assert lengths == {ref["n_frames"]} and g["canonical_reference"].nunique() == 1
    assert "source_frames" in meta and "n_frames" not in meta
    linear, _ = canonical_primitives(prep_dataset, ["pick"], min_clips=3, time_warping="linear")
    assert len(linear) == 14 and len({m.n_frames for m in linear}) == 1
    with_absent, _ = canonical_primitives(prep_dataset, ["pick", "jump"], 3, "linear")  # jump: not in the data
    assert len(with_absent) == len(linear)
    with pytest.raises(ValueError, match="du2022_fda.behaviours: none of \\['jump'\\] in the prep data"):
        canonical_primitives(prep_dataset, ["jump"], 3, "dtw")
    with pytest.raises(ValueError, match="no primitive has du2022_fda.min_clips"):
        canonical_primitives(prep_dataset, ["pick"], 50, "dtw")


def test_basis_sizes_and_fig3_9(canonical_dataset):
    rmse, chosen = choose_basis_sizes(canonical_dataset, BasisSettings(n_basis=(4, 6, 8, 10)))
    assert list(chosen["primitive"]) == ["pick_reach", "walk_leftStance"]
    assert len(rmse) == 8 and rmse.groupby("primitive")["chosen"].sum().tolist() == [1, 1]
    assert n_basis_of(chosen, "pick_reach") == int(chosen["n_basis"].iloc[0])
    with pytest.raises(ValueError, match="n_basis.csv: no basis size for primitive 'run'"):
        n_basis_of(chosen, "run", "n_basis.csv")
    with pytest.raises(ValueError, match="every K exceeds"):
        choose_basis_sizes(canonical_dataset, BasisSettings(n_basis=(500,)))

    result = evaluate_fig3_9(rmse, FdaSettings())
    table = result.table
    assert len(table) == 8 + 8 and set(table.loc[table["primitive"] == "(all)", "behaviour"]) == {"pick", "walk"}
    # pooled RMSE of a behaviour with one primitive is that primitive's RMSE
    pooled = table[(table["primitive"] == "(all)") & (table["behaviour"] == "pick")]["rmse_cm"].to_numpy()
    assert np.allclose(pooled, rmse[rmse["primitive"] == "pick_reach"]["rmse_cm"])
    claim, more = result.claims
    assert claim.claim_id == "du2022.fig3_9.rmse_decreases_with_k" and claim.verdict == "reproduced"
    assert "2/2 behaviours strictly decreasing" in claim.measured
    assert (claim.value, claim.bound, claim.unit, claim.direction) == (1.0, 1.0, "share", ">=")
    # complex motions need more basis functions at equal error (the default rule): the first K
    # within each RMSE, flagged in the table, compared for every RMSE walk_leftStance reaches
    assert more.claim_id == "du2022.fig3_9.complex_motions_need_more_basis"
    rows = table[table["primitive"] != "(all)"]
    targets = FdaSettings().basis.equal_error_cm
    first = {
        (p, t): int(g.loc[g[f"first_within_{t:g}_cm"], "n_basis"].iloc[0])
        if g[f"first_within_{t:g}_cm"].any()
        else None
        for p, g in rows.groupby("primitive")
        for t in targets
    }
    assert all(rows.groupby("primitive")[f"first_within_{t:g}_cm"].sum().max() <= 1 for t in targets)
    compared = [t for t in targets if first["walk_leftStance", t] is not None]
    more_k = [first["pick_reach", t] is None or first["pick_reach", t] > first["walk_leftStance", t] for t in compared]
    if compared:
        assert more.value == pytest.approx(sum(more_k) / len(compared)), more.measured
    else:
        assert more.verdict == "not testable"
    # the cut-off rule: pick_reach's chosen K against walk_leftStance's
    k = dict(zip(chosen["primitive"], chosen["n_basis"]))
    cutoff = evaluate_fig3_9(rmse, FdaSettings.from_dict({"basis": {"claim_rule": "relative_drop"}})).claims[1]
    assert cutoff.measured.startswith(f"pick_reach K {k['pick_reach']} vs walk_leftStance K {k['walk_leftStance']}")
    if k["pick_reach"] == k["walk_leftStance"] == 10:  # both at the largest candidate
        assert cutoff.verdict == "not testable" and "largest candidate K" in cutoff.note
    else:
        assert cutoff.verdict == ("reproduced" if k["pick_reach"] > k["walk_leftStance"] else "not reproduced")
        assert cutoff.value == k["pick_reach"] - k["walk_leftStance"]
    for c in (*result.claims, cutoff):
        check_value_bound(c)
    no_pick = evaluate_fig3_9(rmse[rmse["primitive"] != "pick_reach"], FdaSettings())
    assert no_pick.claims[1].verdict == "not applicable" and "'pick_reach'" in no_pick.claims[1].note
    fig = draw_fig3_9(result)
    assert len(fig.axes) == 2
    plt.close(fig)


@pytest.fixture(scope="module")
def fda_curves(canonical_dataset):
    """The Fig. 3.10-3.11 measurements of both primitives, in three parts each as the pipeline."""
    settings = FdaSettings.from_dict(
        {
            "seed": 0,
            "reconstruction": {"dims": [1, 3, 100]},
            "latent": {"n_components": 3},
            "sfpca": {"max_iter": 3, "eval_frames_per_basis": 2},
            "gplvm": {"n_inducing": 6, "max_iter": 8, "noise_init": 0.01, "discriminative_sigma2": 1.0},
        }
    )
    out = []
    for primitive in ("walk_leftStance", "pick_reach"):
        fd, meta = functional_primitive(canonical_dataset, primitive, 6)
        for methods in (
            ["fpca", "normalized_fpca", "sfpca"],
            ["gplvm"],
            ["normalized_fpca_floored", "root_scaled_fpca"],
        ):
            out.append(reconstruction_curves(fd, meta["variant"], primitive, methods, settings))
    return out


def test_reconstruction_curves(fda_curves):
    z = fda_curves[0]
    assert str(z["primitive"]) == "walk_leftStance" and list(z["methods"]) == ["fpca", "normalized_fpca", "sfpca"]
    assert list(z["dims"]) == [1, 3] and int(z["latent_dim"]) == 3  # d = 100 > clips - 1 dropped
    assert z["labels"].dtype.kind == "U" and len(z["labels"]) == 24 == int(z["n_clips"])
    for method in z["methods"]:
        assert z[f"{method}/feature_error"].shape == (2,) and z[f"{method}/latent"].shape == (24, 3)
    assert np.all(np.diff(z["fpca/feature_error"]) < 0)
    assert str(fda_curves[4]["gplvm/info"][0]).split()[1] == "it,"
    table = curves_table(fda_curves)
    assert len(table) == 2 * 6 * 2 and set(table["method"]) == {
        "fpca",
        "normalized_fpca",
        "sfpca",
        "gplvm",
        "normalized_fpca_floored",
        "root_scaled_fpca",
    }
    fd = FunctionalMotions.from_motions(make_clips(4)[0], n_basis=6)
    with pytest.raises(ValueError, match="dims: none <= 3"):
        tiny = FdaSettings.from_dict({"reconstruction": {"dims": [5]}, "latent": {"n_components": 2}})
        reconstruction_curves(fd, ["a"] * 4, "tiny", ["fpca"], tiny)


def test_fig3_10(fda_curves):
    result = evaluate_fig3_10(fda_curves, FdaSettings())
    assert len(result.table) == 24 and "fit_seconds" in result.table  # 2 primitives x 6 methods x 2 dims
    # normalized FPCA is the variant of du2022_fda.reconstruction.normalized_variant; every variant is drawn
    assert result.figure["methods"][-2:] == ["normalized_fpca_floored", "root_scaled_fpca"]
    assert "z-score with the SD floored" in result.claims[2].note
    shares = [b / n for b, n in result.measurements["normalized_variants"].values()]
    assert ("so the miss is not the normalisation's reading" in result.claims[2].note) == (
        result.claims[2].verdict != "reproduced" and max(shares) < 0.5 + 1e-9
    )
    assert set(result.measurements["normalized_variants"]) == {
        "normalized_fpca",
        "normalized_fpca_floored",
        "root_scaled_fpca",
    }
    as_written = evaluate_fig3_10(
        fda_curves, FdaSettings.from_dict({"reconstruction": {"normalized_variant": "zscore"}})
    )
    below = as_written.measurements["normalized_variants"]["normalized_fpca"][0]
    assert as_written.claims[2].measured.startswith(
        f"pick_reach: normalized FPCA (z-score as written) < FPCA at {below}/"
    )
    ids = [c.claim_id.split(".")[-1] for c in result.claims]
    assert ids == [
        "fpca_lowest_feature_error",
        "sfpca_lowest_observation_error",
        "normalized_fpca_beats_fpca_observation_pick",
        "fpca_errors_decrease_with_dims",
        "sfpca_errors_decrease_with_dims",
    ]
    first = result.claims[0]  # FPCA minimises the feature-space error (Eq. 3.3)
    assert first.verdict == "reproduced" and first.measured.startswith("FPCA lowest in 4/4")
    assert re.match(r"\d+/8 curves monotone", result.claims[3].measured)  # 2 primitives x 2 FPCAs x 2 spaces
    assert re.match(r"\d+/4 curves monotone", result.claims[4].measured)  # 2 primitives x SFPCA x 2 spaces
    assert first.value == 1.0 and result.claims[4].value == int(result.claims[4].measured.split("/")[0]) / 4
    assert result.claims[1].bound == pytest.approx(0.5)  # "most": more than half of the cases
    for c in result.claims:
        check_value_bound(c)
    walk_only = FdaSettings.from_dict({"reconstruction": {"primitives": ["walk_leftStance"]}})
    no_pick = evaluate_fig3_10(fda_curves[:3], walk_only)  # the normalized-FPCA claim is about picking
    assert [c.verdict == "not applicable" for c in no_pick.claims] == [False, False, True, False, False]
    assert "'pick_reach' is not among the reconstructed primitives" in no_pick.claims[2].note
    for c in no_pick.claims:
        check_value_bound(c)
    fig = draw_fig3_10(result)
    assert len(fig.axes) == 4
    plt.close(fig)


def _fig3_10_claims(sfpca_lowest: dict[str, list[bool]], nfpca_below: list[bool]) -> dict:
    """The Fig. 3.10 claims judged on errors where SFPCA is (True) or is not lowest of all four at each
    dimension of each primitive, and normalized FPCA below FPCA (True) at each dimension of pick_reach."""
    from motionvar.du2022.fda.evaluations.fig3_10 import fig3_10_measurements

    rows = []
    for primitive, lowest in sfpca_lowest.items():
        for d, low in enumerate(lowest, start=1):
            below = primitive == "pick_reach" and nfpca_below[d - 1]
            errors = {"fpca": 2.0, "normalized_fpca": 1.9 if below else 2.1, "gplvm": 1.5, "sfpca": 1.0 if low else 1.8}
            rows += [
                {
                    "primitive": primitive,
                    "method": k,
                    "dims": d,
                    "feature_error": 1.0 / d,
                    "observation_error_cm": v / d,
                }
                for k, v in errors.items()
            ]
    m = fig3_10_measurements(pd.DataFrame(rows), "pick_reach", "normalized_fpca")
    return {c.claim_id.split(".")[-1]: c for c in judge_claims(CLAIMS, "du2022_fig3_10", m)}


def test_fig3_10_partial_verdicts():
    """SFPCA lowest: more than half of all cases, partial at more than half of one primitive's
    dimensions; normalized FPCA below FPCA for picking: more than half, partial at half."""
    t, f = True, False
    cases = [
        ({"pick_reach": [t, t, t, f], "walk_leftStance": [f, t, t, f]}, "reproduced"),  # 5/8
        ({"pick_reach": [t, t, t, f], "walk_leftStance": [f, f, t, f]}, "partial"),  # 4/8, pick 3/4
        ({"pick_reach": [t, t, f, f], "walk_leftStance": [f, f, t, t]}, "not reproduced"),  # 4/8, 2/4 each
    ]
    for lowest, verdict in cases:
        claim = _fig3_10_claims(lowest, [t, t, t, t])["sfpca_lowest_observation_error"]
        assert claim.verdict == verdict, (lowest, claim.measured)
        check_value_bound(claim)
    both = {"pick_reach": [t] * 4, "walk_leftStance": [t] * 4}
    for below, verdict in (([t, t, t, f], "reproduced"), ([t, f, t, f], "partial"), ([t, f, f, f], "not reproduced")):
        claim = _fig3_10_claims(both, below)["normalized_fpca_beats_fpca_observation_pick"]
        assert claim.verdict == verdict, (below, claim.measured)
        check_value_bound(claim)


def test_fig3_11(fda_curves):
    result = evaluate_fig3_11(fda_curves, FdaSettings.from_dict({"latent": {"knn": 3, "tsne_perplexity": 30.0}}))
    table = result.table
    assert list(table.columns) == ["primitive", "method", "latent_dim", "n_clips", "silhouette", "knn3_accuracy"]
    assert len(table) == 8 and table["latent_dim"].eq(3).all()
    for z in fda_curves:  # the measures of the table are those of the latent coordinates
        for method in [m for m in z["methods"] if m in set(table["method"])]:  # the four methods of Fig. 3.11
            row = table[(table["primitive"] == str(z["primitive"])) & (table["method"] == method)].iloc[0]
            sep = latent_separation(z[f"{method}/latent"], z["labels"], 3)
            assert row["silhouette"] == sep["silhouette"] and row["knn3_accuracy"] == sep["knn_accuracy"]
    (claim,) = result.claims
    assert claim.claim_id == "du2022.fig3_11.sfpca_best_separation_pick" and "3-NN accuracy" in claim.measured
    assert claim.value in (0.0, 0.5, 1.0) and claim.unit == "share"
    check_value_bound(claim)
    panels = result.figure["panels"]
    assert len(panels) == 2 and panels[1][0]["xy"].shape == (14, 2)
    fig = draw_fig3_11(result)
    assert len(fig.axes) == 8
    plt.close(fig)


def test_smallest_dim_bisection():
    calls = []

    def error(d):
        calls.append(d)
        return 10.0 / d

    d, seen = smallest_dim(error, 40, 1.0)
    assert d == 10 and seen[10] == 1.0 and seen[9] > 1.0 and len(calls) == len(set(calls)) < 10
    assert smallest_dim(error, 5, 1.0)[0] is None


def test_table3_1(canonical_dataset):
    _, chosen = choose_basis_sizes(canonical_dataset, BasisSettings(n_basis=(4, 6)))
    settings = FdaSettings.from_dict(
        {
            "sfpca": {"max_iter": 3},
            "table": {"reference_components": 3, "max_components": 50, "observation_error_cm": 1.0},
        }
    )
    result = evaluate_table3_1(canonical_dataset, chosen, settings)
    table = result.table.set_index("primitive")
    assert list(table.index) == ["pick_reach", "walk_leftStance"] and result.claims == []
    assert table.loc["pick_reach", "clips"] == 14 and table.loc["pick_reach", "published_dims"] == 45
    assert table.loc["walk_leftStance", "sfpca_reference_dims"] == 3
    for primitive, row in table.iterrows():
        for name in ("sfpca", "fpca"):
            d = row[f"latent_dims_{name}"]
            assert 1 <= d <= row["clips"] - 1 and row[f"error_at_dims_{name}_cm"] <= 1.0
            curve = dict(result.figure["curves"][(primitive, name)])
            assert curve[int(d)] == row[f"error_at_dims_{name}_cm"] and (d == 1 or curve.get(int(d) - 1, 2.0) > 1.0)
    fig = draw_table3_1(result)
    assert len(fig.axes) == 2
    plt.close(fig)
