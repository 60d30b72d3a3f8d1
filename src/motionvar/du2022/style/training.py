"""Training of Du 2022 ch. 5's networks (Sec. 5.4.1), deterministic on the CPU.

- :func:`train_autoencoder`: the convolutional autoencoder on sliding windows of all
  motion, mean squared reconstruction error.
- :func:`train_vae`: a primitive's VAE on its clips' feature maps (loss Eq. 5.6);
  :func:`train_cvae`: given a style example, its CVAE (loss Eq. 5.11 = Eq. 5.6 + the style
  term Eq. 5.10). A CVAE may start from the neutral VAE's weights (``init``): the thesis'
  stylistic primitives are "deformed from" the neutral ones.
- :class:`SlicedAdam`: the optimiser of both (unless ``sgd``): torch's Adam update run slice
  by slice over each parameter, the same weights bit for bit in less time.

The thesis trains with "stochastic gradient descent" at learning rates 1e-4 (autoencoder,
300 epochs) and 1e-5 (VAE/CVAE, 1000 epochs) and names no optimiser or batch size; we use
the optimiser (Adam by default, as every trainer of the author's code, or plain minibatch
SGD), epochs, learning rate and batch size of the config (:class:`~.settings.StyleSettings`;
its defaults are the thesis'). A CVAE's style term decides whether its posterior collapses:
compared sample by sample (``style_target: per_sample``) it pulls every decode to the one
style example, and a decoder that ignores z is its cheapest optimum; on the minibatch's mean
Gram matrix (``batch_mean``, the author's code) the decodes need carry the style only on
average.
Every run draws its shuffles and noise from one ``torch.Generator`` seeded by ``seed``,
so the same inputs give the same weights. Histories are DataFrames, one row per epoch.

From a dataset to the saved models of the pipeline (one per rule):

- :func:`fit_feature_space`: the autoencoder and its feature scaling on (a seeded random
  subset of) the sliding windows of all clips.
- :func:`fit_primitive_vae`: the VAE of one primitive on its neutral clips.
- :func:`fit_style_cvae`: the CVAE of one primitive and style: the neutral clips as
  content, the style's straightest forward clip as the style example (Sec. 5.4.3).
"""

from __future__ import annotations

import copy
import logging
import time
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass

import numpy as np
import pandas as pd
import torch
from torch.optim.adam import adam as adam_update

from ...core.progress import ProgressLog
from ...core.threads import fixed_threads
from ...io.dataset import MotionDataset
from .data import example_features, primitive_features, select_style_example, training_windows, window_counts
from .features import FeatureLayout, FeatureScaler
from .losses import (
    CONTENT_REDUCTIONS,
    GRAM_REDUCTIONS,
    STYLE_NORMS,
    STYLE_TARGETS,
    content_loss,
    kl_loss,
    latent_spread_penalty,
    style_loss,
)
from .model import FeatureSpace, active_units
from .networks import VAE_HIDDEN, ConvAutoencoder, MotionVAE
from .settings import AutoencoderSettings, CvaeSettings, StyleSettings, VaeSettings

log = logging.getLogger(__name__)

# The autoencoder's weights depend on how many threads torch splits its products over (its
# convolutions' backward passes sum in another order); trained on a fixed count, the one of the
# published runs, so that `--cores 1` gives the same feature space, and every Du ch. 5 number
# after it, as two cores.
AUTOENCODER_THREADS = 2

OPTIMIZERS = ("adam", "sgd")
AUTOENCODER_KEEP = ("best", "last")  # which epoch's weights train_autoencoder returns
AUTOENCODER_OPTIMIZER = "adam"  # the autoencoder's optimiser (the VAE's and CVAE's are configured)


