"""The BVH reader and writer (motionvar.io.bvh): known values, the writer, and bad input named by file and line."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest
from bvh_toy import FRAMES, HEADER, line_of, same_rotations, small_bvh
from scipy.spatial.transform import Rotation

from motionvar.core import Motion, Skeleton, cmu_skeleton
from motionvar.core import quaternions as Q
from motionvar.io import BVHError, read_bvh, write_bvh


def test_read_small_file_values(tmp_path):
    m = read_bvh(small_bvh(tmp_path), scale=2.0)
    sk = m.skeleton
    assert sk.names == ("Hips", "Chest", "Arm", "Leg")
    assert sk.parents.tolist() == [-1, 0, 1, 0]
    assert sk.rotation_orders == ("ZYX", "ZXY", "XYZ", "YXZ")
    assert sk.position_channels == (True, False, True, False)
    assert np.allclose(sk.offsets, 2 * np.array([[0, 0, 0], [0, 10, 0], [5, 0, 0], [2, -3, 0]]))
    assert set(sk.end_sites) == {2, 3}
    assert np.allclose(sk.end_sites[2], [8, 0, 0]) and np.allclose(sk.end_sites[3], [0, -16, 0])
    assert m.n_frames == 3 and m.fps == pytest.approx(50.0)
    assert np.allclose(m.root_pos, 2 * FRAMES[:, :3])
    # Arm's position channels are x, z, y in the file; translations are x, y, z
    assert np.allclose(m.translations[:, 2], 2 * FRAMES[:, [9, 11, 10]])
    assert np.isnan(m.translations[:, [0, 1, 3]]).all()
    cols = {0: (slice(3, 6), "ZYX"), 1: (slice(6, 9), "ZXY"), 2: (slice(12, 15), "XYZ"), 3: (slice(15, 18), "YXZ")}
    for j, (c, order) in cols.items():
        ref = Rotation.from_euler(order, FRAMES[:, c], degrees=True).as_quat(scalar_first=True)
        assert same_rotations(m.rotations[:, j], ref, 1e-12)
    # wrapped angles (350 -> 359 -> 3, 359 -> 1) give sign-continuous quaternions
    assert np.all(np.sum(m.rotations[1:] * m.rotations[:-1], axis=-1) > 0)
    step = np.degrees(Q.qangle(m.rotations[1:], m.rotations[:-1]))
    assert step[:, 1].max() < 15 and step[:, 3].max() < 10


@pytest.mark.parametrize("fmt", ["%.6f", "%r", "%.25g", "%.3e"])
def test_frame_values_are_loadtxts_bit_for_bit(fmt):
    """The frame reader (pandas' C parser) gives np.loadtxt's values exactly: six decimals as
    BVH writers use, shortest round-trip reprs, more digits than a double holds, exponents;
    blank and whitespace-only lines skipped, tabs and surrounding spaces as separators."""
    from motionvar.io.bvh import _frame_values

    rng = np.random.default_rng(4)
    x = (rng.standard_normal(6000) * 10.0 ** rng.integers(-8, 8, 6000)).reshape(-1, 6)
    lines = [" \t".join(fmt % float(v) for v in row) for row in x]
    lines[3], lines[7] = "  " + lines[3] + "  ", ""
    lines.insert(10, "   ")
    ours = _frame_values("\n".join(lines))
    ref = np.loadtxt(lines, dtype=float, comments=None, ndmin=2)
    assert ours.shape == ref.shape == (len(x) - 1, 6)
    assert np.array_equal(ours, ref)


def test_root_without_position_channels(tmp_path):
    header = HEADER.replace(
        "OFFSET 0 0 0\n  CHANNELS 6 Xposition Yposition Zposition Zrotation Yrotation Xrotation",
        "OFFSET 1 2 3\n  CHANNELS 3 Zrotation Yrotation Xrotation",
    )
    path = small_bvh(tmp_path, header, FRAMES[:, 3:])
    m = read_bvh(path)
    assert m.skeleton.position_channels[0] is False
    assert np.allclose(m.root_pos, [1, 2, 3])
    write_bvh(tmp_path / "out.bvh", m)
    assert np.allclose(read_bvh(tmp_path / "out.bvh").positions(), m.positions(), atol=1e-5)
    moved = replace(m, root_pos=m.root_pos + 1.0)
    with pytest.raises(ValueError, match="no position channels"):
        write_bvh(tmp_path / "moved.bvh", moved)
    assert not (tmp_path / "moved.bvh").exists()


def test_float_frames_header_and_crlf(tmp_path):
    text = HEADER.replace("Frames: 3", "Frames: 3.0").replace("\n", "\r\n")
    m = read_bvh(small_bvh(tmp_path, text))
    assert m.n_frames == 3


def test_round_trip_small_file_reproduces_layout(tmp_path):
    m = read_bvh(small_bvh(tmp_path))
    out = tmp_path / "out.bvh"
    write_bvh(out, m)
    m2 = read_bvh(out)
    assert m2.skeleton.names == m.skeleton.names
    assert m2.skeleton.rotation_orders == m.skeleton.rotation_orders
    assert m2.skeleton.position_channels == m.skeleton.position_channels
    assert {j: o.tolist() for j, o in m2.skeleton.end_sites.items()} == {
        j: o.tolist() for j, o in m.skeleton.end_sites.items()
    }
    assert np.allclose(m2.positions(), m.positions(), atol=1e-5)
    assert same_rotations(m2.rotations, m.rotations, 1e-6)
    assert np.allclose(m2.translations, m.translations, atol=1e-6, equal_nan=True)
    channels = [line.split() for line in out.read_text().splitlines() if "CHANNELS" in line]
    assert channels[2] == [
        "CHANNELS",
        "6",
        "Xposition",
        "Yposition",
        "Zposition",
        "Xrotation",
        "Yrotation",
        "Zrotation",
    ]
    assert channels[3] == ["CHANNELS", "3", "Yrotation", "Xrotation", "Zrotation"]


def test_write_scale_is_cm_per_file_unit(tmp_path):
    m = read_bvh(small_bvh(tmp_path), scale=3.0)
    write_bvh(tmp_path / "units.bvh", m, scale=3.0)
    again = read_bvh(tmp_path / "units.bvh")  # file units, as in the original
    assert np.allclose(again.root_pos, FRAMES[:, :3], atol=1e-6)
    assert np.allclose(again.skeleton.offsets, read_bvh(tmp_path / "s.bvh").skeleton.offsets)


def test_round_trip_random_cmu_motion(tmp_path):
    rng = np.random.default_rng(0)
    sk = cmu_skeleton()
    T = 40
    rot = Q.qnormalize(rng.normal(size=(T, sk.n_joints, 4)))
    m = Motion(sk, rng.normal(size=(T, 3)) * 50, rot, fps=120.0)
    write_bvh(tmp_path / "cmu.bvh", m, fmt="%.8f")
    m2 = read_bvh(tmp_path / "cmu.bvh")
    assert m2.fps == pytest.approx(120.0, rel=1e-9)
    assert np.abs(m2.positions() - m.positions()).max() < 1e-4
    assert same_rotations(m2.rotations, m.rotations, 1e-6)


def test_non_depth_first_joint_order_writes_correct_channels(tmp_path):
    # breadth-first order: A(root), B, C children of A, D child of B
    sk = Skeleton(
        names=("A", "B", "C", "D"),
        parents=np.array([-1, 0, 0, 1]),
        offsets=np.array([[0, 0, 0], [0, 1, 0], [1, 0, 0], [0, 2, 0]], dtype=float),
        rotation_orders=("ZYX", "XYZ", "ZXY", "YZX"),
    )
    rng = np.random.default_rng(1)
    m = Motion(sk, rng.normal(size=(5, 3)), Q.qnormalize(rng.normal(size=(5, 4, 4))), fps=30.0)
    write_bvh(tmp_path / "bfs.bvh", m)
    m2 = read_bvh(tmp_path / "bfs.bvh")
    assert m2.skeleton.names == ("A", "B", "D", "C")  # depth-first in the file
    perm = [sk.index(n) for n in m2.skeleton.names]
    assert np.abs(m2.positions() - m.positions()[:, perm]).max() < 1e-5
    assert m2.skeleton.rotation_orders == tuple(sk.rotation_orders[j] for j in perm)


def test_write_is_atomic_on_bad_motion(tmp_path):
    m = read_bvh(small_bvh(tmp_path))
    target = tmp_path / "keep.bvh"
    target.write_text("old")
    bad = m.copy()
    bad.rotations[1, 2] = np.nan
    with pytest.raises(ValueError, match="non-finite"):
        write_bvh(target, bad)
    assert target.read_text() == "old"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["keep.bvh", "s.bvh"]


def _drop_line(text: str, needle: str) -> str:
    return "\n".join(line for line in text.splitlines() if needle not in line) + "\n"


GOOD_BODY = "\n".join(" ".join(f"{v:g}" for v in row) for row in FRAMES) + "\n"


FULL = HEADER + GOOD_BODY


FRAME1 = line_of(FULL, "Frame Time") + 1


def _bad_value(text: str, value: str) -> str:
    lines = text.splitlines()
    toks = lines[FRAME1].split()
    toks[4] = value
    lines[FRAME1] = " ".join(toks)
    return "\n".join(lines) + "\n"


BAD_CASES = {
    # name: (text, expected line, message fragment)
    "missing HIERARCHY": (FULL.replace("HIERARCHY\n", "HIERARCH\n"), 1, "missing HIERARCHY"),
    "empty file": ("", 1, "missing HIERARCHY"),
    "missing MOTION": (FULL.replace("MOTION\n", ""), line_of(FULL, "Frames:") - 1, "missing MOTION"),
    "missing MOTION at end of file": (HEADER.split("MOTION")[0], line_of(FULL, "MOTION") - 1, "missing MOTION"),
    "unclosed brace": (
        FULL.replace("      }\n    }\n  }\n", "      }\n    }\n", 1),
        line_of(FULL, "MOTION") - 1,
        "unbalanced braces",
    ),
    "extra closing brace": (FULL.replace("}\nMOTION", "}\n}\nMOTION"), line_of(FULL, "MOTION"), "unbalanced braces"),
    "frame with too few values": (
        FULL.replace(GOOD_BODY.splitlines()[1], GOOD_BODY.splitlines()[1].rsplit(" ", 1)[0]),
        FRAME1 + 1,
        "frame 2 has 17 values",
    ),
    "frame with too many values": (
        FULL.replace(GOOD_BODY.splitlines()[2], GOOD_BODY.splitlines()[2] + " 7"),
        FRAME1 + 2,
        "frame 3 has 19 values",
    ),
    "non-numeric value": (_bad_value(FULL, "abc"), FRAME1 + 1, "non-numeric value 'abc'"),
    "non-finite value": (_bad_value(FULL, "nan"), FRAME1 + 1, "non-finite value 'nan'"),
    "fewer frames than Frames:": (FULL.replace("Frames: 3", "Frames: 5"), FRAME1 + 2, "ends after 3 frames"),
    "more frames than Frames:": (FULL.replace("Frames: 3", "Frames: 2"), FRAME1 + 2, "more frame lines"),
    "zero frames": (HEADER.replace("Frames: 3", "Frames: 0"), line_of(FULL, "Frames:"), "zero frames"),
    "fractional Frames:": (FULL.replace("Frames: 3", "Frames: 2.5"), line_of(FULL, "Frames:"), "bad 'Frames:'"),
    "missing Frames:": (_drop_line(FULL, "Frames:"), line_of(FULL, "Frames:"), "missing 'Frames:'"),
    "missing Frame Time": (_drop_line(FULL, "Frame Time"), line_of(FULL, "Frame Time"), "missing 'Frame Time:'"),
    "zero Frame Time": (
        FULL.replace("Frame Time: 0.02", "Frame Time: 0"),
        line_of(FULL, "Frame Time"),
        "bad 'Frame Time:'",
    ),
    "CHANNELS count not a number": (
        FULL.replace("CHANNELS 3 Zrotation Xrotation", "CHANNELS three Zrotation Xrotation"),
        line_of(FULL, "CHANNELS 3 Zrotation Xrotation"),
        "bad CHANNELS count 'three'",
    ),
    "CHANNELS count too large": (
        FULL.replace("CHANNELS 3 Zrotation Xrotation", "CHANNELS 4 Zrotation Xrotation"),
        line_of(FULL, "JOINT Arm"),
        "bad CHANNELS count",
    ),
    "CHANNELS count too small": (
        FULL.replace("CHANNELS 3 Zrotation Xrotation", "CHANNELS 2 Zrotation Xrotation"),
        line_of(FULL, "CHANNELS 3 Zrotation Xrotation"),
        "followed by more channel names",
    ),
    "two rotation channels": (
        FULL.replace("CHANNELS 3 Yrotation Xrotation Zrotation", "CHANNELS 2 Yrotation Xrotation"),
        line_of(FULL, "CHANNELS 3 Yrotation"),
        "unsupported CHANNELS 2",
    ),
    "position channels only": (
        FULL.replace("CHANNELS 3 Yrotation Xrotation Zrotation", "CHANNELS 3 Xposition Yposition Zposition"),
        line_of(FULL, "CHANNELS 3 Yrotation"),
        "three rotation channels",
    ),
    "repeated rotation axis": (
        FULL.replace("CHANNELS 3 Yrotation Xrotation Zrotation", "CHANNELS 3 Yrotation Xrotation Xrotation"),
        line_of(FULL, "CHANNELS 3 Yrotation"),
        "unsupported CHANNELS",
    ),
    "joint without OFFSET": (_drop_line(FULL, "OFFSET 2 -3 0"), line_of(FULL, "JOINT Leg"), "no OFFSET"),
    "bad OFFSET": (
        FULL.replace("OFFSET 2 -3 0", "OFFSET 2 -3 x"),
        line_of(FULL, "OFFSET 2 -3 0"),
        "OFFSET needs 3 numbers",
    ),
    "duplicate joint name": (FULL.replace("JOINT Leg", "JOINT Chest"), line_of(FULL, "JOINT Leg"), "appears twice"),
    "second ROOT": (FULL.replace("}\nMOTION", "}\nROOT Other\nMOTION"), line_of(FULL, "MOTION"), "second ROOT"),
}


@pytest.mark.parametrize("case", list(BAD_CASES))
def test_bad_input_names_file_and_line(tmp_path, case):
    text, line, fragment = BAD_CASES[case]
    path = tmp_path / "bad.bvh"
    path.write_text(text)
    with pytest.raises(BVHError) as info:
        read_bvh(path)
    msg = str(info.value)
    assert msg.startswith(f"{path}:{line}: "), msg
    assert fragment in msg, msg
    assert info.value.line == line


def test_missing_file_names_it(tmp_path):
    with pytest.raises(BVHError, match="nothere.bvh"):
        read_bvh(tmp_path / "nothere.bvh")
