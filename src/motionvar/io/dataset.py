"""Packed motion datasets: ``clips.npz`` (all clips' arrays concatenated over frames)
plus ``metadata.csv`` (one row per clip, docs/design.md "Datasets").

All clips of a dataset share one topology (names, parents, channel layout); bone
lengths, fps and length differ per clip. Writes are atomic: a failed save leaves no file.
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd

from ..core.motion import Motion
from ..core.skeleton import Skeleton
from .atomic import atomic_write
from .model_file import exception_line

CLIPS_FILE = "clips.npz"
METADATA_FILE = "metadata.csv"
# The arrays of clips.npz that every dataset has (``translations`` only where a clip has them).
CLIP_ARRAYS = (
    "names",
    "parents",
    "rotation_orders",
    "position_channels",
    "end_site_joints",
    "end_site_offsets",
    "offsets",
    "fps",
    "starts",
    "root_pos",
    "rotations",
)


class DatasetError(ValueError):
    """A packed dataset that cannot be read or written; the message names the file."""


def save_dataset(directory: str | Path, motions: Sequence[Motion], metadata: pd.DataFrame) -> None:
    """Write ``motions`` and their ``metadata`` (same order, a unique ``clip_id`` column)."""
    directory = Path(directory)
    if len(motions) != len(metadata):
        raise DatasetError(f"{directory}: {len(motions)} motions but {len(metadata)} metadata rows")
    if len(motions) == 0:
        raise DatasetError(f"{directory}: no clips to save")
    if "clip_id" not in metadata or metadata["clip_id"].duplicated().any():
        raise DatasetError(f"{directory}: metadata needs a unique clip_id column")
    sk0 = motions[0].skeleton
    for m, cid in zip(motions, metadata["clip_id"]):
        if not m.skeleton.same_topology(sk0):
            raise DatasetError(f"{directory}: clip {cid} has another skeleton topology than the first clip")
    end_idx = np.array(sorted(sk0.end_sites), dtype=np.int64)
    lengths = np.array([m.n_frames for m in motions])
    has_tr = any(m.translations is not None for m in motions)
    arrays = {
        "names": np.array(sk0.names),
        "parents": sk0.parents,
        "rotation_orders": np.array(sk0.rotation_orders),
        "position_channels": np.array(sk0.position_channels),
        "end_site_joints": end_idx,
        "end_site_offsets": np.array([[m.skeleton.end_sites[j] for j in end_idx] for m in motions]).reshape(
            len(motions), len(end_idx), 3
        ),
        "offsets": np.stack([m.skeleton.offsets for m in motions]),
        "fps": np.array([m.fps for m in motions], dtype=float),
        "starts": np.concatenate([[0], np.cumsum(lengths)]),
        "root_pos": np.concatenate([m.root_pos for m in motions]),
        "rotations": np.concatenate([m.rotations for m in motions]).astype(np.float32),
    }
    if has_tr:
        arrays["translations"] = np.concatenate(
            [
                m.translations if m.translations is not None else np.full(m.rotations.shape[:2] + (3,), np.nan)
                for m in motions
            ]
        ).astype(np.float32)
    meta = metadata.copy()
    meta["n_frames"] = lengths
    meta["fps"] = arrays["fps"]

    def write_clips(tmp: Path) -> None:
        with open(tmp, "wb") as fh:  # a file object: np.savez would append .npz to the temporary name
            np.savez(fh, **arrays)

    atomic_write(directory / CLIPS_FILE, write_clips)
    atomic_write(directory / METADATA_FILE, lambda tmp: meta.to_csv(tmp, index=False))


@dataclass
class MotionDataset:
    """A loaded packed dataset: ``metadata`` (DataFrame) and the clips' arrays."""

    metadata: pd.DataFrame
    arrays: dict[str, np.ndarray]

    def __len__(self) -> int:
        return len(self.metadata)

    def _skeleton(self, i: int) -> Skeleton:
        a = self.arrays
        return Skeleton(
            names=tuple(str(n) for n in a["names"]),
            parents=a["parents"],
            offsets=a["offsets"][i],
            end_sites={int(j): a["end_site_offsets"][i, k] for k, j in enumerate(a["end_site_joints"])},
            rotation_orders=tuple(str(o) for o in a["rotation_orders"]),
            position_channels=tuple(bool(p) for p in a["position_channels"]),
        )

    def motion(self, i: int) -> Motion:
        """The i-th clip (row i of ``metadata``) as a Motion."""
        a = self.arrays
        s, e = a["starts"][i], a["starts"][i + 1]
        tr = a["translations"][s:e].astype(float) if "translations" in a else None
        return Motion(
            skeleton=self._skeleton(i),
            root_pos=a["root_pos"][s:e].copy(),
            rotations=a["rotations"][s:e].astype(float),
            fps=float(a["fps"][i]),
            translations=tr,
        )

    def by_id(self, clip_id: str) -> Motion:
        idx = np.flatnonzero(self.metadata["clip_id"].to_numpy() == clip_id)
        if len(idx) != 1:
            raise KeyError(f"clip_id {clip_id!r} not in dataset")
        return self.motion(int(idx[0]))

    def __iter__(self) -> Iterator[Motion]:
        return (self.motion(i) for i in range(len(self)))

    def select(self, mask: np.ndarray | pd.Series) -> list[tuple[pd.Series, Motion]]:
        """(metadata row, Motion) pairs of the clips where ``mask`` is true."""
        idx = np.flatnonzero(np.asarray(mask))
        return [(self.metadata.iloc[i], self.motion(int(i))) for i in idx]


def load_dataset(directory: str | Path) -> MotionDataset:
    """Read a dataset written by :func:`save_dataset`."""
    directory = Path(directory)
    clips, meta = directory / CLIPS_FILE, directory / METADATA_FILE
    for f in (clips, meta):
        if not f.is_file():
            raise DatasetError(f"{f}: missing (expected a packed dataset in {directory})")
    try:
        with np.load(clips, allow_pickle=False) as z:
            arrays = {k: z[k] for k in z.files}
    except Exception as exc:  # zip/npy errors: name the file
        raise DatasetError(f"{clips}: not a readable packed dataset ({exception_line(exc)})") from exc
    try:
        metadata = pd.read_csv(meta, dtype={"clip_id": str, "subject": str})
    except Exception as exc:  # empty, garbled or not text: name the file
        raise DatasetError(f"{meta}: not a readable metadata table ({exception_line(exc)})") from exc
    missing = [k for k in CLIP_ARRAYS if k not in arrays]
    if missing:
        raise DatasetError(f"{clips}: not a packed dataset (no arrays {', '.join(missing)})")
    if len(metadata) != len(arrays["fps"]):
        raise DatasetError(f"{meta}: {len(metadata)} rows but {clips} holds {len(arrays['fps'])} clips")
    return MotionDataset(metadata=metadata, arrays=arrays)
