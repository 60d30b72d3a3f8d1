"""BVH reading (motionvar.io.bvh.read_bvh) against pybvh and bvhio on the 35 real files of
../shared/data/bvh (CMU, Xia, Bandai-Namco, Aalto, DFKI, PyMO; ``$MOTIONVAR_BVH_DIR`` points
elsewhere, as for the other BVH tests; skipped where the folder is absent).

Compared per file: joint names and parents, OFFSETs, End Sites, rotation channel orders, which
joints have position channels, frame count and frame time, and every frame's values: root
positions, other joints' position channels, local rotations (as matrices, so that quaternion
signs do not matter), and with pybvh also the world joint positions of its own forward
kinematics.

Tolerances: pybvh reads in float64: 1e-9 relative to the array's largest magnitude (measured
over all files: offsets and root positions identical, rotation matrices 6e-16, FK positions
1.5e-15). bvhio keeps float32 (glm): 1e-6 relative, rotation matrices 2e-6 (measured: offsets
3e-8, root positions 6e-8, other joints' position channels 4e-8, rotation matrices 6.6e-7).

Frame time: ours is the file's literal value (``Frame Time: 0.008333`` -> 120.0048 fps);
pybvh snaps a value within 1e-4 of 1/N to 1/N (1/120), so that check is 1e-4 relative for
pybvh and exact against the file's text for ours.

What they cannot read: the DFKI file writes ``Frames: 46.0``, which both libraries refuse;
it is read from a copy with ``Frames: 46``. pybvh refuses joints other than the root with
position channels (both Bandai-Namco files): skipped for pybvh, checked with bvhio."""

import os
import re
import warnings
from pathlib import Path

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from motionvar.io.bvh import read_bvh

ROOT = Path(__file__).resolve().parents[2]
DATA = Path(os.environ.get("MOTIONVAR_BVH_DIR") or ROOT.parent / "shared" / "data" / "bvh")  # as tests/bvh_files.py
FILES = sorted(DATA.rglob("*.bvh")) if DATA.is_dir() else []
IDS = [str(f.relative_to(DATA)) for f in FILES]
needs_data = pytest.mark.skipif(not FILES, reason=f"real BVH files not found at {DATA}")
_FLOAT_FRAMES = re.compile(r"^(\s*Frames\s*:\s*)(\d+)\.0+\s*$", re.MULTILINE | re.IGNORECASE)


def readable_copy(path: Path, tmp_path: Path) -> Path:
    """The file itself, or a copy with a float ``Frames: 46.0`` written as ``Frames: 46``."""
    text = path.read_text()
    if not _FLOAT_FRAMES.search(text):
        return path
    out = tmp_path / path.name
    out.write_text(_FLOAT_FRAMES.sub(r"\g<1>\g<2>", text, count=1))
    return out


def literal_frame_time(path: Path) -> float:
    return float(re.search(r"Frame\s+Time\s*:\s*(\S+)", path.read_text(), re.IGNORECASE).group(1))


def matrices(quats_wxyz: np.ndarray) -> np.ndarray:
    q = np.asarray(quats_wxyz, dtype=float)
    return Rotation.from_quat(q.reshape(-1, 4)[:, [1, 2, 3, 0]]).as_matrix().reshape(*q.shape[:-1], 3, 3)


def rel(a, b) -> float:
    a, b = np.asarray(a, float), np.asarray(b, float)
    return float(np.abs(a - b).max() / max(np.abs(b).max(), 1.0)) if a.size else 0.0


@needs_data
@pytest.mark.skipif("MOTIONVAR_BVH_DIR" in os.environ, reason="$MOTIONVAR_BVH_DIR points to other files")
def test_all_35_files_present():
    assert len(FILES) == 35, IDS


