"""Du 2022 ch. 5 losses (Eq. 5.6-5.12): content, KL, Gram matrices and the style distance."""

import numpy as np
import pytest
import torch

from motionvar.du2022.style import (
    CvaeSettings,
    VaeSettings,
    content_loss,
    gram,
    gram_distance,
    gram_distance_maps,
    kl_loss,
    latent_spread_penalty,
    style_distance,
    style_loss,
    train_cvae,
    train_vae,
)

pytestmark = pytest.mark.usefixtures("one_torch_thread")  # tests/conftest.py


def test_content_and_kl_losses():
    y = torch.tensor([[1.0, 2.0], [0.0, 0.0]])
    recon = torch.stack([y + 1.0, y])  # L = 2 samples
    # (2 inputs x 2 dims x 1^2 in sample 1 + 0) / (2 N L) = 4 / 8
    assert float(content_loss(recon, y)) == pytest.approx(0.5)
    assert float(kl_loss(torch.zeros(4, 32), torch.zeros(4, 32))) == pytest.approx(0.0)
    mu = torch.full((1, 2), 1.0)
    logvar = torch.log(torch.tensor([[2.0, 2.0]]))
    expected = 0.5 * (2.0 + 4.0 - 2.0 - 2 * np.log(2.0))
    assert float(kl_loss(mu, logvar)) == pytest.approx(expected)


def test_gram_sums_over_frames_as_eq_5_9_or_averages_independent_of_their_order():
    y = torch.randn(4, 10)
    g = gram(y)  # Eq. 5.9 as printed: the sum over frames
    assert torch.allclose(g, sum(torch.outer(y[:, i], y[:, i]) for i in range(10)), atol=1e-5)
    assert torch.allclose(gram(y[:, torch.randperm(10)]), g, atol=1e-5)
    gm = gram(y, "mean")
    assert torch.allclose(gm, g / 10, atol=1e-6)  # the frame-count factor
    assert torch.allclose(gram(torch.cat([y, y], dim=1), "mean"), gm, atol=1e-6)  # examples of any length
    assert torch.allclose(gram(torch.cat([y, y], dim=1)), 2 * g, atol=1e-5)
    assert float(style_distance(y[None].repeat(3, 1, 1), y)) == pytest.approx(0.0, abs=1e-9)
    assert float(gram_distance(gm + 1.0, gm)) == pytest.approx(1.0)
    with pytest.raises(ValueError, match="reduce must be one of"):
        gram(y, "max")


def test_gram_sum_and_mean_differ_by_the_frame_count_in_the_style_terms():
    """T = 30 feature frames (the canonical 60-frame clips): the Gram difference of two
    30-frame maps is 30 times larger summed than averaged, so the Frobenius style term
    (Eq. 5.10) is 30 times larger at the same alpha and the mean squared distance 900 times."""
    gen = torch.Generator().manual_seed(1)
    a, b = (
        torch.rand(2, 3, 16, 30, generator=gen, dtype=torch.float64),
        torch.rand(16, 30, generator=gen, dtype=torch.float64),
    )
    assert torch.allclose(gram_distance_maps(a, b, "sum"), 900 * gram_distance_maps(a, b, "mean"), rtol=1e-9)
    fro_sum = float(style_loss(a, b, 200.0, "frobenius", gram_reduce="sum"))
    fro_mean = float(style_loss(a, b, 200.0, "frobenius", gram_reduce="mean"))
    assert fro_sum == pytest.approx(30 * fro_mean, rel=1e-6)
    ms_sum = float(style_loss(a, b, 200.0, norm="mean_squared", gram_reduce="sum"))
    assert ms_sum == pytest.approx(
        900 * float(style_loss(a, b, 200.0, norm="mean_squared", gram_reduce="mean")), rel=1e-9
    )
    # Table 5.1's distance stays on the average (the thesis' scale) unless asked
    assert float(style_distance(a[0], b)) == pytest.approx(float(gram_distance_maps(a[0], b, "mean").mean()))
    assert float(style_distance(a[0], b, "sum")) == pytest.approx(900 * float(style_distance(a[0], b)))
    with pytest.raises(ValueError, match="reduce must be one of"):
        style_loss(a, b, 1.0, "frobenius", gram_reduce="median")


def test_batch_mean_style_target_lets_samples_differ():
    """Eq. 5.10 on the minibatch's mean Gram matrix (the author's code) is zero for two decodes
    that differ, each carrying half the style example's Gram matrix; compared sample by sample
    the same decodes pay, and only copies of one Gram matrix are free."""
    style = torch.tensor([[1.0, -1.0, 1.0, -1.0], [1.0, 1.0, -1.0, -1.0]])  # Gram: 4 I summed, I averaged
    a = torch.stack([np.sqrt(2.0) * style[0], torch.zeros(4)])  # Gram diag(2, 0) averaged
    b = torch.stack([torch.zeros(4), np.sqrt(2.0) * style[1]])  # diag(0, 2)
    pair = torch.stack([a, b])[None]  # (L = 1, N = 2, K, T)
    for reduce in ("mean", "sum"):
        together = style_loss(pair, style, 200.0, "frobenius", reduce, target="batch_mean")
        apart = style_loss(pair, style, 200.0, "frobenius", reduce, target="per_sample")
        assert float(together) < 1e-3 < float(apart), (reduce, float(together), float(apart))
        copies = style_loss(style.expand(1, 3, 2, 4), style, 200.0, "frobenius", reduce, target="per_sample")
        assert float(copies) < 1e-3
    # the mean of the decodes' Gram matrices, as an explicit mean over samples
    gen = torch.Generator().manual_seed(2)
    maps, ref = torch.rand(3, 5, 6, 10, generator=gen, dtype=torch.float64), torch.rand(6, 12, generator=gen)
    for reduce in ("mean", "sum"):
        mean_gram = gram(maps.reshape(-1, 6, 10), reduce).mean(dim=0)
        expected = 200.0 * float(torch.linalg.norm(mean_gram - gram(ref.double(), reduce)))
        got = float(style_loss(maps, ref.double(), 200.0, "frobenius", reduce, target="batch_mean"))
        assert got == pytest.approx(expected, rel=1e-9)
    with pytest.raises(ValueError, match="target must be one of"):
        style_loss(pair, style, 1.0, "frobenius", "mean", target="every")


