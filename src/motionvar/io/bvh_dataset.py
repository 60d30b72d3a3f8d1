"""Import a labelled folder of BVH files as clips plus a metadata table, and export
single clips as BVH (docs/design.md, "Datasets").

The labels CSV has one row per clip with the columns ``file`` (path relative to the
folder), ``subject``, ``behaviour`` and ``style``; any further columns (``variant``,
``primitive``, ...) are carried into the metadata. Only the labelled files are read.

The CMU files of the cgspeed conversion start with a synthetic T-pose at frame 0 that
the converter added; pass ``drop_first_frame=True`` to remove it (the 3dsMax-friendly
release, e.g. 131_*.bvh, has none). No heuristic tries to detect it.
"""

from __future__ import annotations

from pathlib import Path

import pandas as pd

from ..core.joint_map import JointMap
from ..core.motion import Motion
from ..core.skeleton import Skeleton
from .bvh import read_bvh, write_bvh
from .dataset import DatasetError

REQUIRED_COLUMNS = ("file", "subject", "behaviour", "style")
METADATA_COLUMNS = ("clip_id", "subject", "behaviour", "style", "variant", "primitive", "source_file")


def _read_labels(labels_csv: Path) -> pd.DataFrame:
    if not labels_csv.is_file():
        raise DatasetError(f"{labels_csv}: labels CSV not found")
    try:
        labels = pd.read_csv(labels_csv, dtype=str, keep_default_na=False)
    except (pd.errors.ParserError, pd.errors.EmptyDataError, UnicodeDecodeError) as exc:
        raise DatasetError(f"{labels_csv}: not a readable CSV ({exc})") from exc
    labels.columns = [str(c).strip() for c in labels.columns]
    for col in REQUIRED_COLUMNS:
        if col not in labels.columns:
            raise DatasetError(f"{labels_csv}: missing required column {col!r} (has {list(labels.columns)})")
    if labels.empty:
        raise DatasetError(f"{labels_csv}: no clips listed")
    return labels


def _layout(sk: Skeleton) -> tuple:
    return sk.names, tuple(sk.parents.tolist()), sk.rotation_orders, sk.position_channels


def _check_files(labels: pd.DataFrame, folder: Path, labels_csv: Path) -> list[Path]:
    """Paths of the labelled files; errors name the CSV line (header = line 1)."""
    paths = []
    for i, name in enumerate(labels["file"].str.strip()):
        line = i + 2
        if not name:
            raise DatasetError(f"{labels_csv}:{line}: empty 'file' entry")
        path = folder / name
        if not path.is_file():
            raise DatasetError(f"{labels_csv}:{line}: labelled file {name!r} does not exist in {folder}")
        paths.append(path)
    stems = pd.Series([p.stem for p in paths])
    dup = stems[stems.duplicated(keep=False)]
    if len(dup):
        lines = ", ".join(str(i + 2) for i in dup.index)
        raise DatasetError(f"{labels_csv}: duplicate clip ids {sorted(set(dup))} (file stems at lines {lines})")
    return paths


def import_bvh_folder(
    folder: str | Path,
    labels_csv: str | Path,
    unit_cm: float,
    drop_first_frame: bool = False,
    joint_map: JointMap | None = None,
) -> tuple[list[Motion], pd.DataFrame]:
    """Read the BVH files listed in ``labels_csv`` (a relative path is taken inside
    ``folder``) with lengths scaled by ``unit_cm`` (cm per file unit, e.g.
    ``CMU_UNIT_CM``). Returns the clips and their metadata (one row per clip, columns
    :data:`METADATA_COLUMNS` plus any extra label columns). All files must share one
    topology and channel layout; ``joint_map``, if given, must fit that skeleton.
    """
    folder = Path(folder)
    labels_csv = Path(labels_csv)
    if not labels_csv.is_absolute():
        labels_csv = folder / labels_csv
    if not folder.is_dir():
        raise DatasetError(f"{folder}: BVH folder not found")
    if not any(folder.rglob("*.bvh")):
        raise DatasetError(f"{folder}: no .bvh files in the folder")
    labels = _read_labels(labels_csv)
    paths = _check_files(labels, folder, labels_csv)
    motions: list[Motion] = []
    for path in paths:
        m = read_bvh(path, scale=unit_cm)
        if motions and _layout(m.skeleton) != _layout(motions[0].skeleton):
            raise DatasetError(
                f"{path}: skeleton topology or channel layout differs from {paths[0]} (all clips must share one)"
            )
        if drop_first_frame:
            if m.n_frames < 2:
                raise DatasetError(f"{path}: only {m.n_frames} frame; cannot drop the first frame")
            m = m.slice(1, m.n_frames)
        motions.append(m)
    if joint_map is not None:
        try:
            joint_map.validate(motions[0].skeleton, source=f"joint map for {paths[0]}")
        except ValueError as exc:
            raise DatasetError(str(exc)) from exc
    meta = pd.DataFrame({
        "clip_id": [p.stem for p in paths],
        "subject": labels["subject"].to_numpy(),
        "behaviour": labels["behaviour"].to_numpy(),
        "style": labels["style"].to_numpy(),
        "variant": labels["variant"].to_numpy() if "variant" in labels else "",
        "primitive": labels["primitive"].to_numpy() if "primitive" in labels else "",
        "source_file": [str(p) for p in paths],
    })
    extra = [c for c in labels.columns if c not in METADATA_COLUMNS and c != "file"]
    for c in extra:
        meta[c] = labels[c].to_numpy()
    return motions, meta


def export_clip_bvh(motion: Motion, path: str | Path) -> None:
    """Write one clip as BVH in cm (Blender's BVH importer reads it; set its scale to
    0.01 for metres). Atomic; the channel layout is the clip's own."""
    write_bvh(path, motion, scale=1.0)
