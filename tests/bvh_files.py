"""Test helpers: where the shared real BVH files are, their expected sizes (from the
PROVENANCE.md that lies beside the files, outside the repository; docs/data.md summarises
it), and each rig's length unit."""

from __future__ import annotations

import os
import re
from pathlib import Path

import numpy as np

from motionvar.core import CMU_UNIT_CM, Motion, Skeleton, cmu_skeleton
from motionvar.core import quaternions as Q


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


def floor_rooted(translations: bool, frames: int = 20, seed: int = 0) -> Motion:
    """The CMU rig under an extra ROOT ``Ground`` (a floor point, like Bandai's joint_Root),
    random rotations everywhere; with ``translations``, every joint has position channels
    that move (as Bandai's 6-channel joints)."""
    rng = np.random.default_rng(seed)
    cmu = cmu_skeleton()
    names = ("Ground",) + cmu.names
    parents = np.concatenate([[-1], cmu.parents + 1])
    parents[1] = 0
    offsets = np.vstack([[0.0, 0.0, 0.0], cmu.offsets])
    offsets[1] = [0.0, 93.0, -3.0]
    end_sites = {j + 1: o for j, o in cmu.end_sites.items()}
    J = len(names)
    sk = Skeleton(names, parents, offsets, end_sites, ("ZXY",) * J, (True,) * J if translations else None)
    rot = Q.qnormalize(np.array([1.0, 0, 0, 0]) + 0.3 * rng.normal(size=(frames, J, 4)))
    root = np.column_stack([np.linspace(0, 100, frames), np.zeros(frames), rng.normal(size=frames)])
    tr = None
    if translations:
        tr = offsets + rng.normal(size=(frames, J, 3))
        tr[:, 0] = np.nan
    return Motion(sk, root, rot, fps=30.0, translations=tr)


def chain_bvh(depth: int) -> str:
    """A chain of ``depth`` joints below the root, one frame."""
    lines = [
        "HIERARCHY",
        "ROOT J0",
        "{",
        "OFFSET 0 0 0",
        "CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation",
    ]
    for d in range(1, depth + 1):
        lines += [f"JOINT J{d}", "{", "OFFSET 0 1 0", "CHANNELS 3 Zrotation Xrotation Yrotation"]
    lines += ["End Site", "{", "OFFSET 0 1 0", "}"] + ["}"] * (depth + 1)
    n_channels = 6 + 3 * depth
    lines += ["MOTION", "Frames: 1", "Frame Time: 0.01", " ".join(["0"] * n_channels)]
    return "\n".join(lines) + "\n"
