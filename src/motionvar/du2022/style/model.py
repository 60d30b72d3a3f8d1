"""Du 2022 ch. 5 put together (Fig. 5.2): a :class:`FeatureSpace` (the trained
convolutional autoencoder with its feature scaling) encodes clips into feature maps,
a primitive's VAE or CVAE samples feature maps, and the motion decoder turns them back
into clips' features.

Models are saved with :func:`motionvar.io.model_file.save_torch_model`: the weights as a
``state_dict`` in ``<base>.pt`` (read back with ``weights_only=True``) and the settings
(kind, hyper-parameters, the feature scaler's mean and scale, a VAE's feature-map shape
and info) in ``<base>.json``.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import torch

from ...io.model_file import load_torch_model, save_torch_model
from .features import FeatureScaler
from .networks import ConvAutoencoder, MotionVAE

AUTOENCODER_KIND = "du2022_conv_autoencoder"
VAE_KIND = "du2022_vae"


@dataclass
class FeatureSpace:
    """The motion encoder Phi and decoder Phi' (Eq. 5.1-5.2) with the feature scaling."""

    ae: ConvAutoencoder
    scaler: FeatureScaler

    @torch.no_grad()
    def encode(self, features: np.ndarray) -> torch.Tensor:
        """Features (N, T, C) -> feature maps Y (N, 256, T / 2)."""
        x = torch.as_tensor(self.scaler.transform(np.asarray(features)), dtype=torch.float32)
        return self.ae.encode(x.transpose(-1, -2))

    @torch.no_grad()
    def decode(self, maps: torch.Tensor, out: np.ndarray | None = None) -> np.ndarray:
        """Feature maps (N, 256, T') -> features (N, T, C) in the data's units (float64;
        written into ``out`` when given)."""
        x = self.ae.decode(torch.as_tensor(maps, dtype=torch.float32)).transpose(-1, -2)
        return self.scaler.inverse(x.numpy(), out=out)

    @torch.no_grad()
    def reencode(self, maps: torch.Tensor) -> torch.Tensor:
        """Phi(Phi'(Y)): decode feature maps to motion and encode that motion again."""
        return self.ae.encode(self.ae.decode(torch.as_tensor(maps, dtype=torch.float32)))

    def reconstruction_rmse(self, features: np.ndarray) -> float:
        """Root mean squared error of Phi'(Phi(x)) in the data's units (all channels)."""
        back = self.decode(self.encode(features))
        return float(np.sqrt(np.mean((back - features) ** 2)))

    def save(self, path: str | Path) -> None:
        """Write ``<base>.pt`` (the autoencoder's state dict) and ``<base>.json`` (its
        hyper-parameters and the scaler's mean and scale with their dtype: exact in JSON)."""
        save_torch_model(
            path,
            self.ae.state_dict(),
            {
                "kind": AUTOENCODER_KIND,
                "hparams": self.ae.hparams,
                "scaler_dtype": str(np.asarray(self.scaler.mean_).dtype),
                "scaler_mean": np.asarray(self.scaler.mean_).tolist(),
                "scaler_std": np.asarray(self.scaler.std_).tolist(),
            },
        )

    @classmethod
    def load(cls, path: str | Path) -> "FeatureSpace":
        state, settings = load_torch_model(path, AUTOENCODER_KIND)
        ae = ConvAutoencoder(**settings["hparams"])
        ae.load_state_dict(state)
        ae.eval()
        dtype = np.dtype(settings["scaler_dtype"])
        mean = np.asarray(settings["scaler_mean"], dtype=dtype)
        scaler = FeatureScaler(n_joints=(len(mean) - 3) // 3).set_fitted(
            mean, np.asarray(settings["scaler_std"], dtype=dtype)
        )
        return cls(ae=ae, scaler=scaler)


def save_vae(
    path: str | Path,
    vae: MotionVAE,
    map_shape: tuple[int, int],
    info: Mapping[str, str | float] | None = None,
) -> None:
    """Save a VAE/CVAE (``<base>.pt`` + ``<base>.json``) with the (K, T') shape of its
    feature maps and string/number ``info`` (primitive, style, style example's clip id...)."""
    save_torch_model(
        path,
        vae.state_dict(),
        {
            "kind": VAE_KIND,
            "hparams": vae.hparams,
            "map_shape": [int(k) for k in map_shape],
            "info": dict(info or {}),
        },
    )


def load_vae(path: str | Path) -> tuple[MotionVAE, tuple[int, int], dict]:
    """(VAE, feature-map shape (K, T'), info) of a model written by :func:`save_vae`."""
    state, settings = load_torch_model(path, VAE_KIND)
    hp = settings["hparams"]
    vae = MotionVAE(hp["in_dim"], hidden=tuple(hp["hidden"]), latent=hp["latent"])
    vae.load_state_dict(state)
    vae.eval()
    return vae, tuple(settings["map_shape"]), dict(settings["info"])


@torch.no_grad()
def sample_maps(vae: MotionVAE, map_shape: tuple[int, int], n: int, seed: int) -> torch.Tensor:
    """n feature maps (n, K, T') from z ~ N(0, I), drawn with their own seeded generator."""
    gen = torch.Generator().manual_seed(seed)
    return vae.sample(n, generator=gen).reshape(n, *map_shape)


def sample_features(
    vae: MotionVAE,
    map_shape: tuple[int, int],
    space: FeatureSpace,
    n: int,
    seed: int,
    chunk: int = 1000,
) -> np.ndarray:
    """n random clips of a model as features (n, T, C) (VAE decoder, then motion decoder),
    decoded ``chunk`` clips at a time into one array (the draws do not depend on ``chunk``)."""
    maps = sample_maps(vae, map_shape, n, seed)
    ae = space.ae
    out = np.empty((n, maps.shape[-1] * ae.pool, ae.hparams["n_channels"]))
    for i in range(0, n, chunk):
        space.decode(maps[i : i + chunk], out=out[i : i + chunk])
    return out


@torch.no_grad()
def active_units(vae: MotionVAE, maps: torch.Tensor, threshold: float = 0.01) -> int:
    """Latent dimensions in use (Burda et al. 2016): Cov over the inputs of E[z | y] above
    ``threshold``; a VAE whose posterior collapsed to the prior uses few (its samples
    then vary little)."""
    mu, _ = vae.encode(torch.as_tensor(maps, dtype=torch.float32).reshape(len(maps), -1))
    return int((mu.var(dim=0) > threshold).sum())


SavedVAE = tuple[MotionVAE, tuple[int, int], dict]
"""A VAE/CVAE as :func:`load_vae` returns it: (network, feature-map shape (K, T'), info)."""
