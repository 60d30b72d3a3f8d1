"""Test helpers: where the shared real BVH files are, their expected sizes (from the
PROVENANCE.md that lies beside the files, outside the repository; docs/data.md summarises
it), and each rig's length unit."""

from __future__ import annotations

import os
import re
from pathlib import Path

from motionvar.core import CMU_UNIT_CM


def real_bvh_dir() -> Path:
    """``$MOTIONVAR_BVH_DIR`` or ``<repo>/../shared/data/bvh`` (may not exist)."""
    env = os.environ.get("MOTIONVAR_BVH_DIR")
    return Path(env) if env else Path(__file__).resolve().parents[2] / "shared/data/bvh"


def real_bvh_files() -> list[Path]:
    d = real_bvh_dir()
    return sorted(d.rglob("*.bvh")) if d.is_dir() else []


def provenance() -> dict[str, tuple[float, int, int]]:
    """File name -> (fps, joints, frames) from the tables of the data folder's PROVENANCE.md."""
    out = {}
    text = (real_bvh_dir() / "PROVENANCE.md").read_text(encoding="utf-8")
    for line in text.splitlines():
        cells = [c.strip() for c in line.split("|")]
        if len(cells) >= 9 and cells[1].endswith(".bvh"):
            fps = float(re.match(r"[\d.]+", cells[5]).group())
            out[Path(cells[1]).name] = (fps, int(cells[6]), int(cells[7]))
    return out


# cm per file unit, by folder. PyMO's unit is not documented: its hips stand ~33 units
# high and its joints span ~52 units, which fits inches (84 and 132 cm).
UNITS_CM = {
    "cmu": CMU_UNIT_CM,
    "xia": CMU_UNIT_CM,
    "pymo": 2.54,
    "bandai": 1.0,
    "aalto": 1.0,
    "dfki": 1.0,
    "dfki/markerless_steps": 0.1,
}


def unit_cm(path: Path) -> float:
    return UNITS_CM[path.parent.relative_to(real_bvh_dir()).as_posix()]
