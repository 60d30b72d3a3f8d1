"""Atomic writes and model files: outputs get an ordinary file's mode, a failed or killed
save leaves nothing behind, only regular files are replaced, several files are written as
one transaction (AtomicFiles), models round-trip as .npz + .json (no pickle) and a file
that cannot be read is a ValueError naming it."""

from __future__ import annotations

import os
import stat
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from motionvar.core import Motion, cmu_skeleton
from motionvar.core.quaternions import qidentity
from motionvar.io import DatasetError, load_dataset, save_dataset, write_bvh
from motionvar.io.atomic import TMP_SUFFIX, AtomicFiles, TargetError, TargetExistsError, atomic_write, stale_temp_files
from motionvar.io.model_file import load_model, load_torch_model, save_model, save_torch_model


def _mode(path) -> int:
    return stat.S_IMODE(os.stat(path).st_mode)


def _expected_mode() -> int:
    umask = os.umask(0)
    os.umask(umask)
    return 0o666 & ~umask


def _motion(n: int = 4) -> Motion:
    sk = cmu_skeleton()
    return Motion(sk, np.zeros((n, 3)), np.broadcast_to(qidentity(), (n, sk.n_joints, 4)).copy(), 120.0)


def test_saved_dataset_bvh_and_model_files_are_readable_by_all(tmp_path):
    save_dataset(tmp_path / "ds", [_motion()], pd.DataFrame({"clip_id": ["a"]}))
    write_bvh(tmp_path / "a.bvh", _motion())
    files = save_model(tmp_path / "m", {"x": np.arange(3)}, {"kind": "toy"})
    for path in [tmp_path / "ds" / "clips.npz", tmp_path / "ds" / "metadata.csv", tmp_path / "a.bvh", *files]:
        assert _mode(path) == _expected_mode(), f"{path.name}: mode {oct(_mode(path))}"


def test_failed_write_leaves_nothing(tmp_path):
    def fail(tmp):
        tmp.write_text("half")
        raise RuntimeError("killed mid-write")

    with pytest.raises(RuntimeError):
        atomic_write(tmp_path / "out.csv", fail)
    assert list(tmp_path.iterdir()) == []


def test_leftovers_of_a_killed_save_are_removed_by_the_next_save(tmp_path):
    """A hard kill cannot run cleanup code: the next write of the same file removes the
    hidden temporary file the killed process left."""
    target = tmp_path / "clips.npz"
    stale = tmp_path / ".clips.npz.abc123.tmp"
    stale.write_bytes(b"partial")
    assert stale_temp_files(target) == [stale]
    atomic_write(target, lambda tmp: tmp.write_bytes(b"complete"))
    assert sorted(p.name for p in tmp_path.iterdir()) == ["clips.npz"]
    assert target.read_bytes() == b"complete"


def test_model_round_trip_and_kind_check(tmp_path):
    arrays = {"w": np.linspace(0, 1, 5), "names": np.array(["a", "b"])}
    save_model(tmp_path / "model.npz", arrays, {"kind": "toy", "n": 5})
    back, settings = load_model(tmp_path / "model", kind="toy")
    np.testing.assert_array_equal(back["w"], arrays["w"])
    assert settings == {"kind": "toy", "n": 5}
    with pytest.raises(ValueError, match=r"model.json: not a saved other"):
        load_model(tmp_path / "model", kind="other")
    with pytest.raises(FileNotFoundError, match=r"missing.npz: model file missing"):
        load_model(tmp_path / "missing")


def test_torch_weights_round_trip_as_a_state_dict(tmp_path):
    import torch

    net = torch.nn.Linear(3, 2)
    save_torch_model(tmp_path / "net", net.state_dict(), {"kind": "linear", "in": 3})
    state, settings = load_torch_model(tmp_path / "net.pt", kind="linear")
    other = torch.nn.Linear(settings["in"], 2)
    other.load_state_dict(state)
    assert torch.equal(other.weight, net.weight)
    (tmp_path / "net.pt").write_bytes(b"not a zip")
    with pytest.raises(ValueError, match=r"net.pt: not a readable torch weights file"):
        load_torch_model(tmp_path / "net")


def test_atomic_write_refuses_what_is_not_a_regular_file(tmp_path):
    """A rename would put a regular file in the place of a pipe or a symlink: refused, and
    the pipe, the link and its target stay as they were."""
    pipe, link, target = tmp_path / "pipe.csv", tmp_path / "link.csv", tmp_path / "target.csv"
    os.mkfifo(pipe)
    target.write_text("target")
    link.symlink_to(target)
    for path, kind in ((pipe, "named pipe"), (link, "symlink"), (tmp_path, "folder")):
        with pytest.raises(TargetError, match=f"is a {kind}, not a regular file"):
            atomic_write(path, lambda tmp: tmp.write_text("new"))
    assert stat.S_ISFIFO(os.lstat(pipe).st_mode) and link.is_symlink() and target.read_text() == "target"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["link.csv", "pipe.csv", "target.csv"]