@needs_data
@pytest.mark.parametrize("path", FILES, ids=IDS)
def test_matches_pybvh(path, tmp_path):
    pybvh = pytest.importorskip("pybvh", reason="pybvh is not installed (pip install -e '.[crosscheck]')")
    ours = read_bvh(path)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            theirs = pybvh.read_bvh_file(readable_copy(path, tmp_path), warn_on_world_up_disagreement=False)
    except ValueError as exc:
        if "position channels on non-root joints" in str(exc):
            pytest.skip(f"pybvh: {exc}".split(" (got")[0] + " (checked with bvhio)")
        raise
    sk = ours.skeleton
    joints = [n for n in theirs.nodes if not n.is_end_site()]
    assert [n.name for n in joints] == list(sk.names)
    index = {n.name: j for j, n in enumerate(joints)}
    assert [index[n.parent.name] if n.parent is not None else -1 for n in joints] == list(sk.parents)
    assert rel(np.array([n.offset for n in joints]), sk.offsets) <= 1e-9
    ends = {index[n.parent.name]: n.offset for n in theirs.nodes if n.is_end_site()}
    assert sorted(ends) == sorted(sk.end_sites)
    assert all(rel(ends[j], sk.end_sites[j]) <= 1e-9 for j in ends)
    assert list(theirs.euler_orders) == list(sk.rotation_orders)
    assert sk.position_channels == (True,) + (False,) * (len(joints) - 1)
    assert theirs.frame_count == ours.n_frames
    # pybvh snaps a frame time within 1e-4 of 1/N to 1/N (0.008333 -> 1/120); ours keeps the file's value
    assert abs(1.0 / ours.fps - literal_frame_time(path)) <= 1e-15
    assert abs(theirs.frame_time * ours.fps - 1.0) <= 1e-4
    assert rel(theirs.root_pos, ours.root_pos) <= 1e-9
    assert rel(matrices(ours.rotations), theirs.to_rotmat()[1]) <= 1e-9
    assert rel(ours.positions(), theirs.joint_positions()) <= 1e-9


def bvhio_joints(container):
    """(joint, parent index) in file order (depth first)."""
    out, stack = [], [(container.Root, -1)]
    while stack:
        joint, parent = stack.pop()
        out.append((joint, parent))
        stack.extend((child, len(out) - 1) for child in reversed(joint.Children))
    return out


@needs_data
@pytest.mark.parametrize("path", FILES, ids=IDS)
def test_matches_bvhio(path, tmp_path):
    bvhio = pytest.importorskip("bvhio", reason="bvhio is not installed (pip install -e '.[crosscheck]')")
    ours = read_bvh(path)
    sk = ours.skeleton
    container = bvhio.readAsBvh(str(readable_copy(path, tmp_path)))
    joints = bvhio_joints(container)
    assert [j.Name for j, _ in joints] == list(sk.names)
    assert [p for _, p in joints] == list(sk.parents)
    assert rel(np.array([list(j.Offset) for j, _ in joints]), sk.offsets) <= 1e-6
    orders = ["".join(c[0].upper() for c in j.Channels if c.lower().endswith("rotation")) for j, _ in joints]
    assert orders == list(sk.rotation_orders)
    has_pos = tuple(any(c.lower().endswith("position") for c in j.Channels) for j, _ in joints)
    assert has_pos == sk.position_channels
    assert container.FrameCount == ours.n_frames and abs(container.FrameTime * ours.fps - 1.0) <= 1e-6
    keys = [j.Keyframes for j, _ in joints]
    quats = np.array([[[k.Rotation.w, k.Rotation.x, k.Rotation.y, k.Rotation.z] for k in ks] for ks in keys])
    pos = np.array([[list(k.Position) for k in ks] for ks in keys]).transpose(1, 0, 2)
    assert rel(matrices(quats.transpose(1, 0, 2)), matrices(ours.rotations)) <= 2e-6
    assert rel(pos[:, 0], ours.root_pos) <= 1e-6
    moving = np.flatnonzero(has_pos[1:]) + 1
    if len(moving):
        assert rel(pos[:, moving], ours.translations[:, moving]) <= 1e-6
