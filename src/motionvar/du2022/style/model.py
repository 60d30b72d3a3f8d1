"""Du 2022 ch. 5 put together (Fig. 5.2): a :class:`FeatureSpace` (the trained
convolutional autoencoder with its feature scaling) encodes clips into feature maps,
a primitive's VAE or CVAE samples feature maps, and the motion decoder turns them back
into clips' features; :func:`style_distance_matrix` is Table 5.1 (Eq. 5.12).

Models are saved as torch files of plain dicts (hyper-parameters, state dict, scaler)
and load with ``weights_only=True``.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd
import torch

from .features import FeatureScaler
from .losses import style_distance
from .networks import ConvAutoencoder, MotionVAE


def _save(path: str | Path, obj: dict) -> None:
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_name(f".{path.name}.tmp")
    try:
        torch.save(obj, tmp)
        tmp.replace(path)
    except BaseException:
        tmp.unlink(missing_ok=True)
        raise


def _load(path: str | Path, kind: str) -> dict:
    path = Path(path)
    if not path.is_file():
        raise FileNotFoundError(f"{path}: model file missing")
    try:
        obj = torch.load(path, weights_only=True)
    except Exception as exc:
        raise ValueError(f"{path}: not a readable model file ({exc})") from exc
    if not isinstance(obj, dict) or obj.get("kind") != kind:
        raise ValueError(f"{path}: not a saved {kind}")
    return obj


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
    def decode(self, maps: torch.Tensor) -> np.ndarray:
        """Feature maps (N, 256, T') -> features (N, T, C) in the data's units."""
        x = self.ae.decode(torch.as_tensor(maps, dtype=torch.float32)).transpose(-1, -2)
        return self.scaler.inverse(x.numpy())

    @torch.no_grad()
    def reencode(self, maps: torch.Tensor) -> torch.Tensor:
        """Phi(Phi'(Y)): decode feature maps to motion and encode that motion again."""
        return self.ae.encode(self.ae.decode(torch.as_tensor(maps, dtype=torch.float32)))

    def reconstruction_rmse(self, features: np.ndarray) -> float:
        """Root mean squared error of Phi'(Phi(x)) in the data's units (all channels)."""
        back = self.decode(self.encode(features))
        return float(np.sqrt(np.mean((back - features) ** 2)))

    def save(self, path: str | Path) -> None:
        _save(path, {
            "kind": "du2022_conv_autoencoder", "hparams": self.ae.hparams, "state_dict": self.ae.state_dict(),
            "mean": torch.as_tensor(self.scaler.mean), "std": torch.as_tensor(self.scaler.std),
        })

    @classmethod
    def load(cls, path: str | Path) -> "FeatureSpace":
        obj = _load(path, "du2022_conv_autoencoder")
        ae = ConvAutoencoder(**obj["hparams"])
        ae.load_state_dict(obj["state_dict"])
        ae.eval()
        return cls(ae=ae, scaler=FeatureScaler(mean=obj["mean"].numpy(), std=obj["std"].numpy()))


def save_vae(path: str | Path, vae: MotionVAE, map_shape: tuple[int, int], info: Mapping[str, str | float] | None = None) -> None:
    """Save a VAE/CVAE with the (K, T') shape of its feature maps and string/number ``info``
    (primitive, style, style example's clip id...)."""
    _save(path, {
        "kind": "du2022_vae", "hparams": vae.hparams, "state_dict": vae.state_dict(),
        "map_shape": list(map_shape), "info": dict(info or {}),
    })


def load_vae(path: str | Path) -> tuple[MotionVAE, tuple[int, int], dict]:
    """(VAE, feature-map shape (K, T'), info) of a file written by :func:`save_vae`."""
    obj = _load(path, "du2022_vae")
    vae = MotionVAE(obj["hparams"]["in_dim"], hidden=tuple(obj["hparams"]["hidden"]), latent=obj["hparams"]["latent"])
    vae.load_state_dict(obj["state_dict"])
    vae.eval()
    return vae, tuple(obj["map_shape"]), dict(obj["info"])


@torch.no_grad()
def sample_maps(vae: MotionVAE, map_shape: tuple[int, int], n: int, seed: int) -> torch.Tensor:
    """n feature maps (n, K, T') from z ~ N(0, I), drawn with their own seeded generator."""
    gen = torch.Generator().manual_seed(seed)
    return vae.sample(n, generator=gen).reshape(n, *map_shape)


def sample_features(
    vae: MotionVAE, map_shape: tuple[int, int], space: FeatureSpace, n: int, seed: int, chunk: int = 1000,
) -> np.ndarray:
    """n random clips of a model as features (n, T, C) (VAE decoder, then motion decoder),
    decoded ``chunk`` clips at a time (the draws do not depend on ``chunk``)."""
    maps = sample_maps(vae, map_shape, n, seed)
    return np.concatenate([space.decode(maps[i:i + chunk]) for i in range(0, n, chunk)])


def style_distance_matrix(
    models: Mapping[str, tuple[MotionVAE, tuple[int, int]]],
    examples: Mapping[str, np.ndarray],
    space: FeatureSpace,
    n_samples: int,
    seed: int,
) -> pd.DataFrame:
    """Table 5.1: D(m, s) (Eq. 5.12) for every model m (rows) and style example s
    (columns, features (T, C)). Each model's ``n_samples`` clips are decoded to motion
    and encoded again, Gram(encoder(x_i)); the examples are encoded once."""
    ex_maps = {s: space.encode(np.asarray(x)[None])[0] for s, x in examples.items()}
    table = pd.DataFrame(index=list(models), columns=list(examples), dtype=float)
    for k, (name, (vae, shape)) in enumerate(models.items()):
        enc = space.reencode(sample_maps(vae, shape, n_samples, seed + k))
        for s, m in ex_maps.items():
            table.loc[name, s] = float(style_distance(enc, m))
    table.index.name = "model"
    return table


@torch.no_grad()
def active_units(vae: MotionVAE, maps: torch.Tensor, threshold: float = 0.01) -> int:
    """Latent dimensions in use (Burda et al. 2016): Cov over the inputs of E[z | y] above
    ``threshold``; a VAE whose posterior collapsed to the prior uses few (its samples
    then vary little)."""
    mu, _ = vae.encode(torch.as_tensor(maps, dtype=torch.float32).reshape(len(maps), -1))
    return int((mu.var(dim=0) > threshold).sum())


def diagonal_minima(table: pd.DataFrame) -> list[str]:
    """Rows whose smallest entry lies in the column of the same name."""
    return [r for r in table.index if r in table.columns and table.loc[r].idxmin() == r]