@dataclass(frozen=True)
class TrainConfig:
    """Epochs, learning rate, minibatch size, the seed and the optimiser (``"adam"`` or
    ``"sgd"``, plain minibatch gradient descent as the thesis names) of one training run
    (from a subsection of :class:`~.settings.StyleSettings`: :meth:`of`)."""

    epochs: int
    lr: float
    batch_size: int
    seed: int
    optimizer: str

    def __post_init__(self) -> None:
        if self.epochs < 1 or self.batch_size < 1 or not self.lr > 0:
            raise ValueError(f"TrainConfig: epochs and batch_size must be >= 1 and lr > 0; got {self}")
        if self.optimizer not in OPTIMIZERS:
            raise ValueError(f"TrainConfig: optimizer must be one of {OPTIMIZERS}; got {self.optimizer!r}")

    @classmethod
    def of(cls, settings: AutoencoderSettings | VaeSettings | CvaeSettings, seed: int) -> TrainConfig:
        """The run of a config subsection (the autoencoder's optimiser: AUTOENCODER_OPTIMIZER)."""
        optimizer = getattr(settings, "optimizer", AUTOENCODER_OPTIMIZER)
        return cls(settings.epochs, settings.lr, settings.batch_size, seed, optimizer)

    def describe(self) -> str:
        """E.g. "adam lr 0.0001, 10 epochs, batch 32"."""
        return f"{self.optimizer} lr {self.lr:g}, {self.epochs} epochs, batch {self.batch_size}"

    def make_optimizer(self, params: Iterable[torch.nn.Parameter]) -> torch.optim.SGD | SlicedAdam:
        """The configured optimiser over ``params`` (Adam: :class:`SlicedAdam`, the updates
        of ``torch.optim.Adam`` bit for bit)."""
        if self.optimizer == "sgd":
            return torch.optim.SGD(params, lr=self.lr)
        return SlicedAdam(params, lr=self.lr)


class SlicedAdam:
    """Adam with ``torch.optim.Adam``'s defaults (betas 0.9 and 0.999, eps 1e-8), its state
    (a float32 step count and zero moments per parameter, from its first gradient on) and
    its own update, ``torch.optim.adam.adam`` (single-tensor, the CPU default), run on
    slices of ``slice_size`` elements of each parameter. The update is elementwise, so the
    weights come out bit for bit as torch.optim.Adam's, while a slice's parameter, gradient
    and moments stay in the cache across the update's seven passes instead of streaming
    from memory seven times: the VAE's two 7,680 x 512 layers hold 4M weights each (Sec.
    5.4.1); measured at full size (medians, one thread), the update of a VAE step took 19 ms
    and now 15.5 ms, 35 ms and now 22 ms with other jobs loading the memory. Not a
    ``torch.optim.Optimizer``: constructing one imports ``torch._dynamo``, 1.5 CPU-s per
    training rule."""

    def __init__(
        self,
        params: Iterable[torch.nn.Parameter],
        lr: float,
        betas: tuple[float, float] = (0.9, 0.999),
        eps: float = 1e-8,
        slice_size: int = 1 << 18,
    ) -> None:
        if not lr > 0 or slice_size < 1:
            raise ValueError(f"SlicedAdam: lr must be > 0 and slice_size >= 1; got {lr}, {slice_size}")
        self.params = list(params)
        self.lr, self.betas, self.eps, self.slice_size = lr, betas, eps, slice_size
        self.state: dict[torch.nn.Parameter, dict[str, torch.Tensor]] = {}

    def zero_grad(self) -> None:
        """Drop the gradients (``set_to_none``, as torch's optimisers by default)."""
        for p in self.params:
            p.grad = None

    @torch.no_grad()
    def step(self) -> None:
        """One Adam update of every parameter that has a gradient."""
        n = self.slice_size
        lists: tuple[list[torch.Tensor], ...] = ([], [], [], [], [])  # params, grads, moments 1 and 2, steps
        for p in self.params:
            if p.grad is None:
                continue
            if p not in self.state:
                self.state[p] = {
                    "step": torch.tensor(0.0),
                    "exp_avg": torch.zeros_like(p),
                    "exp_avg_sq": torch.zeros_like(p),
                }
            state = self.state[p]
            tensors, bounds = (p, p.grad, state["exp_avg"], state["exp_avg_sq"]), [(0, None)]
            if p.is_contiguous():  # flat views (reshape copies a non-contiguous gradient, which is only read)
                tensors = tuple(t.reshape(-1) for t in tensors)
                bounds = [(a, a + n) for a in range(0, p.numel(), n)]
            for a, b in bounds:
                for out, t in zip(lists, tensors):
                    out.append(t[a:b])
                lists[4].append(state["step"].clone())  # each slice advances its own copy of the count
            state["step"] += 1
        params, grads, exp_avgs, exp_avg_sqs, steps = lists
        beta1, beta2 = self.betas
        adam_update(
            params,
            grads,
            exp_avgs,
            exp_avg_sqs,
            [],
            steps,
            foreach=False,
            amsgrad=False,
            beta1=beta1,
            beta2=beta2,
            lr=self.lr,
            weight_decay=0.0,
            eps=self.eps,
            maximize=False,
        )


