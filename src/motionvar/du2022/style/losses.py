"""Losses and the style measure of Du 2022 Sec. 5.3-5.4.3.

- :func:`vae_loss`: Eq. 5.6 = content (Eq. 5.7, L samples per input) + KL (Eq. 5.8).
- :func:`gram`: Eq. 5.9, the Gram matrix of a feature map over its time axis, "the sum of
  the inner product of features over the temporal axis": ``reduce="sum"`` as printed;
  ``reduce="mean"`` divides the sum by the number of frames (the thesis also says style
  frames "will be averaged by the calculation of gram matrix", Sec. 5.4.1). For two maps of
  T frames the sum is T times the mean, so their Gram difference is T times larger (T' = 30
  feature frames for the canonical 60-frame clips): under the Frobenius norm of Eq. 5.10 the
  same alpha weighs the style term 30 times more with the sum than with the mean (900 times
  under the mean squared distance).
- :func:`gram_distance`: the distance of Eq. 5.12, which the thesis describes as "the mean
  squared distance": the mean over the 256 x 256 entries of the squared difference.
- :func:`gram_distance_maps`: the same distance computed from the feature maps without
  forming the K x K Gram matrices (exact algebra, ~10x less work for K = 256 kernels and
  T = 30 frames: ||A A'/T - B B'/S||^2 = ||A'A||^2/T^2 - 2 ||A'B||^2/(T S) + ||B'B||^2/S^2,
  without the divisions for the summed Gram matrix).
- :func:`style_loss`: Eq. 5.10, alpha ||Gram(decoder(z)) - Gram(y_s)||, the Frobenius norm as
  printed (``norm="frobenius"``) or Eq. 5.12's mean squared distance (``norm="mean_squared"``).
  ``target="batch_mean"`` compares the mean of the minibatch's decoded Gram matrices with the
  style example's, as the author's code does (``models/conditional_vae_autoencoder.py`` of
  DeepMotionModeling: ``tf.norm(reduce_mean(gram(style)) - reduce_mean(gram(decoded)))``):
  the decodes must carry the style on average and may differ from each other.
  ``target="per_sample"`` compares every decode's Gram matrix and averages the norms, which
  pulls each sample to the one example: a decoder that ignores z is its cheapest optimum.
  The choices set the balance against the content term (Eq. 5.7, a sum over 7,680
  features) for a given alpha: with 256 x 256 entries the Frobenius norm is 256 times the
  root of the mean squared distance.
- :func:`latent_spread_penalty`: the author's code's term w exp(-mean (z - mean z)^2) over a
  minibatch's latent draws, which the thesis does not mention (``author_code`` variant).
- :func:`style_distance`: Eq. 5.12 (Table 5.1), by default on frame-averaged Gram matrices:
  the thesis' neutral-to-neutral distance (0.0149) has the scale of the average (ours
  0.0135); the sum multiplies every entry of Table 5.1 by 30^2 = 900 (same pattern).
"""

from __future__ import annotations

import torch

from .settings import CvaeSettings

CONTENT_REDUCTIONS = ("mean", "sum")


def content_loss(recon: torch.Tensor, y: torch.Tensor, reduce: str = "mean") -> torch.Tensor:
    """Eq. 5.7: 1 / (2 N L) sum_i sum_l ||decoder(z_il) - y_i||^2 (``reduce="mean"``); recon
    (L, N, D), y (N, D). ``reduce="sum"``: 1 / L sum_i sum_l ||...||^2, the author's code's
    sum over the minibatch (its ``reconstruction_loss``, one draw per input)."""
    if reduce not in CONTENT_REDUCTIONS:
        raise ValueError(f"content_loss: reduce must be one of {CONTENT_REDUCTIONS}; got {reduce!r}")
    L, N = recon.shape[0], recon.shape[1]
    return ((recon - y) ** 2).sum() / (2.0 * N * L if reduce == "mean" else L)


def kl_loss(mu: torch.Tensor, logvar: torch.Tensor) -> torch.Tensor:
    """Eq. 5.8, averaged over the N inputs: 1/2 (mu'mu + tr(Sigma) - k - log det Sigma)."""
    return 0.5 * (mu.pow(2) + logvar.exp() - 1.0 - logvar).sum(dim=-1).mean()


def vae_loss(
    recon: torch.Tensor, y: torch.Tensor, mu: torch.Tensor, logvar: torch.Tensor
) -> tuple[torch.Tensor, torch.Tensor]:
    """Eq. 5.6 as (content, KL); the loss is their sum."""
    return content_loss(recon, y), kl_loss(mu, logvar)


GRAM_REDUCTIONS = ("sum", "mean")


def _check_reduce(reduce: str) -> None:
    if reduce not in GRAM_REDUCTIONS:
        raise ValueError(f"gram: reduce must be one of {GRAM_REDUCTIONS}; got {reduce!r}")


