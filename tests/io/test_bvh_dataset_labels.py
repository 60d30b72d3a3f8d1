"""A labelled folder of BVH files: labels as users write them, mixed rigs and re-rooting, clips that are one primitive each."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from bvh_dataset_toy import MAPS, cmu_motion, labels_csv

from motionvar.core import CMU_UNIT_CM, JointMap, Motion, Skeleton, cmu_joint_map, cmu_skeleton
from motionvar.core import quaternions as Q
from motionvar.io import (
    DatasetError,
    import_bvh_folder,
    load_dataset,
    load_joint_map,
    read_bvh,
    save_dataset,
    write_bvh,
)


def test_behaviour_vocabulary_is_the_segmenters():
    from motionvar.io.bvh_dataset import BEHAVIOURS
    from motionvar.prep import SEGMENTERS

    assert sorted(BEHAVIOURS) == sorted(SEGMENTERS)


def test_aliases_map_the_source_words_and_keep_them(folder):
    labels_csv(
        folder,
        "file,subject,behaviour,style\na.bvh,02,walk_step,normal\nb.bvh,02,sidestep_left,sexy\n"
        "sub/c.bvh,07,jog,normal\n",
    )
    _, meta = import_bvh_folder(
        folder,
        "labels.csv",
        unit_cm=CMU_UNIT_CM,
        behaviour_aliases={
            "walk_step": "walk",
            "sidestep_left": {"behaviour": "sidestep", "variant": "left"},
            "jog": "run",
        },
        style_aliases={"sexy": "female"},
        neutral_style="normal",
    )
    assert meta["behaviour"].tolist() == ["walk", "sidestep", "run"]
    assert meta["variant"].tolist() == ["", "left", ""]
    assert meta["style"].tolist() == ["neutral", "female", "neutral"]
    assert meta["source_behaviour"].tolist() == ["walk_step", "sidestep_left", "jog"]
    assert meta["source_style"].tolist() == ["normal", "sexy", "normal"]


def test_behaviours_no_paper_uses_are_left_out_unread(folder, caplog):
    (folder / "broken.bvh").write_text("not a BVH file")  # left out, so never parsed
    labels_csv(
        folder,
        "file,subject,behaviour,style\na.bvh,02,walk,x\nb.bvh,02,jump,x\nbroken.bvh,02,kick,x\nsub/c.bvh,02,jump,x\n",
    )
    with caplog.at_level("WARNING"):
        motions, meta = import_bvh_folder(folder, "labels.csv", unit_cm=CMU_UNIT_CM)
    assert meta["clip_id"].tolist() == ["a"] and len(motions) == 1
    assert "left out 3 clips of behaviours no paper uses: jump 2, kick 1" in caplog.text


LABEL_WORD_ERRORS = {
    # name: (labels CSV rows, import keyword arguments, expected message)
    "no behaviour left": (
        "a.bvh,02,walk_step,x\n",
        {},
        "no clip has a behaviour the papers use (idle, pick, place, run, sidestep, walk); found "
        "walk_step: map the source's words with behaviour_aliases",
    ),
    "alias to an unknown behaviour": (
        "a.bvh,02,walk_step,x\n",
        {"behaviour_aliases": {"walk_step": "stroll"}},
        "behaviour_aliases: walk_step -> 'stroll' is not a behaviour the papers use",
    ),
    "malformed alias": (
        "a.bvh,02,walk_step,x\n",
        {"behaviour_aliases": {"walk_step": {"variant": "l"}}},
        "behaviour_aliases: walk_step: expected a behaviour or",
    ),
    "variant clash": (
        "a.bvh,02,walk,x,\nb.bvh,02,side_l,x,right\n",
        {"behaviour_aliases": {"side_l": {"behaviour": "sidestep", "variant": "left"}}},
        "labels.csv:3: variant 'right' contradicts behaviour_aliases (side_l -> variant 'left')",
    ),
    "neutral twice": (
        "a.bvh,02,walk,normal\n",
        {"neutral_style": "normal", "style_aliases": {"normal": "calm"}},
        "neutral_style 'normal' is also in style_aliases (-> 'calm')",
    ),
    "bad mixed_rigs": ("a.bvh,02,walk,x\n", {"mixed_rigs": "majority"}, "mixed_rigs: 'majority' is not one of"),
}


@pytest.mark.parametrize("case", list(LABEL_WORD_ERRORS))
def test_bad_label_words_are_named(folder, case):
    rows, kw, expected = LABEL_WORD_ERRORS[case]
    header = "file,subject,behaviour,style" + (",variant" if case == "variant clash" else "")
    labels_csv(folder, header + "\n" + rows)
    with pytest.raises(DatasetError) as info:
        import_bvh_folder(folder, "labels.csv", unit_cm=CMU_UNIT_CM, **kw)
    assert expected in str(info.value)


def test_unused_aliases_are_logged(folder, caplog):
    with caplog.at_level("WARNING"):
        import_bvh_folder(folder, "labels.csv", unit_cm=CMU_UNIT_CM, behaviour_aliases={"walk_stepp": "walk"})
    assert "aliases that match no clip: walk_stepp" in caplog.text


def _other_rig(path: Path) -> None:
    sk = Skeleton(names=("Hips", "Spine"), parents=np.array([-1, 0]), offsets=np.array([[0, 0, 0], [0, 10.0, 0]]))
    write_bvh(path, Motion(sk, np.zeros((3, 3)), Q.qidentity((3, 2)), fps=30.0))


def test_mixed_rigs_leave_the_minority_out(folder, caplog):
    _other_rig(folder / "other.bvh")
    labels_csv(folder, "file,subject,behaviour,style\na.bvh,02,walk,x\nother.bvh,02,walk,x\nb.bvh,02,walk,x\n")
    with caplog.at_level("WARNING"):
        motions, meta = import_bvh_folder(folder, "labels.csv", unit_cm=CMU_UNIT_CM, joint_map=cmu_joint_map())
    assert meta["clip_id"].tolist() == ["a", "b"] and len(motions) == 2
    assert "left out 1 clips on another rig than the other 2 (2 joints, not 31): other.bvh" in caplog.text


def test_mixed_rigs_without_a_majority_stop(folder):
    _other_rig(folder / "other.bvh")
    labels_csv(folder, "file,subject,behaviour,style\na.bvh,02,walk,x\nother.bvh,02,walk,x\n")
    with pytest.raises(DatasetError, match="no rig holds a majority of the clips"):
        import_bvh_folder(folder, "labels.csv", unit_cm=CMU_UNIT_CM)


def _floor_rooted_folder(tmp_path: Path) -> Path:
    from bvh_files import floor_rooted

    d = tmp_path / "floor"
    d.mkdir()
    for seed in range(2):
        write_bvh(d / f"w{seed}.bvh", floor_rooted(translations=True, seed=seed))
    (d / "labels.csv").write_text("file,subject,behaviour,style\nw0.bvh,1,walk,n\nw1.bvh,1,walk,n\n")
    return d


def test_import_reroots_at_the_joint_maps_hips(tmp_path, caplog):
    """A ROOT below which the pelvis hangs (Bandai's joint_Root): joint 0 becomes the hips."""
    from bvh_files import floor_rooted

    d = _floor_rooted_folder(tmp_path)
    with caplog.at_level("INFO"):
        motions, _ = import_bvh_folder(d, "labels.csv", unit_cm=1.0, joint_map=cmu_joint_map())
    assert "re-rooting every clip at the joint map's hips Hips (the BVH ROOT is Ground)" in caplog.text
    for seed, m in enumerate(motions):
        ref = read_bvh(d / f"w{seed}.bvh")
        assert m.skeleton.names == cmu_skeleton().names
        assert np.abs(m.positions() - ref.positions()[:, 1:]).max() < 1e-6
        assert np.abs(m.positions() - floor_rooted(True, seed=seed).positions()[:, 1:]).max() < 1e-3  # file precision


def test_joint_map_groups_listing_a_joint_above_the_hips(tmp_path):
    d = _floor_rooted_folder(tmp_path)
    jm = cmu_joint_map()
    jm = JointMap(jm.joints, {**jm.groups, "upper_body": ("Ground",) + jm.groups["upper_body"]}, origin="my.yaml")
    with pytest.raises(DatasetError, match=r"\(my.yaml\): groups list \['Ground'\], above the hips Hips; .*delete"):
        import_bvh_folder(d, "labels.csv", unit_cm=1.0, joint_map=jm)


def test_hips_whose_ancestors_have_other_children_is_refused(folder):
    jm = cmu_joint_map()
    jm = JointMap({**jm.joints, "hips": "LowerBack"}, {})
    with pytest.raises(DatasetError, match="hips = LowerBack is not the BVH ROOT and cannot make LowerBack the root"):
        import_bvh_folder(folder, "labels.csv", unit_cm=CMU_UNIT_CM, joint_map=jm)


STEP_NAMES = {"0": "walk_start", 2: "walk_rightStance", "3": "walk_leftStance"}  # YAML may give int keys


def _step_labels(folder: Path, labels: tuple[str, str, str]) -> Path:
    return labels_csv(
        folder,
        "file,subject,behaviour,style,primitive_label\n"
        + "".join(f"{f},02,walk_step,x,{k}\n" for f, k in zip(["a.bvh", "b.bvh", "sub/c.bvh"], labels)),
    )


def test_primitive_labels_give_primitive_and_whole_clip_segments(folder):
    _step_labels(folder, ("0", " 2", "3"))
    motions, meta = import_bvh_folder(
        folder,
        "labels.csv",
        unit_cm=CMU_UNIT_CM,
        drop_first_frame=True,
        behaviour_aliases={"walk_step": "walk"},
        primitive_labels={"column": "primitive_label", "names": STEP_NAMES},
    )
    assert meta["primitive"].tolist() == ["walk_start", "walk_rightStance", "walk_leftStance"]
    assert meta["segments"].tolist() == [f"{p}:0:11" for p in meta["primitive"]]  # 12 frames, first dropped
    assert all(m.n_frames == 11 for m in motions)
    assert meta["primitive_label"].tolist() == ["0", " 2", "3"]  # the source's label kept
    _, plain = import_bvh_folder(folder, "labels.csv", unit_cm=CMU_UNIT_CM, behaviour_aliases={"walk_step": "walk"})
    assert "segments" not in plain.columns and plain["primitive"].tolist() == ["", "", ""]


def test_whole_clip_segments_feed_ground_truth_prep(folder, tmp_path):
    """prep.use_ground_truth_segments keeps each clip whole (through the packed dataset, as
    in the workflow); min_primitive_s still drops short ones."""
    from motionvar.prep import PrepOptions, preprocess_dataset

    write_bvh(folder / "b.bvh", cmu_motion(1, frames=60), scale=CMU_UNIT_CM)
    _step_labels(folder, ("0", "2", "3"))
    motions, meta = import_bvh_folder(
        folder,
        "labels.csv",
        unit_cm=CMU_UNIT_CM,
        behaviour_aliases={"walk_step": "walk"},
        primitive_labels={"column": "primitive_label", "names": STEP_NAMES},
    )
    opts = PrepOptions(use_ground_truth_segments=True, min_primitive_s=0.2)  # 12 frames at 120 fps = 0.1 s: dropped
    save_dataset(tmp_path / "packed", motions, meta)
    out = preprocess_dataset(load_dataset(tmp_path / "packed"), cmu_joint_map(), opts)
    assert out.metadata["source_clip"].tolist() == ["b"]
    assert out.metadata[["primitive", "start_frame", "stop_frame"]].values.tolist() == [["walk_rightStance", 0, 60]]
    assert out.motions[0].n_frames == 60
    assert sorted(out.dropped["clip_id"]) == ["a", "c"] and set(out.dropped["reason"]) == {"too short"}


PRIMITIVE_LABEL_ERRORS = {
    # name: (labels of a, b, c; option; expected message)
    "unmapped label": (
        ("0", "2", "7"),
        {"column": "primitive_label", "names": STEP_NAMES},
        "labels.csv:4: primitive_label '7' is not in primitive_labels.names "
        "(0 -> walk_start, 2 -> walk_rightStance, 3 -> walk_leftStance)",
    ),
    "empty label": (
        ("0", "", "3"),
        {"column": "primitive_label", "names": STEP_NAMES},
        "labels.csv:3: primitive_label '' is not in primitive_labels.names",
    ),
    "absent column": (
        ("0", "2", "3"),
        {"column": "step", "names": STEP_NAMES},
        "labels.csv: primitive_labels.column 'step' is not a column",
    ),
    "no names": (("0", "2", "3"), {"column": "primitive_label", "names": {}}, "primitive_labels.names: expected"),
    "bad name": (
        ("0", "2", "3"),
        {"column": "primitive_label", "names": {"0": "walk:start"}},
        "primitive_labels.names: {'0': 'walk:start'} are not primitive names",
    ),
    "missing key": (("0", "2", "3"), {"names": STEP_NAMES}, "primitive_labels: expected {column: ..., names:"),
}


@pytest.mark.parametrize("case", list(PRIMITIVE_LABEL_ERRORS))
def test_bad_primitive_labels_are_named(folder, case):
    labels, option, expected = PRIMITIVE_LABEL_ERRORS[case]
    _step_labels(folder, labels)
    with pytest.raises(DatasetError) as info:
        import_bvh_folder(
            folder, "labels.csv", unit_cm=CMU_UNIT_CM, behaviour_aliases={"walk_step": "walk"}, primitive_labels=option
        )
    assert expected in str(info.value), str(info.value)


@pytest.mark.parametrize("column", ["segments", "primitive"])
def test_primitive_labels_with_the_csvs_own_segments_or_primitive(folder, column):
    labels_csv(
        folder,
        f"file,subject,behaviour,style,primitive_label,{column}\n"
        "a.bvh,02,walk,x,0,walk_start:0:5\nb.bvh,02,walk,x,2,\nsub/c.bvh,02,walk,x,3,\n",
    )
    with pytest.raises(DatasetError, match=rf"labels.csv: has a (filled )?'{column}' column and primitive_labels"):
        import_bvh_folder(
            folder,
            "labels.csv",
            unit_cm=CMU_UNIT_CM,
            primitive_labels={"column": "primitive_label", "names": STEP_NAMES},
        )


def test_real_dfki_config_maps_every_label(tmp_path):
    """config/real/dfki_markerless.yaml's primitive_labels: every clip mapped, each whole."""
    import yaml

    folder = MAPS.parents[2] / "shared/data/real/dfki_markerless"  # ../shared/data/real of the repo root
    if not folder.is_dir():
        pytest.skip(f"{folder} absent")
    cfg = yaml.safe_load((MAPS.parent / "real/dfki_markerless.yaml").read_text())["datasets"]["dfki_markerless"]
    motions, meta = import_bvh_folder(
        folder,
        "labels.csv",
        unit_cm=0.1,
        joint_map=load_joint_map(MAPS / "dfki_markerless.yaml"),
        behaviour_aliases=cfg["behaviour_aliases"],
        primitive_labels=cfg["primitive_labels"],
    )
    assert meta["primitive"].value_counts().to_dict() == {
        "walk_rightStance": 127,
        "walk_leftStance": 103,
        "walk_start": 83,
        "walk_end": 83,
    }
    assert meta["segments"].tolist() == [f"{p}:0:{m.n_frames}" for p, m in zip(meta["primitive"], motions)]