def _batches(n: int, batch_size: int, gen: torch.Generator) -> list[torch.Tensor]:
    return list(torch.randperm(n, generator=gen).split(batch_size))


def train_autoencoder(
    windows: np.ndarray, settings: AutoencoderSettings, seed: int
) -> tuple[ConvAutoencoder, pd.DataFrame]:
    """Train Eq. 5.1-5.2 (``settings.kernels`` kernels of ``settings.kernel_width`` frames,
    ``settings.decoder_order``) on scaled windows (W, T, C) for ``settings.epochs`` epochs of
    Adam, the shuffles drawn with ``seed``. ``settings.keep``: "last" returns the weights
    of the last epoch (the thesis' final model), "best" those of the epoch whose
    end-of-epoch loss over all windows is lowest (a late spike of the loss does not end in
    the model; at full size this changed the VAEs downstream: config/schema.yaml). History columns:
    epoch, loss (running mean of the minibatch MSE), end_loss (MSE of the end-of-epoch
    weights over all windows: every epoch with "best"; with "last" only for the last epoch,
    NaN before, which spares a forward pass over all windows per epoch, a third of the
    epoch's time), kept (the epoch returned), seconds."""
    if windows.ndim != 3 or len(windows) == 0:
        raise ValueError(f"train_autoencoder: windows must be a non-empty (W, T, C) array; got {windows.shape}")
    keep = settings.keep
    if keep not in AUTOENCODER_KEEP:
        raise ValueError(f"train_autoencoder: keep must be one of {AUTOENCODER_KEEP}; got {keep!r}")
    cfg = TrainConfig.of(settings, seed)
    torch.manual_seed(cfg.seed)
    gen = torch.Generator().manual_seed(cfg.seed)
    x = torch.as_tensor(windows, dtype=torch.float32).permute(0, 2, 1).contiguous()
    model = ConvAutoencoder(
        x.shape[1], n_kernels=settings.kernels, kernel_width=settings.kernel_width, decoder_order=settings.decoder_order
    )
    opt = cfg.make_optimizer(model.parameters())
    rows, t0 = [], time.perf_counter()
    best_loss, best_state, kept = np.inf, None, cfg.epochs
    progress = ProgressLog("autoencoder epoch", cfg.epochs)
    for epoch in range(1, cfg.epochs + 1):
        total = 0.0
        for idx in _batches(len(x), cfg.batch_size, gen):
            xb = x[idx]
            loss = torch.mean((model(xb) - xb) ** 2)
            opt.zero_grad()
            loss.backward()
            opt.step()
            total += float(loss.detach()) * len(idx)
        end_loss = np.nan
        if keep == "best" or epoch == cfg.epochs:
            with torch.no_grad():
                end_loss = float(sum(torch.sum((model(xb) - xb) ** 2) for xb in x.split(512)) / x.numel())
        if keep == "best" and end_loss < best_loss:
            best_loss, best_state, kept = end_loss, copy.deepcopy(model.state_dict()), epoch
        rows.append({"epoch": epoch, "loss": total / len(x), "end_loss": end_loss, "seconds": time.perf_counter() - t0})
        progress(epoch, total / len(x))
    if keep == "best":
        model.load_state_dict(best_state)
    model.eval()
    history = pd.DataFrame(rows)
    history["kept"] = history["epoch"] == kept
    return model, history


