"""Settings of Du 2022 ch. 5 (config section ``du2022_style``): the convolutional motion
autoencoder (Sec. 5.3.1, Eq. 5.1-5.2), the VAE of each motion primitive (Sec. 5.3.2, Fig.
5.3, Eq. 5.6-5.8), the CVAE of each primitive and style (Sec. 5.3.3, Eq. 5.9-5.11) and the
evaluations (Table 5.1, Tables 5.2-5.3, Fig. 5.4-5.5).

The defaults are the thesis' values where it gives them (Sec. 5.4.1: the autoencoder 300
epochs at learning rate 1e-4, each VAE and CVAE 1000 epochs at 1e-5, alpha 200); where it is
silent or reads two ways, the author's code decides (DeepMotionModeling,
``models/conditional_vae_autoencoder.py``): Adam for "stochastic gradient descent", the
frame-averaged Gram matrix, the CVAE's style term on the minibatch's mean Gram matrix.
``config/config.yaml`` sets the training budgets that fit a 2-core CPU;
``config/variants/du2022_author_code.yaml`` selects the author's code's other choices (fresh
weights, summed content, its latent-spread penalty, alpha 500). The thesis names no batch
size; those defaults are ours.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from ...core.settings import Settings


@dataclass(frozen=True)
class AutoencoderSettings(Settings):
    """The convolutional autoencoder (Eq. 5.1-5.2) and its training (Adam), Sec. 5.3.1, 5.4.1."""

    SECTION = "du2022_style.autoencoder"

    kernels: int = 256
    """Convolution kernels (Sec. 5.3.1: 256)."""
    kernel_width: int = 15
    """Kernel width in frames (Sec. 5.3.1: 15, a quarter of the canonical timeline); odd."""
    decoder_order: str = "conv_depool"
    """conv_depool (Eq. 5.2 as written: convolve, then depool) or depool_conv (Holden et al.
    2016: depool, then convolve)."""
    window_stride: int = 30
    """Stride of the training windows (Sec. 5.4.1: windows of 60 frames overlapping by half)."""
    max_windows: int = 0
    """Train on at most this many windows (a seeded random subset); 0 for all (the thesis)."""
    epochs: int = 300
    """Training epochs (Sec. 5.4.1: 300)."""
    lr: float = 1.0e-4
    """Adam learning rate (Sec. 5.4.1: 0.0001)."""
    batch_size: int = 64
    """Windows per minibatch (not given in the thesis)."""
    keep: str = "last"
    """Which weights to keep: last (the thesis' final model) or best (the epoch with the lowest
    end-of-epoch loss over all windows)."""


@dataclass(frozen=True)
class NetworkTraining(Settings):
    """The training of a VAE or a CVAE: Sec. 5.4.1 gives one setting for both ("For VAE and
    CVAE model training, we set epochs to 1000 with a training rate of 0.00001")."""

    epochs: int = 1000
    """Training epochs (Sec. 5.4.1: 1000)."""
    lr: float = 1.0e-5
    """Learning rate (Sec. 5.4.1: 0.00001)."""
    batch_size: int = 32
    """Clips per minibatch (not given in the thesis)."""
    optimizer: str = "adam"
    """adam, as every trainer of the author's code (the thesis' "stochastic gradient descent",
    Sec. 5.3.2, names the family), or sgd: plain minibatch gradient descent (at the thesis' lr
    1e-5 it leaves the VAE untrained)."""


@dataclass(frozen=True)
class VaeSettings(NetworkTraining):
    """The neutral VAE of each primitive (Fig. 5.3, loss Eq. 5.6) and its training, Sec. 5.3.2, 5.4.1."""

    SECTION = "du2022_style.vae"

    latent: int = 32
    """Latent dimensions (Sec. 5.3.2: 32)."""
    samples_per_input: int = 10
    """L, draws of z per input in Eq. 5.7 (Sec. 5.3.2: L = 10)."""


@dataclass(frozen=True)
class CvaeSettings(NetworkTraining):
    """The CVAE of each primitive and style (Eq. 5.9-5.11) and its training, Sec. 5.3.3, 5.4.1."""

    SECTION = "du2022_style.cvae"

    alpha: float = 200.0
    """Style weight alpha of Eq. 5.10 (Sec. 5.3.3: 200)."""
    style_norm: str = "frobenius"
    """The norm of Eq. 5.10: frobenius (as printed) or mean_squared (Eq. 5.12's mean squared
    distance over the Gram entries)."""
    gram: str = "mean"
    """The Gram matrix of Eq. 5.9: mean over the feature frames (Sec. 5.4.1: style frames "will
    be averaged by the calculation of gram matrix"; the author's ``gram_matrix``) or sum (Eq.
    5.9 as printed)."""
    style_target: str = "batch_mean"
    """What Eq. 5.10 compares with the style example's Gram matrix: batch_mean, the mean of the
    minibatch's decoded Gram matrices (the author's code), or per_sample, each decode's."""
    init_from_neutral: bool = True
    """Start from the neutral VAE's weights (the stylistic primitives are "deformed from" the
    neutral ones, Fig. 5.5); the author's code starts from fresh weights."""
    content: str = "mean"
    """Eq. 5.7's content term: mean (1 / (2 N L), as printed) or sum (over the minibatch, the
    author's code)."""
    spread_weight: float = 0.0
    """Weight of the author's code's latent-spread penalty w exp(-mean (z - mean z)^2) (its 10);
    0 leaves it out, as the thesis does."""


@dataclass(frozen=True)
class StyleSettings(Settings):
    """Config section ``du2022_style``: Du 2022 ch. 5's models and evaluations."""

    SECTION = "du2022_style"

    seed: int = 0
    """Seed of every training run (torch generator) and of the sampling."""
    canonical_frames: int = 60
    """Frames of the canonical timeline (Sec. 4.4.1) and of the autoencoder's windows (Sec. 5.4.1)."""
    styles: tuple[str, ...] = ("proud", "depressed", "angry", "female", "childlike", "old")
    """The styles that get a CVAE (Sec. 5.4: the thesis' six)."""
    vae_primitives: tuple[str, ...] = ("walk_leftStance", "walk_rightStance", "run_rightStance", "pick_reach")
    """Primitives that get a neutral VAE and are drawn in Fig. 5.4 (Sec. 5.4.2)."""
    style_primitives: tuple[str, ...] = ("walk_leftStance", "walk_rightStance")
    """Primitives that get a CVAE per style and are measured in Tables 5.2-5.3 (Sec. 5.4.5)."""
    distance_primitive: str = "walk_leftStance"
    """Primitive of the style-distance matrix (Table 5.1) and the style rows of Fig. 5.5."""
    autoencoder: AutoencoderSettings = field(default_factory=AutoencoderSettings)
    vae: VaeSettings = field(default_factory=VaeSettings)
    cvae: CvaeSettings = field(default_factory=CvaeSettings)
    distance_samples: int = 1000
    """Samples per model for the style distances of Table 5.1 (Sec. 5.4.3: 1000)."""
    diversity_samples: int = 10000
    """Samples per model for pose_SD, V_SD, step_SD of Tables 5.2-5.3 (Sec. 5.4.5: 10,000)."""
    pose_sd_tolerance: float = 0.05
    """The neutral VAE's pose_SD counts as close to the training data's within this relative
    difference (Tables 5.2-5.3 claim; the thesis says "very close")."""
    figure_samples: int = 6
    """Random samples per model drawn in Fig. 5.4-5.5."""
    gif_panel_px: int = 200
    """Width and height (pixels) of one panel of the Fig. 5.4-5.5 GIFs."""
