"""Baselines of Ma 2010 Sec. 7.4: Perlin noise, RBF (Rose 1998), style-only Kriging, GPLVM, DBN."""

import numpy as np
import pytest

from motionvar.core.noise import perlin_noise
from motionvar.ma2010.baselines.dbn import LauDBN
from motionvar.ma2010.baselines.gplvm import helix_trajectory
from motionvar.ma2010.baselines.perlin import add_rotation_noise
from motionvar.ma2010.baselines.rbf import RBFInterpolation, cubic_bspline


def test_perlin_noise_is_seeded_bounded_and_smooth():
    t = np.arange(600) / 120.0
    a = perlin_noise(t, 4, 2.0, seed=3, octaves=3)
    assert a.shape == (600, 4)
    assert np.array_equal(a, perlin_noise(t, 4, 2.0, seed=3, octaves=3))
    assert not np.allclose(a, perlin_noise(t, 4, 2.0, seed=4, octaves=3))
    assert np.abs(a).max() <= 1.0 and a.std() > 0.05
    one = perlin_noise(t, 2, 2.0, seed=0)
    lattice = np.isclose((t * 2.0) % 1.0, 0.0)
    assert np.allclose(one[lattice], 0.0)  # gradient noise is zero on the lattice
    assert np.abs(np.diff(one, axis=0)).max() < 0.1  # no jumps at 120 samples per second
    with pytest.raises(ValueError, match="frequency > 0"):
        perlin_noise(t, 2, 0.0, seed=0)


def test_rotation_noise_keeps_unit_quaternions_and_the_root():
    rot = np.zeros((100, 5, 4))
    rot[..., 0] = 1
    out = add_rotation_noise(rot, 120.0, 0.2, 1.0, seed=0)
    assert np.allclose(np.linalg.norm(out, axis=-1), 1) and np.allclose(out[:, 0], rot[:, 0])
    assert not np.allclose(out[:, 1:], rot[:, 1:])


def test_rbf_interpolates_with_a_linear_term():
    rng = np.random.default_rng(0)
    x = rng.uniform(0, 1, (20, 2))
    y = np.stack([np.sin(3 * x[:, 0]), x[:, 1] ** 2], 1)
    f = RBFInterpolation().fit(x, y)
    assert np.allclose(f.predict(x), y, atol=1e-8)
    far = f.predict(np.array([[10.0, 10.0]]))  # beyond every B-spline's support: the linear term alone
    assert np.allclose(far, f.linear_[0] + ((np.array([10.0, 10.0]) - f.x_mean_) / f.x_scale_) @ f.linear_[1:])
    assert cubic_bspline(np.array([0.0]))[0] == pytest.approx(2 / 3) and cubic_bspline(np.array([2.0]))[0] == 0


def test_helix_circles_the_latent_cloud_and_rises_along_its_third_axis():
    rng = np.random.default_rng(1)
    t = np.linspace(0, 2 * np.pi, 200, endpoint=False)
    cloud = np.stack([10 * np.cos(t), 10 * np.sin(t), rng.uniform(-1, 1, 200)], 1) + [5.0, -2.0, 0.0]
    path = helix_trajectory(cloud, 100, n_turns=2.0)
    assert path.shape == (100, 3)
    assert np.allclose(np.linalg.norm(path[:, :2] - [5.0, -2.0], axis=1), 10.0, rtol=0.05)
    assert path[-1, 2] - path[0, 2] == pytest.approx(np.ptp(cloud[:, 2]), rel=0.05)


def test_dbn_learns_an_ar2_process_and_unrolls():
    rng = np.random.default_rng(2)
    seqs = []
    for _ in range(5):
        x = np.zeros((300, 2))
        x[:2] = rng.normal(size=(2, 2))
        for t in range(2, 300):
            x[t, 0] = 1.6 * x[t - 1, 0] - 0.8 * x[t - 2, 0] + 0.1 * rng.normal()
            x[t, 1] = 0.5 * x[t - 1, 0] + 0.1 * rng.normal()
        seqs.append(x)
    dbn = LauDBN(max_parents=4).fit(seqs)
    W, b, s = dbn.transition_
    assert W[0, 0] == pytest.approx(1.6, abs=0.1) and W[0, 2] == pytest.approx(-0.8, abs=0.1)
    assert W[1, 0] == pytest.approx(0.5, abs=0.1) and s[0] == pytest.approx(0.1, rel=0.2)
    out = dbn.sample(1000, np.random.default_rng(0))
    assert out.shape == (1000, 2) and np.isfinite(out).all()
    with pytest.raises(ValueError, match="need sequences"):
        LauDBN().fit([np.zeros((2, 3))])