def train_vae(
    maps: torch.Tensor | np.ndarray, settings: VaeSettings, seed: int, hidden: tuple[int, ...] = VAE_HIDDEN
) -> tuple[MotionVAE, pd.DataFrame]:
    """Train a primitive's VAE (``settings.latent`` latent dimensions, hidden layers
    ``hidden``) on its clips' feature maps (N, K, T') with the loss of Eq. 5.6 (L =
    ``settings.samples_per_input`` draws of z per input, Eq. 5.7), the run of ``settings``
    seeded by ``seed``. History columns: epoch, loss, content, kl, style (0), seconds
    (per-epoch means over the inputs) and active (latent dimensions in use on the inputs at
    the end of the epoch, :func:`~.model.active_units`)."""
    return _train_vae(maps, TrainConfig.of(settings, seed), settings.samples_per_input, settings.latent, hidden)


def train_cvae(
    maps: torch.Tensor | np.ndarray,
    style_maps: torch.Tensor | np.ndarray,
    vae: VaeSettings,
    cvae: CvaeSettings,
    seed: int,
    init: MotionVAE | None,
    hidden: tuple[int, ...] = VAE_HIDDEN,
) -> tuple[MotionVAE, pd.DataFrame]:
    """Train a primitive's CVAE on its clips' feature maps (N, K, T') and ``style_maps``
    (K, T_s), the encoded style example: the loss of Eq. 5.11 with the style term of Eq.
    5.10 (weight ``cvae.alpha``, norm ``cvae.style_norm``, Gram matrices of Eq. 5.9 averaged
    or summed over frames by ``cvae.gram``, on the minibatch's mean Gram matrix or each
    sample's by ``cvae.style_target``, :func:`~.losses.style_loss`), the content term reduced
    by ``cvae.content`` and the latent-spread penalty weighted ``cvae.spread_weight``, the
    neutral VAE's latent size and L (``vae``), the run of ``cvae`` seeded by ``seed``. ``init``
    (a trained VAE) gives the starting weights, or None. History columns: those of
    :func:`train_vae` (loss includes the spread penalty)."""
    cfg = TrainConfig.of(cvae, seed)
    return _train_vae(maps, cfg, vae.samples_per_input, vae.latent, hidden, init, (style_maps, cvae))


