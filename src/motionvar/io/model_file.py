"""The one on-disk format of fitted models: arrays in ``<base>.npz`` plus a small JSON of
settings in ``<base>.json`` (no pickle anywhere; torch weights are a ``state_dict`` in
``<base>.pt``, read back with ``weights_only=True``, beside the same JSON).

Both files are written atomically (:mod:`motionvar.io.atomic`): an interrupted save leaves
no half-written model, and the files get an ordinary file's mode. Whatever makes a file
unreadable (truncated, garbled, not JSON, not a zip of arrays, weights that are not a
``state_dict`` of tensors) is a ValueError naming the file.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any, Callable

import numpy as np

from .atomic import atomic_write


def model_base(path: str | Path) -> Path:
    """``path`` without a model suffix (``.npz``, ``.json``, ``.pt``)."""
    path = Path(path)
    return path.with_suffix("") if path.suffix in (".npz", ".json", ".pt") else path


def _write_npz(arrays: dict[str, np.ndarray]) -> Callable[[Path], None]:
    def write(tmp: Path) -> None:
        with open(tmp, "wb") as fh:  # a file object: np.savez would append .npz to the name
            np.savez(fh, **{k: np.asarray(v) for k, v in arrays.items()})

    return write


def _write_json(settings: dict[str, Any]) -> Callable[[Path], None]:
    return lambda tmp: tmp.write_text(json.dumps(settings, indent=1) + "\n")


def save_model(path: str | Path, arrays: dict[str, np.ndarray], settings: dict[str, Any]) -> list[Path]:
    """Write ``<base>.npz`` (``arrays``) and ``<base>.json`` (``settings``, JSON-able);
    returns both paths."""
    base = model_base(path)
    npz = atomic_write(base.with_suffix(".npz"), _write_npz(arrays))
    js = atomic_write(base.with_suffix(".json"), _write_json(settings))
    return [npz, js]


def _read_settings(data_file: Path, js: Path, kind: str | None) -> dict[str, Any]:
    """The settings JSON beside ``data_file``, checked for ``kind``; errors name the file."""
    for f in (data_file, js):
        if not f.is_file():
            raise FileNotFoundError(f"{f}: model file missing")
    try:
        settings = json.loads(js.read_text(encoding="utf-8"))
    except (OSError, ValueError) as exc:
        raise ValueError(f"{js}: not a readable model settings file ({exc})") from exc
    if not isinstance(settings, dict):
        raise ValueError(f"{js}: not a readable model settings file (a JSON {type(settings).__name__}, not an object)")
    if kind is not None and settings.get("kind") != kind:
        raise ValueError(f"{js}: not a saved {kind} (kind {settings.get('kind')!r})")
    return settings


def load_model(path: str | Path, kind: str | None = None) -> tuple[dict[str, np.ndarray], dict[str, Any]]:
    """Read ``(arrays, settings)`` written by :func:`save_model`. With ``kind``, the
    settings must say ``"kind": kind``. Errors name the file."""
    base = model_base(path)
    npz = base.with_suffix(".npz")
    settings = _read_settings(npz, base.with_suffix(".json"), kind)
    try:
        with np.load(npz, allow_pickle=False) as z:
            arrays = {k: z[k] for k in z.files}
    except Exception as exc:  # zip, zlib and npy errors of a truncated or garbled file
        raise ValueError(f"{npz}: not a readable model array file ({exception_line(exc)})") from exc
    return arrays, settings


def save_torch_model(path: str | Path, state_dict: dict, settings: dict[str, Any]) -> list[Path]:
    """Write torch weights ``<base>.pt`` (a ``state_dict`` of tensors) and ``<base>.json``."""
    import torch

    base = model_base(path)
    pt = atomic_write(base.with_suffix(".pt"), lambda tmp: torch.save(state_dict, tmp))
    js = atomic_write(base.with_suffix(".json"), _write_json(settings))
    return [pt, js]


def load_torch_model(path: str | Path, kind: str | None = None) -> tuple[dict, dict[str, Any]]:
    """Read ``(state_dict, settings)`` written by :func:`save_torch_model` (the weights
    with ``weights_only=True``)."""
    import torch

    base = model_base(path)
    pt = base.with_suffix(".pt")
    settings = _read_settings(pt, base.with_suffix(".json"), kind)
    try:
        state = torch.load(pt, weights_only=True)
    except Exception as exc:  # torch raises several kinds for a corrupt file
        raise ValueError(f"{pt}: not a readable torch weights file ({exception_line(exc)})") from exc
    if not (isinstance(state, dict) and all(isinstance(k, str) and torch.is_tensor(v) for k, v in state.items())):
        raise ValueError(f"{pt}: not a readable torch weights file (not a state_dict of named tensors)")
    return state, settings


def exception_line(exc: BaseException) -> str:
    """``exc`` as one line: its message, after its type unless an OSError or ValueError
    (whose messages say what went wrong; a BadZipFile's or an EOFError's need the type)."""
    text = " ".join(str(exc).split()) or "no message"
    return text if isinstance(exc, (OSError, ValueError)) else f"{type(exc).__name__}: {text}"
