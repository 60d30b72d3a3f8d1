"""Du 2022 ch. 3 B-splines (Eq. 3.1), the functional motion parameterisation (Eq. 3.2, Sec. 3.2.1) and FPCA (Eq. 3.3-3.5)."""

import json
import math

import numpy as np
import pytest
from fda_toy import chain_skeleton, make_clips
from scipy.integrate import simpson

from motionvar.core import Motion
from motionvar.core.quaternions import quat_about_axis
from motionvar.du2022.fda import (
    FPCA,
    SFPCA,
    BSplineBasis,
    FunctionalMotions,
    NormalizedFPCA,
    align_quaternion_signs,
    bspline_fit_rmse,
    choose_n_basis,
    functional_std,
)


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