def _train_vae(
    maps: torch.Tensor | np.ndarray,
    cfg: TrainConfig,
    n_samples: int,
    latent: int,
    hidden: tuple[int, ...],
    init: MotionVAE | None = None,
    style: tuple[torch.Tensor | np.ndarray, CvaeSettings] | None = None,
) -> tuple[MotionVAE, pd.DataFrame]:
    """The training loop of :func:`train_vae` and, with ``style`` (the style example's maps
    and the CVAE's settings), of :func:`train_cvae`."""
    style_maps, style_term = style if style is not None else (None, None)
    maps = torch.as_tensor(maps, dtype=torch.float32)
    if maps.ndim != 3 or len(maps) == 0:
        raise ValueError(f"train_vae: maps must be a non-empty (N, K, T) array; got {tuple(maps.shape)}")
    if n_samples < 1:
        raise ValueError(f"train_vae: n_samples (L) must be >= 1; got {n_samples}")
    N, K, Tf = maps.shape
    y = maps.reshape(N, K * Tf)
    torch.manual_seed(cfg.seed)
    gen = torch.Generator().manual_seed(cfg.seed)
    model = MotionVAE(K * Tf, hidden=hidden, latent=latent)
    if init is not None:
        if init.hparams != model.hparams:
            raise ValueError(f"train_vae: init VAE has {init.hparams}, expected {model.hparams}")
        model.load_state_dict(init.state_dict())
    if style_term is not None:
        alpha, style_norm, gram_reduce = style_term.alpha, style_term.style_norm, style_term.gram
        if style_norm not in STYLE_NORMS:
            raise ValueError(f"train_cvae: style_norm must be one of {STYLE_NORMS}; got {style_norm!r}")
        if gram_reduce not in GRAM_REDUCTIONS:
            raise ValueError(f"train_cvae: gram must be one of {GRAM_REDUCTIONS}; got {gram_reduce!r}")
        if style_term.style_target not in STYLE_TARGETS:
            raise ValueError(
                f"train_cvae: style_target must be one of {STYLE_TARGETS}; got {style_term.style_target!r}"
            )
        if style_term.content not in CONTENT_REDUCTIONS:
            raise ValueError(f"train_cvae: content must be one of {CONTENT_REDUCTIONS}; got {style_term.content!r}")
        style_maps = torch.as_tensor(style_maps, dtype=torch.float32)
        if style_maps.ndim != 2 or style_maps.shape[0] != K:
            raise ValueError(f"train_vae: style_maps must be ({K}, T_s); got {tuple(style_maps.shape)}")
    opt = cfg.make_optimizer(model.parameters())
    rows, t0 = [], time.perf_counter()
    progress = ProgressLog(f"{'CVAE' if style_term is not None else 'VAE'} epoch", cfg.epochs)
    for epoch in range(1, cfg.epochs + 1):
        sums = np.zeros(4)
        for idx in _batches(N, cfg.batch_size, gen):
            yb = y[idx]
            mu, logvar = model.encode(yb)
            eps = torch.randn((n_samples, len(idx), model.latent), generator=gen)
            z = model.reparameterize(mu, logvar, eps)
            recon = model.decode(z)
            k = kl_loss(mu, logvar)
            if style_term is None:
                c, s = content_loss(recon, yb), torch.zeros(())
                loss = c + k
            else:
                c = content_loss(recon, yb, style_term.content)
                recon_maps = recon.reshape(n_samples, len(idx), K, Tf)
                s = style_loss(recon_maps, style_maps, alpha, style_norm, gram_reduce, style_term.style_target)
                loss = c + k + s
                if style_term.spread_weight:
                    loss = loss + latent_spread_penalty(z, style_term.spread_weight)
            opt.zero_grad()
            loss.backward()
            opt.step()
            sums += len(idx) * np.array([float(v.detach()) for v in (loss, c, k, s)])
        sums /= N
        seconds = time.perf_counter() - t0
        rows.append(
            {
                "epoch": epoch,
                "loss": sums[0],
                "content": sums[1],
                "kl": sums[2],
                "style": sums[3],
                "seconds": seconds,
                "active": active_units(model, y),
            }
        )
        progress(epoch, float(sums[0]))
    model.eval()
    return model, pd.DataFrame(rows)


# ---------------------------------------------------------------- from a dataset to the models


