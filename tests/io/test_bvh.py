"""BVH reader and writer: known values, layouts, round trips, every kind of bad input,
and all real files of ../shared/data/bvh (skipped when absent)."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest
from bvh_files import chain_bvh, provenance, real_bvh_dir, real_bvh_files, unit_cm
from scipy.spatial.transform import Rotation

from motionvar.core import Motion, Skeleton, cmu_skeleton
from motionvar.core import quaternions as Q
from motionvar.io import BVHError, read_bvh, write_bvh

HEADER = """HIERARCHY
ROOT Hips
{
  OFFSET 0 0 0
  CHANNELS 6 Xposition Yposition Zposition Zrotation Yrotation Xrotation
  JOINT Chest
  {
    OFFSET 0 10 0
    CHANNELS 3 Zrotation Xrotation Yrotation
    JOINT Arm
    {
      OFFSET 5 0 0
      CHANNELS 6 Xposition Zposition Yposition Xrotation Yrotation Zrotation
      End Site
      {
        OFFSET 4 0 0
      }
    }
  }
  JOINT Leg
  {
    OFFSET 2 -3 0
    CHANNELS 3 Yrotation Xrotation Zrotation
    End Site
    {
      OFFSET 0 -8 0
    }
  }
}
MOTION
Frames: 3
Frame Time: 0.02
"""
# 18 channels: Hips 6, Chest 3, Arm 6 (positions x, z, y), Leg 3. Angles include wrapped ones.
FRAMES = np.array(
    [
        [1, 90, 2, 10, 20, 30, 350, 5, 15, 5.5, 0.25, -0.5, 30, 40, 50, 0, 0, 359],
        [2, 91, 3, 11, 21, 31, 359, 6, 16, 5.6, 0.25, -0.4, 31, 41, 51, 1, 2, 1],
        [3, 92, 4, 12, 22, 32, 3, 7, 17, 5.7, 0.25, -0.3, 32, 42, 52, 2, 4, 3],
    ],
    dtype=float,
)


def small_bvh(tmp_path: Path, header: str = HEADER, frames: np.ndarray | str = FRAMES, name: str = "s.bvh") -> Path:
    body = frames if isinstance(frames, str) else "\n".join(" ".join(f"{v:g}" for v in row) for row in frames) + "\n"
    path = tmp_path / name
    path.write_text(header + body)
    return path


def line_of(text: str, needle: str, nth: int = 0) -> int:
    """1-based number of the nth line containing ``needle``."""
    return [i + 1 for i, line in enumerate(text.splitlines()) if needle in line][nth]


def same_rotations(a: np.ndarray, b: np.ndarray, atol: float) -> bool:
    return bool(np.max(Q.qangle(a, b)) < atol)


# ---------------------------------------------------------------- known values


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


# ---------------------------------------------------------------- writer


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


# ---------------------------------------------------------------- bad input


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


# ---------------------------------------------------------------- real files

REAL = real_bvh_files()
needs_real = pytest.mark.skipif(not REAL, reason=f"real BVH folder {real_bvh_dir()} absent")
REAL_PARAMS = [pytest.param(p, id=p.relative_to(real_bvh_dir()).as_posix()) for p in REAL] or [
    pytest.param(None, marks=needs_real, id="absent")
]


@needs_real
def test_every_real_file_is_in_provenance():
    prov = provenance()
    assert sorted(p.name for p in REAL) == sorted(prov)


@pytest.mark.parametrize("path", REAL_PARAMS)
def test_real_file_reads_plausibly_and_round_trips(tmp_path, path):
    fps, n_joints, n_frames = provenance()[path.name]
    unit = unit_cm(path)
    m = read_bvh(path, scale=unit)
    sk = m.skeleton
    assert sk.n_joints == n_joints and m.n_frames == n_frames
    assert m.fps == pytest.approx(fps, rel=1e-3)
    assert np.all(np.isfinite(m.rotations)) and np.all(np.isfinite(m.root_pos))
    assert np.allclose(np.linalg.norm(m.rotations, axis=-1), 1.0, atol=1e-9)
    assert np.all(np.sum(m.rotations[1:] * m.rotations[:-1], axis=-1) >= 0)  # sign-continuous
    pos = m.positions()
    assert np.all(np.isfinite(pos))
    # rigid bones (no position channels) keep their rest length on every frame
    rigid = [j for j in range(1, n_joints) if m.translations is None or np.isnan(m.translations[:, j]).all()]
    bones = np.linalg.norm(pos[:, rigid] - pos[:, sk.parents[rigid]], axis=-1)
    assert np.allclose(bones, sk.bone_lengths()[rigid], atol=1e-6 * max(1.0, sk.bone_lengths().max()))
    # the body spans a human height in cm (joints only; the head top is an End Site)
    extent = np.median(pos[..., 1].max(axis=1) - pos[..., 1].min(axis=1))
    assert 110 < extent < 200, extent

    out = tmp_path / "rt.bvh"
    write_bvh(out, m, scale=unit)
    m2 = read_bvh(out, scale=unit)
    assert m2.skeleton.names == sk.names and np.array_equal(m2.skeleton.parents, sk.parents)
    assert m2.skeleton.rotation_orders == sk.rotation_orders
    assert m2.skeleton.position_channels == sk.position_channels
    assert m2.n_frames == m.n_frames and m2.fps == pytest.approx(m.fps, rel=1e-9)
    assert np.abs(m2.positions() - pos).max() < 1e-4
    assert same_rotations(m2.rotations, m.rotations, 1e-4)


@needs_real
def test_real_wrapped_angles_give_the_unwrapped_rotations():
    """Aalto stores angles wrapped to 0..360 (channels jump by ~360 degrees between
    frames): the rotations read from the wrapped channels equal those of the unwrapped
    channels on every frame, and are sign-continuous."""
    (path,) = [p for p in REAL if p.parent.name == "aalto"]
    m = read_bvh(path)
    sk = m.skeleton
    lines = path.read_text().splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith("Frame Time")) + 1
    raw = np.loadtxt(lines[start:])
    assert np.sum(np.abs(np.diff(raw, axis=0)) > 300) > 10  # the file really has wrapped angles
    n_ch = [6 if p else 3 for p in sk.position_channels]
    rot_cols = np.array([s + n - 3 + np.arange(3) for s, n in zip(np.cumsum([0] + n_ch[:-1]), n_ch)])
    unwrapped = np.degrees(np.unwrap(np.radians(raw[:, rot_cols]), axis=0))
    assert np.abs(unwrapped).max() > 360  # unwrapping changed something
    for j, order in enumerate(sk.rotation_orders):
        ref = Q.euler_to_quat(unwrapped[:, j], order)
        assert same_rotations(m.rotations[:, j], ref, 1e-9)
    assert np.all(np.sum(m.rotations[1:] * m.rotations[:-1], axis=-1) >= 0)


# ---- edge cases a user met (issue: real data end to end) ------------------------------


@pytest.mark.parametrize("depth", [1_000, 5_000])
def test_deeply_nested_hierarchy_reads_without_recursion(tmp_path, depth):
    path = tmp_path / "deep.bvh"
    path.write_text(chain_bvh(depth))
    m = read_bvh(path)
    assert m.skeleton.n_joints == depth + 1
    assert m.skeleton.parents[-1] == depth - 1


def test_file_without_motion_stops_at_the_first_error_with_bounded_memory(tmp_path):
    """A hierarchy followed by megabytes of text and no MOTION line: the reader reports
    the first unexpected token instead of tokenising the whole file first."""
    import tracemalloc

    head = HEADER[: HEADER.index("MOTION")]
    junk = ("1.0 2.0 3.0 4.0 5.0 6.0 7.0 8.0 9.0\n") * 200_000  # ~7 MB of numbers
    path = tmp_path / "nomotion.bvh"
    path.write_text(head + junk)
    size = path.stat().st_size
    tracemalloc.start()
    with pytest.raises(BVHError, match="missing MOTION"):
        read_bvh(path)
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    assert peak < 12 * size, f"peak {peak / 1e6:.0f} MB for a {size / 1e6:.0f} MB file"


def test_utf8_byte_order_mark_is_accepted(tmp_path):
    path = small_bvh(tmp_path)
    path.write_bytes(b"\xef\xbb\xbf" + path.read_bytes())
    assert read_bvh(path).skeleton.names[0] == "Hips"


def test_latin1_bytes_give_a_clear_error_or_read_with_the_encoding(tmp_path):
    path = small_bvh(tmp_path)
    text = path.read_text().replace("JOINT Chest", "JOINT Brustkörper")
    path.write_bytes(text.encode("latin-1"))
    with pytest.raises(BVHError, match=rf"{path.name}:{line_of(text, 'Brustkörper')}: byte 0xf6 is not valid utf-8"):
        read_bvh(path)
    assert read_bvh(path, encoding="latin-1").skeleton.names[1] == "Brustkörper"


def test_ascii_bytes_and_decoded_text_read_alike(tmp_path):
    """A pure-ASCII file's frames are parsed from its bytes; one with a byte-order mark, CRLF
    line ends or other characters, from the decoded text: the same values."""
    path = small_bvh(tmp_path)
    ref = read_bvh(path)
    for name, data in (
        ("bom.bvh", b"\xef\xbb\xbf" + path.read_bytes()),
        ("crlf.bvh", path.read_bytes().replace(b"\n", b"\r\n")),
        ("umlaut.bvh", path.read_text().replace("JOINT Chest", "JOINT Brustkörper").encode()),
    ):
        target = tmp_path / name
        target.write_bytes(data)
        other = read_bvh(target)
        assert np.array_equal(other.rotations, ref.rotations) and np.array_equal(other.root_pos, ref.root_pos)


def test_latin1_byte_in_the_frames_names_its_line(tmp_path):
    """One byte per character but not ASCII (latin-1): a non-numeric byte in a frame line is
    reported at its line, as in a UTF-8 file."""
    path = small_bvh(tmp_path)
    text = path.read_text()
    lines = text.split("\n")
    k = line_of(text, "Frame Time") + 1  # the 2nd frame line (1-based)
    lines[k] = lines[k].replace(" ", " \xb5", 1)
    path.write_bytes("\n".join(lines).encode("latin-1"))
    with pytest.raises(BVHError, match=rf"{path.name}:{k + 1}: frame 2: non-numeric value"):
        read_bvh(path, encoding="latin-1")


@pytest.mark.parametrize("frame_time", ["1e-320", "1e-5", "2.0"])
def test_frame_time_giving_an_implausible_rate_is_rejected(tmp_path, frame_time):
    path = small_bvh(tmp_path, header=HEADER.replace("Frame Time: 0.02", f"Frame Time: {frame_time}"))
    with pytest.raises(BVHError, match=rf"{path.name}:\d+: 'Frame Time: {frame_time}' means .* frames per second"):
        read_bvh(path)
