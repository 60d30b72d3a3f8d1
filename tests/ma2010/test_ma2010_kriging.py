"""Universal Kriging's variogram (Ma et al. 2010 Sec. 6.1; motionvar.ma2010.kriging) on
residuals with a known variogram: Gaussian processes drawn at random 2-D/3-D parameter
points with an exponential (or Gaussian) covariance and a nugget."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.distance import cdist

from motionvar.ma2010.kriging import (
    AUTO_MODELS,
    UniversalKriging,
    Variogram,
    bin_count,
    empirical_semivariogram,
    fit_semivariogram,
    output_weights,
)


def draw_gp(
    n: int,
    p: int,
    d: int,
    family: str = "exponential",
    sill: float = 1.0,
    rng_: float = 1.0,
    nugget: float = 0.2,
    box: float = 8.0,
    seed: int = 0,
) -> tuple[np.ndarray, np.ndarray]:
    """n points uniform in [0, box]^p and d independent outputs, each a zero-mean GP with
    covariance sill * rho(h / rng_) plus white noise of variance ``nugget``: semivariogram
    nugget + sill * (1 - rho(h / rng_))."""
    rng = np.random.default_rng(seed)
    x = rng.uniform(0, box, (n, p))
    h = cdist(x, x) / rng_
    rho = np.exp(-h) if family == "exponential" else np.exp(-(h**2))
    chol = np.linalg.cholesky(sill * rho + 1e-9 * np.eye(n))
    z = chol @ rng.normal(size=(n, d)) + np.sqrt(nugget) * rng.normal(size=(n, d))
    return x, z - z.mean(axis=0)


@pytest.mark.parametrize("p, n, box", [(2, 200, 8.0), (3, 300, 5.0)])
def test_fitted_exponential_variogram_comes_back(p, n, box):
    x, r = draw_gp(n, p, 40, "exponential", sill=1.0, rng_=1.0, nugget=0.2, box=box, seed=1)
    v = fit_semivariogram(x, r, "exponential", None, "none").variogram.describe()
    assert v["range"] == pytest.approx(1.0, rel=0.35)
    assert v["partial_sill"] == pytest.approx(1.0, rel=0.3)
    assert v["nugget"] == pytest.approx(0.2, abs=0.2)


@pytest.mark.parametrize("family", ["exponential", "gaussian"])
@pytest.mark.parametrize("seed", [0, 1])
def test_auto_picks_the_true_family_in_a_clear_case(family, seed):
    x, r = draw_gp(200, 2, 40, family, rng_=1.0, nugget=0.05, box=8.0, seed=seed)
    fit = fit_semivariogram(x, r, "auto", None, "none")
    assert set(fit.candidates) == set(AUTO_MODELS)
    assert fit.variogram.model == family, fit.aic
    assert fit.aic["linear"] > fit.aic[family] + 10  # a bounded variogram is not a line


def test_pure_noise_gives_a_flat_variogram_and_auto_keeps_it_simple():
    rng = np.random.default_rng(3)
    x, r = rng.uniform(0, 5, (150, 2)), rng.normal(size=(150, 30))
    fit = fit_semivariogram(x, r - r.mean(axis=0), "auto", None, "sd")
    v = fit.variogram
    assert np.all(np.abs(fit.gamma - 1.0) < 0.2)  # sd scaling: unrelated pairs have semivariance ~1
    assert v.curve(np.array([0.05, 3.0])) == pytest.approx([1.0, 1.0], abs=0.15)


def test_normalisation_makes_a_mixed_unit_output_fit_like_a_single_unit_one():
    """Half the dimensions carry the structure in small units (radians), half are noise in
    large units (key times in ms, say): averaged raw, the noise hides the structure; with
    each dimension scaled by its SD the fit matches the same data in one unit."""
    x, z = draw_gp(200, 2, 20, "exponential", rng_=1.0, nugget=0.05, seed=2)
    noise = np.random.default_rng(5).normal(size=(200, 20))
    single = np.concatenate([z, noise - noise.mean(axis=0)], axis=1)
    mixed = np.concatenate([0.01 * z, 100.0 * (noise - noise.mean(axis=0))], axis=1)
    ref = fit_semivariogram(x, single, "exponential", None, "sd").variogram.describe()
    sd = fit_semivariogram(x, mixed, "exponential", None, "sd").variogram.describe()
    raw = fit_semivariogram(x, mixed, "exponential", None, "none").variogram.describe()
    for k in ("nugget", "partial_sill", "range"):
        assert sd[k] == pytest.approx(ref[k], rel=1e-6, abs=1e-9)  # the scaling undoes the units exactly
    structured = lambda v: v["partial_sill"] / (v["partial_sill"] + v["nugget"])  # noqa: E731
    assert structured(ref) > 0.4 and structured(raw) < 0.25 * structured(ref)  # raw: the noise swamps it
    # and Kriging predicts held-out structured dimensions better with the normalised variogram
    test = np.arange(200) % 5 == 0
    err = {}
    for scale in ("sd", "none"):
        k = UniversalKriging("exponential", variogram_scale=scale, standardize=False).fit(x[~test], mixed[~test])
        err[scale] = np.mean((k.predict(x[test])[:, :20] - mixed[test, :20]) ** 2)
    assert err["sd"] < 0.8 * err["none"]


def test_output_weights_and_constant_dimensions():
    r = np.array([[0.0, 1.0, 5.0], [0.0, -1.0, 5.0], [0.0, 3.0, 5.0]])
    assert np.array_equal(output_weights(r, "none"), np.ones(3))
    w = output_weights(r, "sd")
    assert w[0] == 0 and w[2] == 0 and w[1] == pytest.approx(1 / r[:, 1].var())
    with pytest.raises(ValueError, match="scale"):
        output_weights(r, "cm")
    lag, gamma, pairs = empirical_semivariogram(np.arange(3.0)[:, None], r, None, "sd", max_lag=1.0)
    assert pairs.sum() == 3 and np.all(np.isfinite(gamma))
    assert [bin_count(n) for n in (10, 150, 7000, 10**6)] == [20, 20, 70, 100]  # ~100 pairs a bin, 20-100 bins
    x = np.random.default_rng(0).uniform(size=(60, 2))
    lag, _, pairs = empirical_semivariogram(x, np.random.default_rng(1).normal(size=(60, 3)), 5, "none", max_lag=0.5)
    assert len(lag) == 5 and lag.max() <= 0.5 * np.sqrt(2) and pairs.sum() < 60 * 59 // 2
    with pytest.raises(ValueError, match="pair_mask"):
        empirical_semivariogram(x, np.zeros((60, 3)), None, "none", pair_mask=np.ones(3, dtype=bool))


def test_plain_single_model_stays_selectable_and_options_are_checked():
    x, r = draw_gp(80, 2, 10, seed=4)
    old = UniversalKriging("linear", variogram_scale="none", variogram_weights="pairs", max_lag=1.0).fit(x, r)
    assert old.variogram_.model == "linear" and old.variogram_fit_.scale == "none"
    assert isinstance(UniversalKriging("auto", variogram_scale="sd").fit(x, r).variogram_, Variogram)
    with pytest.raises(ValueError, match="unknown variogram model"):
        UniversalKriging("cubic", variogram_scale="sd")
    with pytest.raises(ValueError, match="variogram_scale"):
        UniversalKriging("auto", variogram_scale="per_dim")
    with pytest.raises(ValueError, match="variogram_weights"):
        UniversalKriging("auto", variogram_scale="sd", variogram_weights="uniform")


def test_kriging_interpolates_and_flat_residuals_do_not_break_the_fit():
    rng = np.random.default_rng(6)
    x = rng.uniform(0, 1, (15, 2))
    y = 1.0 + x @ np.array([[2.0, 0.0], [-1.0, 3.0]])  # an exact hyperplane: residuals all zero
    k = UniversalKriging("auto", variogram_scale="sd").fit(x, y)
    assert np.allclose(k.predict(x[:3]), y[:3]) and k.variogram_.nugget == 0.0
    x2, r2 = draw_gp(40, 2, 5, seed=7)
    k2 = UniversalKriging("exponential", variogram_scale="sd").fit(x2, r2)
    assert np.allclose(k2.predict(x2), r2, atol=1e-6)  # Kriging is exact at the examples


# --- the diagnostic evaluation (ma2010_variogram) on toy walkers -------------------------------------


def test_variogram_evaluation_table_and_figure(tmp_path):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import pandas as pd
    from ma2010_toywalk import toy_walk

    from motionvar.core import cmu_joint_map
    from motionvar.io import load_dataset, save_dataset
    from motionvar.ma2010.evaluations.variogram import STYLE_ONLY, variogram_fits
    from motionvar.ma2010.examples import WalkCycles, walk_cycles
    from motionvar.ma2010.figures import draw_variogram
    from motionvar.ma2010.settings import Ma2010Settings
    from motionvar.ma2010.svi import GROUP_ORDER

    jm = cmu_joint_map()
    motions = [
        toy_walk(hip_amp=0.3 + 0.03 * i, arm_amp=0.2 + 0.1 * i, n_cycles=3, hip_growth=0.03 * (i % 3)) for i in range(4)
    ]
    meta = pd.DataFrame(
        {
            "clip_id": [f"w{i}" for i in range(4)],
            "subject": [f"{i:02d}" for i in range(4)],
            "behaviour": "walk",
            "style": "neutral",
            "variant": "forward",
        }
    )
    save_dataset(tmp_path, motions, meta)
    settings = Ma2010Settings().replace(clips__n_frames=24)
    clips, table = walk_cycles(load_dataset(tmp_path), jm, settings)
    walks = WalkCycles(clips, table["subject"].tolist(), jm, source="toy walks", root_group="legs")
    for model, scale in (("auto", "sd"), ("linear", "none")):
        result = variogram_fits(walks, settings.replace(model__variogram_model=model, model__variogram_scale=scale))
        t = result.table
        assert result.claims == []  # a diagnostic: the paper states nothing about the variogram
        assert set(t["group"]) == {*GROUP_ORDER, STYLE_ONLY} and {"all pairs", "old"} <= set(t["series"])
        main = t[t["series"] == "all pairs"]
        assert np.isfinite(main[["lag", "gamma", "fitted", "nugget"]].to_numpy()).all() and (main["pairs"] > 0).all()
        assert set(main["scale"]) == {scale} and (model == "auto" or set(main["model"]) == {"linear"})
        fig = draw_variogram(result)
        assert len(fig.axes) == 5
        plt.close(fig)


def test_trend_cut_off_ignores_a_thin_direction_of_collinear_parameters():
    """Two parameters that vary together (left and right strides of a symmetric walk: a
    0.999 correlation, as the generator's walks) leave a thin direction whose literal
    least-squares slope fits the noise; ``trend_rcond`` drops it, so a query off the line
    (a user asking for unequal strides) gets the trend of the main direction instead of a
    slope fitted to noise, and a query on the line is predicted as before."""
    rng = np.random.default_rng(3)
    s = rng.normal(130.0, 5.0, 60)
    x = np.column_stack([s + rng.normal(0, 0.15, 60), s + rng.normal(0, 0.15, 60)])
    y = np.column_stack([0.02 * s + rng.normal(0, 0.05, 60), -0.01 * s + rng.normal(0, 0.05, 60)])
    on_line, off_line = np.array([[132.0, 132.0]]), np.array([[128.0, 136.0]])
    truth_off = np.array([0.02 * 132.0, -0.01 * 132.0])  # the outputs depend on the mean stride only
    literal = UniversalKriging("linear", variogram_scale="sd", trend_rcond=0.0).fit(x, y)
    cut = UniversalKriging("linear", variogram_scale="sd", trend_rcond=0.1).fit(x, y)
    assert np.abs(cut.trend(off_line) - truth_off).max() < 0.5 * np.abs(literal.trend(off_line) - truth_off).max()
    assert np.allclose(cut.trend(on_line), literal.trend(on_line), atol=0.05)
    with pytest.raises(ValueError, match="trend_rcond"):
        UniversalKriging("linear", variogram_scale="sd", trend_rcond=1.5)


def test_rbf_with_one_example_per_walk_reaches_between_the_walks():
    """RBFs on a linear term (Rose et al. 1998), each kernel's support twice the distance to the
    nearest other example: with every cycle its own example, pairs of near-identical styles (the
    cycles of one walk) get kernels that reach nothing else, and a style between the pairs gets
    the linear fit alone; with each walk one example (its cycles' mean style and output) the
    kernels span the distance to the nearest other walk and reach it, and the interpolation
    passes through each walk's mean."""
    from motionvar.ma2010.baselines.rbf import RBFInterpolation, support_radii

    x = np.array([[0.0], [0.001], [1.0], [1.001], [3.0], [3.001]])
    y = np.array([[0.0], [0.2], [5.0], [5.2], [0.0], [0.2]])
    walks = np.array(["a", "a", "b", "b", "c", "c"])
    linear = np.polyval(np.polyfit(x[:, 0], y[:, 0], 1), 2.0)
    cycles = RBFInterpolation().fit(x, y)
    assert np.allclose(cycles.predict(x), y, atol=1e-6)
    assert cycles.predict(np.array([[2.0]]))[0, 0] == pytest.approx(linear) and not cycles.reaches([[2.0]])[0]
    per_walk = RBFInterpolation().fit(x, y, walks)
    assert per_walk.reaches([[2.0]])[0] and per_walk.predict(np.array([[2.0]]))[0, 0] > linear + 0.2
    assert np.allclose(per_walk.predict(np.array([[0.0005], [1.0005], [3.0005]]))[:, 0], [0.1, 5.1, 0.1])
    assert np.allclose(per_walk.radius_ * x.std(), [2.0, 2.0, 4.0])  # twice the distance to the nearest other walk
    assert not per_walk.reaches([[10.0]])[0]  # beyond every support: the linear term alone
    assert np.allclose(support_radii(np.array([[0.0], [0.0]])), 2.0)  # no other example elsewhere
    with pytest.raises(ValueError, match="group labels"):
        RBFInterpolation().fit(x, y, walks[:3])