def fit_feature_space(
    dataset: MotionDataset,
    layout: FeatureLayout,
    settings: StyleSettings,
    threads: int = AUTOENCODER_THREADS,
) -> tuple[FeatureSpace, pd.DataFrame]:
    """The conv autoencoder (Eq. 5.1-5.2) with its :class:`~.features.FeatureScaler`,
    trained (:func:`train_autoencoder`, ``settings.autoencoder``, seed ``settings.seed``) on
    the windows of ``settings.canonical_frames`` frames every
    ``settings.autoencoder.window_stride`` frames of all clips (Sec. 5.4.1);
    ``settings.autoencoder.max_windows`` > 0 keeps a random subset of that many (drawn with
    the seed). History columns: those of :func:`train_autoencoder` and windows. Trained on
    ``threads`` torch and BLAS threads (:data:`AUTOENCODER_THREADS`), whatever cores the
    caller has."""
    with fixed_threads(threads):
        ae_settings, window, seed = settings.autoencoder, settings.canonical_frames, settings.seed
        stride, max_windows = ae_settings.window_stride, ae_settings.max_windows
        n_all = int(window_counts(dataset, window, stride).sum())
        subset = None
        if 0 < max_windows < n_all:  # only the drawn windows' frames are computed
            subset = np.sort(np.random.default_rng(seed).choice(n_all, max_windows, replace=False))
        windows = training_windows(dataset, layout, window, stride, subset)
        log.info(
            "%d windows of %d frames (%d in all) from %d clips; joints %s",
            len(windows),
            windows.shape[1],
            n_all,
            len(dataset),
            ", ".join(layout.names),
        )
        scaler = FeatureScaler(layout.n_joints).fit(windows)
        ae, history = train_autoencoder(scaler.transform(windows), ae_settings, seed)
        space = FeatureSpace(ae, scaler)
        history["windows"] = len(windows)
        kept = history.loc[history["kept"]].iloc[0]
        log.info(
            "trained in %.1f s; kept epoch %d of %d (end-of-epoch loss %.4g; last %.4g); reconstruction RMSE %.3f",
            history["seconds"].iloc[-1],
            kept["epoch"],
            len(history),
            kept["end_loss"],
            history["end_loss"].iloc[-1],
            space.reconstruction_rmse(windows[:512]),
        )
        return space, history


def fit_primitive_vae(
    dataset: MotionDataset,
    layout: FeatureLayout,
    space: FeatureSpace,
    primitive: str,
    settings: StyleSettings,
    hidden: tuple[int, ...] = VAE_HIDDEN,
) -> tuple[MotionVAE, tuple[int, int], dict, pd.DataFrame]:
    """The VAE of ``primitive`` (Fig. 5.3, Eq. 5.6; :func:`train_vae`, ``settings.vae``, seed
    ``settings.seed``) on the feature maps of its neutral clips resampled to
    ``settings.canonical_frames``: (VAE, feature-map shape (K, T'), info for
    :func:`~.model.save_vae`, history)."""
    rows, feats = primitive_features(dataset, layout, primitive, "neutral", settings.canonical_frames)
    maps = space.encode(feats)
    log.info("%s: %d neutral clips, feature maps %s", primitive, len(rows), tuple(maps.shape))
    vae, history = train_vae(maps, settings.vae, settings.seed, hidden)
    log.info(
        "trained in %.1f s; final loss %.4g (content %.4g, KL %.4g); %d of %d latent dimensions active",
        history["seconds"].iloc[-1],
        history["loss"].iloc[-1],
        history["content"].iloc[-1],
        history["kl"].iloc[-1],
        history["active"].iloc[-1],
        settings.vae.latent,
    )
    info = {
        "primitive": primitive,
        "style": "neutral",
        "n_clips": len(rows),
        "active_units": int(history["active"].iloc[-1]),
        "regime": f"{TrainConfig.of(settings.vae, settings.seed).describe()}, L = {settings.vae.samples_per_input}",
    }
    return vae, tuple(maps.shape[1:]), info, history


def neutral_content(
    dataset: MotionDataset, layout: FeatureLayout, space: FeatureSpace, primitive: str, n_frames: int
) -> tuple[pd.DataFrame, np.ndarray]:
    """(metadata rows, encoded feature maps) of the neutral clips of ``primitive`` on
    ``n_frames`` frames: the content of every CVAE of the primitive (Sec. 5.3.3)."""
    rows, feats = primitive_features(dataset, layout, primitive, "neutral", n_frames)
    return rows, space.encode(feats)


