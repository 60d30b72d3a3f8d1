"""A labelled folder of BVH files (motionvar.io.bvh_dataset): import, packing, export, bad input and the real sets."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from bvh_dataset_toy import MAPS, cmu_motion, labels_csv
from bvh_files import real_bvh_dir

from motionvar.core import CMU_UNIT_CM, JointMap, Motion, Skeleton, cmu_joint_map
from motionvar.core import quaternions as Q
from motionvar.io import (
    DatasetError,
    export_clip_bvh,
    import_bvh_folder,
    load_dataset,
    load_joint_map,
    read_bvh,
    save_dataset,
    write_bvh,
)
from motionvar.io.bvh_dataset import bvh_files


def test_import_folder(folder):
    motions, meta = import_bvh_folder(folder, "labels.csv", unit_cm=CMU_UNIT_CM, joint_map=cmu_joint_map())
    assert list(meta.columns) == [
        "clip_id",
        "subject",
        "behaviour",
        "style",
        "variant",
        "primitive",
        "source_file",
        "source_behaviour",
        "source_style",
        "take",
    ]
    assert meta["source_behaviour"].tolist() == ["walk", "walk", "run"]
    assert meta["clip_id"].tolist() == ["a", "b", "c"]
    assert meta["subject"].tolist() == ["02", "02", "07"]
    assert meta["style"].tolist() == ["neutral", "proud", ""]
    assert meta["variant"].tolist() == ["v1", "", ""]
    assert meta["primitive"].tolist() == ["", "", ""]
    assert meta["take"].tolist() == ["1", "2", "3"]
    assert meta["source_file"].tolist() == [str(folder / f) for f in ["a.bvh", "b.bvh", "sub/c.bvh"]]
    for seed, m in enumerate(motions):
        ref = cmu_motion(seed)
        assert np.allclose(m.skeleton.offsets, ref.skeleton.offsets, atol=1e-4)  # back in cm
        assert np.abs(m.positions() - ref.positions()).max() < 1e-4


def test_drop_first_frame(folder):
    full, _ = import_bvh_folder(folder, folder / "labels.csv", unit_cm=CMU_UNIT_CM)
    dropped, _ = import_bvh_folder(folder, folder / "labels.csv", unit_cm=CMU_UNIT_CM, drop_first_frame=True)
    for a, b in zip(full, dropped):
        assert b.n_frames == a.n_frames - 1
        assert np.allclose(b.rotations, a.rotations[1:]) and np.allclose(b.root_pos, a.root_pos[1:])


def test_import_then_pack_and_load(folder, tmp_path):
    motions, meta = import_bvh_folder(folder, "labels.csv", unit_cm=CMU_UNIT_CM)
    save_dataset(tmp_path / "packed", motions, meta)
    ds = load_dataset(tmp_path / "packed")
    assert ds.metadata["clip_id"].tolist() == ["a", "b", "c"]
    assert np.abs(ds.by_id("c").positions() - motions[2].positions()).max() < 1e-3  # float32 rotations


def test_export_clip_bvh_writes_cm(folder, tmp_path):
    motions, _ = import_bvh_folder(folder, "labels.csv", unit_cm=CMU_UNIT_CM)
    export_clip_bvh(motions[0], tmp_path / "clip.bvh")
    back = read_bvh(tmp_path / "clip.bvh")  # no scale: the file is in cm
    assert np.abs(back.positions() - motions[0].positions()).max() < 1e-4


LABEL_ERRORS = {
    # name: (labels CSV text, expected message after "{csv}")
    "missing required column": ("file,subject,style\na.bvh,02,neutral\n", ": missing required column 'behaviour'"),
    "labelled file missing": (
        "file,subject,behaviour,style\na.bvh,02,walk,x\nzz.bvh,02,walk,x\n",
        ":3: labelled file 'zz.bvh' does not exist",
    ),
    "empty file entry": ("file,subject,behaviour,style\n,02,walk,x\n", ":2: empty 'file' entry"),
    "no rows": ("file,subject,behaviour,style\n", ": no clips listed"),
    "blank CSV": ("", ": not a readable CSV"),
}


@pytest.mark.parametrize("case", list(LABEL_ERRORS))
def test_bad_labels_csv_names_csv(folder, case):
    text, expected = LABEL_ERRORS[case]
    csv = labels_csv(folder, text)
    with pytest.raises(DatasetError) as info:
        import_bvh_folder(folder, csv, unit_cm=CMU_UNIT_CM)
    assert str(info.value).startswith(f"{csv}{expected}"), str(info.value)


def test_missing_csv(folder):
    with pytest.raises(DatasetError, match="nolabels.csv: labels CSV not found"):
        import_bvh_folder(folder, "nolabels.csv", unit_cm=CMU_UNIT_CM)


def test_empty_folder(tmp_path):
    (tmp_path / "labels.csv").write_text("file,subject,behaviour,style\na.bvh,1,walk,x\n")
    with pytest.raises(DatasetError, match=rf"{tmp_path}: no .bvh files"):
        import_bvh_folder(tmp_path, "labels.csv", unit_cm=1.0)


def test_missing_folder(tmp_path):
    with pytest.raises(DatasetError, match="BVH folder not found"):
        import_bvh_folder(tmp_path / "nope", "labels.csv", unit_cm=1.0)


def test_duplicate_clip_ids(folder):
    write_bvh(folder / "sub/a.bvh", cmu_motion(5), scale=CMU_UNIT_CM)
    csv = labels_csv(folder, "file,subject,behaviour,style\na.bvh,02,walk,x\nb.bvh,02,walk,x\nsub/a.bvh,02,walk,x\n")
    with pytest.raises(DatasetError, match=r"duplicate clip ids \['a'\] \(file stems at lines 2, 4\)"):
        import_bvh_folder(folder, csv, unit_cm=CMU_UNIT_CM)


def test_topology_mismatch_names_the_file(folder):
    sk = Skeleton(names=("Hips", "Spine"), parents=np.array([-1, 0]), offsets=np.array([[0, 0, 0], [0, 10.0, 0]]))
    write_bvh(folder / "other.bvh", Motion(sk, np.zeros((3, 3)), Q.qidentity((3, 2)), fps=30.0))
    csv = labels_csv(folder, "file,subject,behaviour,style\na.bvh,02,walk,x\nother.bvh,02,walk,x\n")
    with pytest.raises(DatasetError, match=rf"{folder / 'other.bvh'}: skeleton topology or channel layout differs"):
        import_bvh_folder(folder, csv, unit_cm=CMU_UNIT_CM, mixed_rigs="error")


def test_channel_layout_mismatch_names_the_file(folder):
    m = cmu_motion(9)
    sk = m.skeleton
    orders = ("ZXY",) + sk.rotation_orders[1:]
    m.skeleton = Skeleton(sk.names, sk.parents, sk.offsets, sk.end_sites, orders, sk.position_channels)
    write_bvh(folder / "zxy.bvh", m, scale=CMU_UNIT_CM)
    csv = labels_csv(folder, "file,subject,behaviour,style\na.bvh,02,walk,x\nzxy.bvh,02,walk,x\n")
    with pytest.raises(DatasetError, match="zxy.bvh: skeleton topology or channel layout differs"):
        import_bvh_folder(folder, csv, unit_cm=CMU_UNIT_CM, mixed_rigs="error")


def test_joint_map_that_does_not_fit(folder):
    jm = cmu_joint_map()
    bad = JointMap(joints={**jm.joints, "head": "Skull"}, groups=jm.groups)
    with pytest.raises(DatasetError, match=r"joint map for .*a.bvh: joints not in the skeleton \['head=Skull'\]"):
        import_bvh_folder(folder, "labels.csv", unit_cm=CMU_UNIT_CM, joint_map=bad)


def test_bad_bvh_in_folder_names_file_and_line(folder):
    (folder / "a.bvh").write_text("HIERARCHY\nROOT Hips\n{\n")
    with pytest.raises(ValueError, match=rf"{folder / 'a.bvh'}:3: unbalanced braces"):
        import_bvh_folder(folder, "labels.csv", unit_cm=CMU_UNIT_CM)


@pytest.mark.parametrize("entry", ["../x.bvh", "sub/../../x.bvh", "absolute"])
def test_labelled_file_outside_the_folder_is_refused(folder, entry):
    """The data rule tracks the folder's files only: a row naming one outside it would be
    imported and never rerun when edited. One line naming the CSV, its line and the path."""
    outside = folder.parent / "x.bvh"
    write_bvh(outside, cmu_motion(4), scale=CMU_UNIT_CM)
    name = str(outside) if entry == "absolute" else entry
    csv = labels_csv(folder, f"file,subject,behaviour,style\na.bvh,02,walk,x\n{name},02,walk,x\n")
    with pytest.raises(DatasetError) as info:
        import_bvh_folder(folder, csv, unit_cm=CMU_UNIT_CM)
    assert str(info.value) == (
        f"{csv}:3: labelled file {name!r} lies outside the dataset folder {folder}: move it into the "
        f"folder (the run tracks only the folder's files)"
    )


def test_labelled_file_that_is_not_bvh_is_refused(folder):
    (folder / "notes.txt").write_text("HIERARCHY\n")
    csv = labels_csv(folder, "file,subject,behaviour,style\na.bvh,02,walk,x\nnotes.txt,02,walk,x\n")
    with pytest.raises(DatasetError, match=r"labels.csv:3: labelled file 'notes.txt' is not a .bvh file"):
        import_bvh_folder(folder, csv, unit_cm=CMU_UNIT_CM)


def test_bvh_suffix_in_any_case_imports(tmp_path):
    """A folder of N.BVH files (as some capture software writes them) imports; clip ids drop the suffix."""
    d = tmp_path / "caps"
    (d / "sub").mkdir(parents=True)
    for seed, rel in enumerate(["1.BVH", "2.BVH", "sub/3.Bvh"]):
        write_bvh(d / rel, cmu_motion(seed), scale=CMU_UNIT_CM)
    (d / "notes.txt").write_text("not motion\n")
    (d / "labels.csv").write_text("file,subject,behaviour,style\n1.BVH,a,walk,x\n2.BVH,a,walk,x\nsub/3.Bvh,b,run,x\n")
    motions, meta = import_bvh_folder(d, "labels.csv", unit_cm=CMU_UNIT_CM)
    assert meta["clip_id"].tolist() == ["1", "2", "3"] and len(motions) == 3
    assert bvh_files(d) == [d / "1.BVH", d / "2.BVH", d / "sub/3.Bvh"]


def _real(sub: str) -> Path:
    path = real_bvh_dir() / sub
    if not path.is_dir():
        pytest.skip(f"{path} absent")
    return path


def test_real_markerless_steps_folder(tmp_path):
    """Han Du's markerless walk primitives: mm, 50 fps, primitive label = last number of the name."""
    folder = _real("dfki/markerless_steps")
    files = sorted(p.name for p in folder.glob("*.bvh"))
    rows = [f"{f},{f.split('_')[0]},walk,,{f.rsplit('_', 1)[1][:-4]}" for f in files]
    csv = tmp_path / "labels.csv"
    csv.write_text("file,subject,behaviour,style,primitive\n" + "\n".join(rows) + "\n")
    jm = load_joint_map(MAPS / "dfki_markerless.yaml")
    motions, meta = import_bvh_folder(folder, csv, unit_cm=0.1, joint_map=jm)
    assert len(motions) == len(files) == 21
    assert sorted(set(meta["primitive"])) == ["0", "1", "2", "3", "4", "5"]
    assert all(m.fps == pytest.approx(50.0) for m in motions)
    hips = np.concatenate([m.positions()[:, jm.index(m.skeleton, "hips"), 1] for m in motions])
    assert 50 < np.median(hips) < 110  # pelvis height in cm