def test_author_code_terms():
    """The author's code's content term sums over the minibatch (L = 1: its reconstruction_loss)
    and its spread penalty w exp(-mean (z - mean z)^2) is w for draws on one point."""
    y = torch.tensor([[1.0, 2.0], [0.0, 0.0]])
    recon = torch.stack([y + 1.0, y])  # L = 2: a squared error of 4 in one draw, 0 in the other
    assert float(content_loss(recon, y, "sum")) == pytest.approx(4.0 / 2)
    assert float(content_loss(recon, y, "sum")) == pytest.approx(2 * 2 * float(content_loss(recon, y)))
    assert float(latent_spread_penalty(torch.ones(3, 5, 4), 10.0)) == pytest.approx(10.0)
    z = torch.tensor([[-1.0, 1.0], [1.0, -1.0]])  # squared deviations 1 everywhere
    assert float(latent_spread_penalty(z, 10.0)) == pytest.approx(10.0 * np.exp(-1.0))
    with pytest.raises(ValueError, match="reduce must be one of"):
        content_loss(recon, y, "max")


def _toy_maps(seed: int = 0):
    """Toy feature maps (64 clips, 16 x 30) from 4 latent factors, and a style example."""
    gen = torch.Generator().manual_seed(seed)
    base = torch.rand(16, 30, generator=gen)
    factors = 0.5 * torch.randn(4, 16, 30, generator=gen)
    maps = torch.relu(base + torch.einsum("nk,kct->nct", torch.randn(64, 4, generator=gen), factors))
    example = torch.relu(1.5 * base + 0.3 * torch.randn(16, 30, generator=gen))
    return maps, example


def test_default_training_keeps_latent_units_over_seeds():
    """Regressions over four training seeds on toy maps, at one budget (30 epochs at lr 1e-3):
    the default optimiser (Adam) trains VAEs that use their latent space in most seeds, plain
    SGD in none; CVAEs from the live ones keep latent units in use with the default style term
    (the minibatch's mean Gram matrix) in most seeds and lose them all in every seed when each
    sample is pulled to the example (per_sample)."""
    maps, example = _toy_maps()
    hidden, live_vaes, kept = (64, 32, 16), 0, {"batch_mean": 0, "per_sample": 0}
    assert VaeSettings().optimizer == "adam" and CvaeSettings().style_target == "batch_mean"
    for seed in range(4):
        sgd = VaeSettings(latent=4, samples_per_input=3, epochs=30, lr=1e-3, batch_size=16, optimizer="sgd")
        assert train_vae(maps, sgd, seed, hidden)[1]["active"].iloc[-1] == 0, seed
        vae_settings = VaeSettings(latent=4, samples_per_input=3, epochs=30, lr=1e-3, batch_size=16)
        vae, hist = train_vae(maps, vae_settings, seed, hidden)
        if hist["active"].iloc[-1] == 0:
            continue
        live_vaes += 1
        for target in kept:
            cvae_settings = CvaeSettings(epochs=20, lr=1e-3, batch_size=16, style_target=target)
            _, chist = train_cvae(maps, example, vae_settings, cvae_settings, seed, vae, hidden)
            kept[target] += int(chist["active"].iloc[-1] > 0)
    assert live_vaes >= 3
    assert kept["per_sample"] == 0 and kept["batch_mean"] >= 2, kept


def test_gram_distance_from_maps_equals_the_explicit_one():
    gen = torch.Generator().manual_seed(0)
    a, b = (
        torch.rand(3, 5, 16, 10, generator=gen, dtype=torch.float64),
        torch.rand(16, 7, generator=gen, dtype=torch.float64),
    )
    for reduce in ("sum", "mean"):
        ref = gram_distance(gram(a, reduce), gram(b, reduce))
        assert ref.shape == (3, 5)
        assert torch.allclose(gram_distance_maps(a, b, reduce), ref, rtol=1e-10)
        assert float(style_distance(a[0], b, reduce)) == pytest.approx(float(ref[0].mean()))
        # Eq. 5.10 as printed, sample by sample: the Frobenius norm of the Gram difference
        fro = torch.linalg.matrix_norm(gram(a, reduce) - gram(b, reduce)).mean()
        per_sample = float(style_loss(a, b, 2.0, "frobenius", gram_reduce=reduce, target="per_sample"))
        assert per_sample == pytest.approx(2.0 * float(fro), rel=1e-6)
        ms = float(style_loss(a, b, 2.0, norm="mean_squared", gram_reduce=reduce, target="per_sample"))
        assert ms == pytest.approx(2.0 * float(ref.mean()))
    with pytest.raises(ValueError, match="norm must be"):
        style_loss(a, b, 2.0, norm="l1", gram_reduce="sum")