def fit_style_cvae(
    dataset: MotionDataset,
    layout: FeatureLayout,
    space: FeatureSpace,
    neutral: MotionVAE,
    primitive: str,
    style: str,
    settings: StyleSettings,
    hidden: tuple[int, ...] = VAE_HIDDEN,
    content: tuple[pd.DataFrame, np.ndarray] | None = None,
) -> tuple[MotionVAE, tuple[int, int], dict, pd.DataFrame]:
    """The CVAE of ``primitive`` and ``style`` (Sec. 5.3.3, loss Eq. 5.11 with the Gram
    style term Eq. 5.10; :func:`train_cvae`, ``settings.cvae``): content the neutral clips
    (on ``settings.canonical_frames`` frames; ``content`` passes :func:`neutral_content`'s
    result, computed once for every style of the primitive), style example the straightest
    forward clip of the style (:func:`~.data.select_style_example`); starts from the
    ``neutral`` VAE's weights when ``settings.cvae.init_from_neutral``. Returns (CVAE,
    feature-map shape, info with the example's clip id, history)."""
    c, n_frames, latent = settings.cvae, settings.canonical_frames, settings.vae.latent
    cfg = TrainConfig.of(c, settings.seed)
    rows, maps = content if content is not None else neutral_content(dataset, layout, space, primitive, n_frames)
    example_id = select_style_example(dataset.metadata, primitive, style)
    example = space.encode(example_features(dataset, layout, example_id, n_frames)[None])[0]
    log.info("%s/%s: %d neutral clips, style example %s", primitive, style, len(rows), example_id)
    init = neutral if c.init_from_neutral else None
    cvae, history = train_cvae(maps, example, settings.vae, c, settings.seed, init, hidden)
    first = history.iloc[0]
    log.info(
        "epoch 1: content %.4g, KL %.4g, style %.4g; %d active latent dimensions",
        first["content"],
        first["kl"],
        first["style"],
        first["active"],
    )
    log.info(
        "trained in %.1f s (%s, lr %g, %d epochs); final loss %.4g (content %.4g, KL %.4g, style %.4g); "
        "%d of %d latent dimensions active",
        history["seconds"].iloc[-1],
        cfg.optimizer,
        cfg.lr,
        cfg.epochs,
        history["loss"].iloc[-1],
        history["content"].iloc[-1],
        history["kl"].iloc[-1],
        history["style"].iloc[-1],
        history["active"].iloc[-1],
        latent,
    )
    info = {
        "primitive": primitive,
        "style": style,
        "example": example_id,
        "n_clips": len(rows),
        "active_units": int(history["active"].iloc[-1]),
        "regime": f"{cfg.describe()}; alpha {c.alpha:g}, {c.style_norm.replace('_', ' ')} norm, "
        f"{c.style_target.replace('_', '-')} Gram ({c.gram} over frames)"
        + (", summed content" if c.content == "sum" else "")
        + (f", spread penalty {c.spread_weight:g}" if c.spread_weight else "")
        + (", from the neutral VAE" if c.init_from_neutral else ", from fresh weights"),
    }
    return cvae, tuple(maps.shape[1:]), info, history


def last_epoch_drop(history: pd.DataFrame, column: str = "style") -> float | None:
    """How far ``column`` of a training history fell in the last epoch, relative to the epoch
    before (0.05: 5 % lower; None with fewer than two epochs)."""
    values = history[column].to_numpy(dtype=float)
    return None if len(values) < 2 else float(1.0 - values[-1] / values[-2])


def last_epoch_drops(
    infos: Sequence[Mapping[str, object]],
    histories: Sequence[pd.DataFrame],
    name: Callable[[Mapping[str, object]], str],
) -> dict[str, float]:
    """``{name(info): last_epoch_drop(history)}`` of trained networks and their histories, in the
    same order; histories of fewer than two epochs are left out."""
    return {name(info): d for info, h in zip(infos, histories, strict=True) if (d := last_epoch_drop(h)) is not None}