def test_atomic_files_appear_together_and_a_failed_rename_puts_back_the_first(tmp_path, monkeypatch):
    """Inside AtomicFiles every atomic_write waits for the end of the block; a rename that
    fails after the first put back the first file's earlier content (kept by a hard link)."""
    a, b = tmp_path / "a.txt", tmp_path / "sub" / "b.txt"
    a.write_text("earlier a")
    with pytest.raises(TargetExistsError, match="a.txt: exists"):
        AtomicFiles([a, b])
    with AtomicFiles([a, b], overwrite=True):
        atomic_write(a, lambda tmp: tmp.write_text("new a"))
        save_model(tmp_path / "sub" / "b", {"x": np.arange(2)}, {"kind": "toy"})  # b.npz, b.json: not targets
        atomic_write(b, lambda tmp: tmp.write_text("new b"))
        assert a.read_text() == "earlier a" and not b.exists()
    assert a.read_text() == "new a" and b.read_text() == "new b" and (tmp_path / "sub" / "b.npz").is_file()

    replace = os.replace

    def fail_on_b(src, dst):
        if Path(dst) == b:
            raise OSError(28, "No space left on device")
        replace(src, dst)

    monkeypatch.setattr(os, "replace", fail_on_b)
    with pytest.raises(OSError, match="No space left"):
        with AtomicFiles([a, b], overwrite=True):
            atomic_write(a, lambda tmp: tmp.write_text("newer a"))
            atomic_write(b, lambda tmp: tmp.write_text("newer b"))
    assert a.read_text() == "new a" and b.read_text() == "new b"
    assert not [p for p in tmp_path.rglob(f"*{TMP_SUFFIX}")]


def test_atomic_files_leave_nothing_after_an_error_or_a_missing_file(tmp_path):
    out = tmp_path / "new" / "deep"
    with pytest.raises(KeyboardInterrupt):
        with AtomicFiles([out / "a.txt", out / "b.txt"]):
            atomic_write(out / "a.txt", lambda tmp: tmp.write_text("a"))
            raise KeyboardInterrupt
    assert list(tmp_path.iterdir()) == []  # the folders made for the temporaries are gone too
    with pytest.raises(ValueError, match="not written: .*b.txt"):
        with AtomicFiles([out / "a.txt", out / "b.txt"]):
            atomic_write(out / "a.txt", lambda tmp: tmp.write_text("a"))
    assert list(tmp_path.iterdir()) == []
    files = AtomicFiles([tmp_path / "c.txt"])  # free when checked, taken before the renames
    with pytest.raises(TargetExistsError):
        with files:
            atomic_write(tmp_path / "c.txt", lambda tmp: tmp.write_text("ours"))
            (tmp_path / "c.txt").write_text("someone else's")
    assert (tmp_path / "c.txt").read_text() == "someone else's" and len(list(tmp_path.iterdir())) == 1


def test_unreadable_model_and_dataset_files_are_value_errors_naming_the_file(tmp_path):
    """Truncated or garbled arrays, JSON that is not an object, torch files that are not a
    state_dict of tensors or carry a pickled object, a garbled metadata table."""
    import torch

    files = save_model(tmp_path / "m", {"x": np.arange(1000)}, {"kind": "toy"})
    data = files[0].read_bytes()
    for cut in (data[: len(data) // 2], data[:-30], b"PK\x03\x04" + bytes(200)):
        files[0].write_bytes(cut)
        with pytest.raises(ValueError, match=r"m.npz: not a readable model array file \("):
            load_model(tmp_path / "m")
    files[1].write_text("[1, 2]")
    with pytest.raises(ValueError, match=r"m.json: not a readable model settings file \(a JSON list"):
        load_model(tmp_path / "m")
    save_torch_model(tmp_path / "w", {"weight": torch.zeros(2)}, {"kind": "toy"})
    for payload, reason in (([torch.zeros(2)], "not a state_dict"), ({"f": Path("x")}, "Unsupported global")):
        torch.save(payload, tmp_path / "w.pt")
        with pytest.raises(ValueError, match=f"w.pt: not a readable torch weights file .*{reason}"):
            load_torch_model(tmp_path / "w")
    save_dataset(tmp_path / "ds", [_motion()], pd.DataFrame({"clip_id": ["a"]}))
    (tmp_path / "ds" / "metadata.csv").write_bytes(b"")
    with pytest.raises(DatasetError, match=r"metadata.csv: not a readable metadata table"):
        load_dataset(tmp_path / "ds")