def test_real_cmu_folder_drops_tpose_and_rejects_other_rig(tmp_path):
    folder = _real("cmu")
    csv = tmp_path / "labels.csv"
    csv.write_text(
        "file,subject,behaviour,style\n02_01.bvh,02,walk,neutral\n02_03.bvh,02,run,neutral\n09_01.bvh,09,run,neutral\n"
    )
    motions, meta = import_bvh_folder(
        folder, csv, unit_cm=CMU_UNIT_CM, drop_first_frame=True, joint_map=cmu_joint_map()
    )
    assert [m.n_frames for m in motions] == [343, 173, 148]
    # the cgspeed T-pose frame is gone: the first remaining frame is close to the next one
    raw = read_bvh(folder / "02_01.bvh", scale=CMU_UNIT_CM)
    jump_raw = np.degrees(Q.qangle(raw.rotations[1], raw.rotations[0])).max()
    jump_new = np.degrees(Q.qangle(motions[0].rotations[1], motions[0].rotations[0])).max()
    assert jump_raw > 45 > 10 > jump_new
    csv.write_text(csv.read_text() + "131_01.bvh,131,walk,jackson\n")
    with pytest.raises(DatasetError, match="131_01.bvh: skeleton topology"):
        import_bvh_folder(folder, csv, unit_cm=CMU_UNIT_CM, mixed_rigs="error")
    assert isinstance(meta, pd.DataFrame)


def test_joint_map_file_naming_absent_joints_names_the_yaml_file(folder, tmp_path):
    import yaml

    from motionvar.io.joint_map_file import load_joint_map

    jm = cmu_joint_map()
    path = tmp_path / "my_rig.yaml"
    path.write_text(yaml.safe_dump({"joints": {**jm.joints, "head": "Skull"}}))
    with pytest.raises(DatasetError, match=r"joint map for .*a.bvh \(.*my_rig.yaml\): joints not in the skeleton"):
        import_bvh_folder(folder, "labels.csv", unit_cm=CMU_UNIT_CM, joint_map=load_joint_map(path))
