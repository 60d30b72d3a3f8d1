"""FPCA (motionvar.du2022.fda.FPCA) against scikit-fda's FPCA on the same B-spline functional
data: eigenfunction coefficients (up to sign), scores, explained variances and the mean.

scikit-fda computes the Gram matrix of its vector-valued B-spline basis with its own
quadrature and solves the eigenproblem of the Gram-weighted coefficients itself, so this is an
independent computation of the same Eq. 3.3-3.5. Tolerance: 1e-9 times the largest magnitude
(measured: ~5e-14 relative). scikit-fda 0.10.1 needs ``multimethod<2`` (the ``crosscheck``
extra pins both).

scikit-fda hands the weighted coefficients to scikit-learn's ``PCA`` with its default solver,
which is randomized once the matrix has more than 500 columns (K x D = 1270 for a 31-joint rig
with 10 B-splines): its components are then approximate (explained variances off by up to
~5e-3 relative at 60 clips x 1270 columns). At that size the check runs scikit-fda with the
full SVD (its ``PCA`` patched to ``svd_solver="full"``) and also holds ours against an exact
SVD built on scikit-fda's own Gram matrix (a third computation)."""

from functools import partial

import numpy as np
import pytest
from sklearn.decomposition import PCA

from motionvar.core import Motion, Skeleton, cmu_skeleton
from motionvar.core.quaternions import quat_about_axis
from motionvar.du2022.fda import FPCA, FunctionalMotions, FunctionLayout
from motionvar.du2022.fda.bspline import BSplineBasis

pytest.importorskip("skfda", reason="scikit-fda is not installed (pip install -e '.[crosscheck]')")
from skfda.preprocessing.dim_reduction import FPCA as SkFPCA  # noqa: E402
from skfda.preprocessing.dim_reduction import _fpca as skfda_fpca_module  # noqa: E402
from skfda.representation.basis import BSplineBasis as SkBSpline  # noqa: E402
from skfda.representation.basis import FDataBasis, VectorValuedBasis  # noqa: E402

RTOL = 1e-9


def smooth_clips(n=60, n_joints=5, seed=0):
    """Clips of a small rig whose joint angles are class offsets plus random-phase sines."""
    rng = np.random.default_rng(seed)
    names = tuple(f"j{i}" for i in range(n_joints))
    parents = np.array([-1, 0, 1, 1, 1][:n_joints])
    offsets = np.array([[0, 0, 0], [0, 20, 0], [0, 25, 0], [15, 20, 0], [-15, 20, 0]][:n_joints], float)
    axes = rng.normal(size=(n_joints, 3))
    clips = []
    for i in range(n):
        T = int(rng.integers(30, 45))
        t = np.linspace(0, 1, T)
        angles = 0.5 * np.sin(2 * np.pi * t[:, None] + rng.uniform(0, 2 * np.pi) + np.arange(n_joints))
        angles += 0.6 * (i % 3) * (np.arange(n_joints) % 2)[None]
        q = np.stack([quat_about_axis(axes[j], angles[:, j]) for j in range(n_joints)], axis=1)
        root = np.stack([t * rng.uniform(80, 120), 90 + 2 * np.sin(4 * np.pi * t), t * 10 * rng.normal()], -1)
        sk = Skeleton(names=names, parents=parents, offsets=offsets * rng.uniform(0.9, 1.1))
        clips.append(Motion(skeleton=sk, root_pos=root, rotations=q, fps=120.0))
    return clips


def skfda_data(fd):
    """The same coefficients as scikit-fda functional data: one cubic B-spline basis with
    the same clamped, equally spaced knots on [0, 1] per function; coefficients function-major."""
    N, K, D = fd.coefs.shape
    basis = VectorValuedBasis([SkBSpline(domain_range=(0, 1), n_basis=K, order=fd.basis.degree + 1)] * D)
    return FDataBasis(basis, fd.coefs.transpose(0, 2, 1).reshape(N, D * K))


@pytest.fixture(scope="module")
def fitted():
    fd = FunctionalMotions.from_motions(smooth_clips(), n_basis=8)
    ours = FPCA(8).fit(fd)
    X = skfda_data(fd)
    theirs = SkFPCA(n_components=8).fit(X)
    return fd, ours, X, theirs


def close(a, b, rtol=RTOL):
    a, b = np.asarray(a, float), np.asarray(b, float)
    return np.abs(a - b).max() <= rtol * max(np.abs(b).max(), 1.0)


def test_fpca_matches_scikit_fda(fitted):
    fd, ours, X, theirs = fitted
    n, (K, D) = ours.n_components, fd.coefs.shape[1:]
    their_functions = theirs.components_.coefficients.reshape(n, D, K).transpose(0, 2, 1)
    sign = np.sign(np.einsum("nkd,nkd->n", ours.eigenfunctions_, their_functions))
    assert np.all(sign != 0)
    assert close(ours.eigenfunctions_, sign[:, None, None] * their_functions)
    assert close(ours.transform(fd), theirs.transform(X) * sign)
    assert close(ours.explained_variance_, theirs.explained_variance_)
    assert close(ours.explained_variance_ratio_, theirs.explained_variance_ratio_)
    assert close(ours.mean_, theirs.mean_.coefficients.reshape(D, K).T)


def test_fpca_matches_scikit_fda_full_svd_on_a_31_joint_rig(monkeypatch):
    rng = np.random.default_rng(0)
    N, K, J, n = 60, 10, 31, 10
    D = 3 + 4 * J
    coefs = np.cumsum(rng.normal(size=(N, K, D)), axis=1) * rng.uniform(0.1, 1.0, size=D)
    sk = cmu_skeleton()
    offsets = np.broadcast_to(sk.offsets, (N, J, 3)).copy()
    fd = FunctionalMotions(coefs, BSplineBasis(K), FunctionLayout(J), offsets, sk.parents, n_frames=60)
    ours = FPCA(n).fit(fd)
    X = skfda_data(fd)
    monkeypatch.setattr(skfda_fpca_module, "PCA", partial(PCA, svd_solver="full"))
    theirs = SkFPCA(n_components=n).fit(X)
    functions = theirs.components_.coefficients.reshape(n, D, K).transpose(0, 2, 1)
    sign = np.sign(np.einsum("nkd,nkd->n", ours.eigenfunctions_, functions))
    assert close(ours.eigenfunctions_, sign[:, None, None] * functions)
    assert close(ours.transform(fd), theirs.transform(X) * sign)
    # exact: singular values of the centred coefficients times a Cholesky factor of scikit-fda's Gram matrix
    L = np.linalg.cholesky(X.basis.gram_matrix())
    c = X.coefficients - X.coefficients.mean(axis=0)
    exact = np.linalg.svd(c @ L, compute_uv=False)[:n] ** 2 / (N - 1)
    assert close(ours.explained_variance_, exact)
