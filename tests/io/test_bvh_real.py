"""The BVH reader on the real files, and the edge cases users met (deep hierarchies, no motion, encodings, implausible frame rates)."""

from __future__ import annotations

import numpy as np
import pytest
from bvh_files import chain_bvh, provenance, real_bvh_dir, real_bvh_files, unit_cm
from bvh_toy import HEADER, line_of, same_rotations, small_bvh

from motionvar.core import quaternions as Q
from motionvar.io import BVHError, read_bvh, write_bvh

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
