"""Atomic writes and model files: outputs get an ordinary file's mode, a failed or killed
save leaves nothing behind, models round-trip as .npz + .json (no pickle)."""

from __future__ import annotations

import os
import stat

import numpy as np
import pandas as pd
import pytest

from motionvar.core import Motion, cmu_skeleton
from motionvar.core.quaternions import qidentity
from motionvar.io import save_dataset, write_bvh
from motionvar.io.atomic import atomic_write, stale_temp_files
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