def gram(features: torch.Tensor, reduce: str = "sum") -> torch.Tensor:
    """Eq. 5.9: (..., K, T) feature maps -> (..., K, K) Gram matrices sum_i y_i y_i^T over the
    T frames (``reduce="sum"``, as printed), or that sum / T (``reduce="mean"``)."""
    _check_reduce(reduce)
    g = features @ features.transpose(-1, -2)
    return g / features.shape[-1] if reduce == "mean" else g


def gram_distance(g: torch.Tensor, g_ref: torch.Tensor) -> torch.Tensor:
    """(...) mean squared difference of Gram matrices (..., K, K) to ``g_ref`` (K, K)."""
    return ((g - g_ref) ** 2).mean(dim=(-2, -1))


def gram_distance_maps(maps: torch.Tensor, ref_maps: torch.Tensor, reduce: str = "sum") -> torch.Tensor:
    """(...) ``gram_distance(gram(maps, reduce), gram(ref_maps, reduce))`` for maps
    (..., K, T) and ref_maps (K, S), through T x T and T x S products instead of K x K ones."""
    _check_reduce(reduce)
    K, T, S = maps.shape[-2], maps.shape[-1], ref_maps.shape[-1]
    wt, ws = (1.0 / T, 1.0 / S) if reduce == "mean" else (1.0, 1.0)
    mt = maps.transpose(-1, -2)
    own = (mt @ maps).pow(2).sum(dim=(-2, -1)) * wt**2
    cross = (mt @ ref_maps).pow(2).sum(dim=(-2, -1)) * (wt * ws)
    ref = (ref_maps.transpose(-1, -2) @ ref_maps).pow(2).sum() * ws**2
    return torch.clamp(own - 2.0 * cross + ref, min=0.0) / K**2


STYLE_NORMS = ("frobenius", "mean_squared")
STYLE_TARGETS = ("batch_mean", "per_sample")


def style_loss(
    recon_maps: torch.Tensor,
    style_maps: torch.Tensor,
    alpha: float,
    norm: str,
    gram_reduce: str,
    target: str = CvaeSettings.style_target,
) -> torch.Tensor:
    """Eq. 5.10: alpha ||Gram(decoder(z)) - Gram(y_s)||; recon_maps (..., K, T) decoded
    feature maps, style_maps (K, S) the encoded style example, ``norm`` frobenius (as
    printed) or mean_squared, ``gram_reduce`` the reduction of Eq. 5.9 (:func:`gram`),
    ``target`` batch_mean (the distance of the decodes' mean Gram matrix) or per_sample (the
    mean of each decode's distance); config du2022_style.cvae.style_norm, .gram and .style_target."""
    if norm not in STYLE_NORMS:
        raise ValueError(f"style_loss: norm must be one of {STYLE_NORMS}; got {norm!r}")
    if target not in STYLE_TARGETS:
        raise ValueError(f"style_loss: target must be one of {STYLE_TARGETS}; got {target!r}")
    K = recon_maps.shape[-2]
    if target == "batch_mean":
        maps = recon_maps.reshape(-1, K, recon_maps.shape[-1])
        # the mean of the decodes' Gram matrices is the Gram matrix of their frames side by side
        side_by_side = maps.transpose(0, 1).reshape(K, -1)
        g = gram(side_by_side, gram_reduce) * (1.0 if gram_reduce == "mean" else 1.0 / len(maps))
        msd = gram_distance(g, gram(style_maps, gram_reduce))
    else:
        msd = gram_distance_maps(recon_maps, style_maps, gram_reduce)
    if norm == "frobenius":
        return alpha * (K * torch.sqrt(msd + 1e-12)).mean()
    return alpha * msd.mean()


def latent_spread_penalty(z: torch.Tensor, weight: float) -> torch.Tensor:
    """``weight`` exp(-mean over draws and dimensions of (z - mean z)^2), z (..., k) latent draws
    pooled over the leading axes: the author's code's ``variational_error`` (weight 10), which
    grows as the draws of a minibatch close in on one point."""
    flat = z.reshape(-1, z.shape[-1])
    return weight * torch.exp(-((flat - flat.mean(dim=0)) ** 2).mean())


def style_distance(sample_maps: torch.Tensor, style_maps: torch.Tensor, gram_reduce: str = "mean") -> torch.Tensor:
    """Eq. 5.12: D(m, s) = 1/N sum_i ||Gram(encoder(x_i)) - Gram(encoder(s))||, with
    sample_maps (N, K, T) the encoded samples x_i of model m and style_maps (K, T') the
    encoded style example s; frame-averaged Gram matrices by default (the thesis' scale)."""
    return gram_distance_maps(sample_maps, style_maps, gram_reduce).mean()
