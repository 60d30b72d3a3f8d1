"""Du 2022 ch. 3 the Bayesian GPLVM and the latent-space measures of Fig. 3.11."""

import math

import numpy as np
import pytest
import torch

from motionvar.du2022.fda import BayesianGPLVM, FunctionalGPLVM, feature_error, knn_accuracy, latent_separation


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
