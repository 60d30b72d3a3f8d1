"""The networks of Du 2022 ch. 5: the convolutional motion autoencoder (Eq. 5.1-5.2) and
the variational autoencoder of one motion primitive in its feature space (Fig. 5.3,
Eq. 5.3-5.5). A CVAE (Sec. 5.3.3) has the VAE's architecture; only its training loss
differs (:mod:`.losses`, :mod:`.training`).

Tensors follow torch's (batch, channels, time) layout for motion: X is (B, C, T) with
C = 66 feature channels (:mod:`.features`) and T = 60 frames; the feature map Y = Phi(X)
is (B, 256, T / 2).
"""

from __future__ import annotations

import torch
from torch import nn
from torch.nn import functional as F

DECODER_ORDERS = ("conv_depool", "depool_conv")
VAE_HIDDEN = (512, 256, 128)  # the VAE encoder's hidden layers (Fig. 5.3; the decoder mirrors them)


def average_pool(h: torch.Tensor, pool: int) -> torch.Tensor:
    """Psi of Eq. 5.1: the mean of each ``pool`` consecutive frames of h (..., T), T a
    multiple of ``pool``. For the thesis' pool of 2 the mean of the frame pairs,
    (a + b) / 2 in the same rounding as ``F.avg_pool1d`` (forward and gradient), in about
    half its CPU time; other pools go through ``F.avg_pool1d``."""
    if pool == 2:
        return h.unflatten(-1, (h.shape[-1] // 2, 2)).mean(-1)
    return F.avg_pool1d(h, pool)


class ConvAutoencoder(nn.Module):
    """Single-layer convolutional autoencoder (Sec. 5.3.1).

    Encoder, Eq. 5.1: Y = Phi(X) = Psi(ReLU(X * W + b)), ``n_kernels`` kernels of
    ``kernel_width`` frames along time (the thesis: 256 of width 15, a quarter of the
    60-frame canonical timeline: config du2022_style.autoencoder), Psi average pooling by ``pool``.
    Decoder, Eq. 5.2: X = Phi'(Y) = Psi'(Y * W' + b'), W' of W's shape (a transposed
    convolution, whose weight tensor is (256, C, 15) like W), Psi' average depooling
    (each feature frame repeated ``pool`` times). ``decoder_order="depool_conv"`` depools
    first and convolves after, as Holden et al. 2016 do, which gives smooth output instead
    of Eq. 5.2's pairs of equal frames (an option beside the faithful order).
    """

    def __init__(
        self,
        n_channels: int,
        n_kernels: int,
        kernel_width: int,
        decoder_order: str,
        pool: int = 2,
    ) -> None:
        super().__init__()
        if decoder_order not in DECODER_ORDERS:
            raise ValueError(f"ConvAutoencoder: decoder_order must be one of {DECODER_ORDERS}; got {decoder_order!r}")
        if kernel_width % 2 != 1:
            raise ValueError(f"ConvAutoencoder: kernel_width must be odd (same-length convolution); got {kernel_width}")
        self.hparams = dict(
            n_channels=n_channels,
            n_kernels=n_kernels,
            kernel_width=kernel_width,
            pool=pool,
            decoder_order=decoder_order,
        )
        pad = kernel_width // 2
        self.conv = nn.Conv1d(n_channels, n_kernels, kernel_width, padding=pad)
        self.deconv = nn.ConvTranspose1d(n_kernels, n_channels, kernel_width, padding=pad)
        self.pool = pool
        self.decoder_order = decoder_order

    def encode(self, x: torch.Tensor) -> torch.Tensor:
        """Eq. 5.1: (B, C, T) -> (B, 256, T / pool); T must be a multiple of ``pool``."""
        if x.shape[-1] % self.pool:
            raise ValueError(f"ConvAutoencoder: clip length {x.shape[-1]} is not a multiple of the pooling {self.pool}")
        return average_pool(F.relu(self.conv(x)), self.pool)

    def decode(self, y: torch.Tensor) -> torch.Tensor:
        """Eq. 5.2: (B, 256, T / pool) -> (B, C, T)."""
        if self.decoder_order == "conv_depool":
            return torch.repeat_interleave(self.deconv(y), self.pool, dim=-1)
        return self.deconv(torch.repeat_interleave(y, self.pool, dim=-1))

    def forward(self, x: torch.Tensor) -> torch.Tensor:
        return self.decode(self.encode(x))


class MotionVAE(nn.Module):
    """The VAE of one motion primitive (Fig. 5.3): encoder with ``hidden`` units (the
    thesis: 512-256-128, :data:`VAE_HIDDEN`) and a ``latent``-dimensional latent space (the
    thesis: 32, config du2022_style.vae.latent; two linear branches for the mean and the log of
    the diagonal covariance), decoder mirrored (32-128-256-512), tanh on every layer but
    the outputs.
    Works on flattened feature maps y (B, D), D = 256 * 30."""

    def __init__(self, in_dim: int, hidden: tuple[int, ...], latent: int) -> None:
        super().__init__()
        self.hparams = dict(in_dim=in_dim, hidden=list(hidden), latent=latent)
        enc, d = [], in_dim
        for h in hidden:
            enc += [nn.Linear(d, h), nn.Tanh()]
            d = h
        self.encoder = nn.Sequential(*enc)
        self.mu = nn.Linear(d, latent)
        self.logvar = nn.Linear(d, latent)
        dec, d = [], latent
        for h in reversed(hidden):
            dec += [nn.Linear(d, h), nn.Tanh()]
            d = h
        dec.append(nn.Linear(d, in_dim))
        self.decoder = nn.Sequential(*dec)
        self.latent = latent

    def encode(self, y: torch.Tensor) -> tuple[torch.Tensor, torch.Tensor]:
        """Q_phi(z | y): mean and log-variance (B, 32)."""
        h = self.encoder(y)
        return self.mu(h), self.logvar(h)

    @staticmethod
    def reparameterize(mu: torch.Tensor, logvar: torch.Tensor, eps: torch.Tensor) -> torch.Tensor:
        """Eq. 5.5: z = mu + Sigma^(1/2) eps (eps (L, B, k) broadcasts over L samples)."""
        return mu + torch.exp(0.5 * logvar) * eps

    def decode(self, z: torch.Tensor) -> torch.Tensor:
        return self.decoder(z)

    @torch.no_grad()
    def sample(self, n: int, generator: torch.Generator | None = None) -> torch.Tensor:
        """n feature vectors decoded from z ~ N(0, I) (the prior of Eq. 5.3)."""
        z = torch.randn(n, self.latent, generator=generator)
        return self.decode(z)
