"""Bayesian GPLVM evidence lower bound and its gradient (motionvar.models.bayesian_gplvm)
against GPy's ``BayesianGPLVM`` with an ARD RBF kernel, at the same fixed parameters.

Parametrisation matched: latent means mu (N, Q) and variances S (N, Q) of q(X), inducing
inputs Z (M, Q), kernel variance sf2 and lengthscales ell (Q,), Gaussian noise variance; the
bound includes -KL(q(X) || N(0, I)) in both. GPy adds a constant 1e-8 to the diagonal of K_uu
(VarDTC's ``const_jitter``); ours adds ``jitter * sf2``, so ours runs with jitter = 1e-8 / sf2
to build the same matrix. Our gradients (torch autograd w.r.t. log S, log sf2, log ell, log
noise) are mapped to the natural parameters by the chain rule.

The one term that differs: our jitter scales with sf2, GPy's does not, so our d bound / d sf2
has the extra term (1e-8 / sf2) tr(dL/dK_uu) (2e-5 of 90 here, 2e-7 relative); it is taken
from GPy's ``grad_dict["dL_dKmm"]`` and added to GPy's gradient before comparing.

Tolerances: bound 1e-10 relative (measured ~1e-15); every gradient block 1e-9 relative to
the block's largest entry (measured <= 2e-12 relative, the sf2 block after the jitter term;
the others <= 1e-14)."""

import numpy as np
import pytest

from motionvar.models.bayesian_gplvm import BayesianGPLVM

GPy = pytest.importorskip("GPy", reason="GPy is not installed (pip install -e '.[crosscheck]')")
torch = pytest.importorskip("torch")

GPY_JITTER = 1e-8  # GPy.inference.latent_function_inference.VarDTC().const_jitter


def ours_bound_and_gradient(Y, mu, S, Z, sf2, ell, noise):
    """Our bound and its gradient w.r.t. (mu, S, Z, sf2, ell, noise)."""
    model = BayesianGPLVM(n_components=mu.shape[1], n_inducing=len(Z), jitter=GPY_JITTER / sf2)
    raw = {"mu": mu, "log_S": np.log(S), "Z": Z, "log_sf2": np.log([sf2]), "log_ell": np.log(ell)}
    raw["log_noise"] = np.log([noise])
    p = {k: torch.tensor(v, dtype=torch.float64, requires_grad=True) for k, v in raw.items()}
    bound, _ = model._bound(p, torch.tensor(Y), float(np.sum(Y**2)), None)
    bound.backward()
    g = {k: v.grad.numpy() for k, v in p.items()}
    return float(bound.detach()), {
        "mu": g["mu"],
        "S": g["log_S"] / S,
        "Z": g["Z"],
        "sf2": g["log_sf2"] / sf2,
        "ell": g["log_ell"] / ell,
        "noise": g["log_noise"] / noise,
    }


def gpy_model(Y, mu, S, Z, sf2, ell, noise):
    kern = GPy.kern.RBF(mu.shape[1], variance=sf2, lengthscale=ell, ARD=True)
    return GPy.models.BayesianGPLVM(
        Y,
        mu.shape[1],
        X=mu.copy(),
        X_variance=S.copy(),
        Z=Z.copy(),
        kernel=kern,
        num_inducing=len(Z),
        likelihood=GPy.likelihoods.Gaussian(variance=noise),
    )


def gpy_bound_and_gradient(m):
    return float(np.ravel(m.log_likelihood())[0]), {
        "mu": np.array(m.X.mean.gradient),
        "S": np.array(m.X.variance.gradient),
        "Z": np.array(m.Z.gradient),
        "sf2": np.array(m.kern.variance.gradient),
        "ell": np.array(m.kern.lengthscale.gradient),
        "noise": np.array(m.likelihood.variance.gradient),
    }


@pytest.fixture(scope="module", params=[(40, 7, 3, 10), (60, 25, 5, 15)], ids=["N40-D7-Q3", "N60-D25-Q5"])
def case(request):
    N, D, Q, M = request.param
    rng = np.random.default_rng(N)
    Y = rng.normal(size=(N, D)) @ rng.normal(size=(D, D)) / np.sqrt(D)
    mu, S, Z = rng.normal(size=(N, Q)), rng.uniform(0.05, 0.5, size=(N, Q)), rng.normal(size=(M, Q))
    params = (mu, S, Z, 1.3, rng.uniform(0.7, 3.0, size=Q), 0.2)
    return Y, params


def test_bound_and_gradient_match_gpy(case):
    Y, params = case
    b_ours, g_ours = ours_bound_and_gradient(Y, *params)
    m = gpy_model(Y, *params)
    b_gpy, g_gpy = gpy_bound_and_gradient(m)
    assert m.inference_method.const_jitter == GPY_JITTER
    g_gpy["sf2"] = g_gpy["sf2"] + GPY_JITTER / params[3] * np.trace(m.grad_dict["dL_dKmm"])
    assert abs(b_ours - b_gpy) <= 1e-10 * abs(b_gpy)
    for name in g_gpy:
        a, b = np.ravel(g_ours[name]), np.ravel(g_gpy[name])
        assert np.abs(a - b).max() <= 1e-9 * np.abs(b).max(), name


def test_gpy_gradient_is_its_bounds_derivative(case):
    """A third computation for the sf2 gradient: a central finite difference of GPy's bound
    agrees with GPy's analytic gradient (so the jitter term above is the whole difference)."""
    Y, params = case
    m = gpy_model(Y, *params)
    analytic = float(m.kern.variance.gradient[0])
    sf2, h = float(m.kern.variance[0]), 1e-6
    values = []
    for x in (sf2 + h, sf2 - h):
        m.kern.variance[:] = x
        values.append(float(np.ravel(m.log_likelihood())[0]))
    assert abs((values[0] - values[1]) / (2 * h) - analytic) <= 1e-6 * abs(analytic)
