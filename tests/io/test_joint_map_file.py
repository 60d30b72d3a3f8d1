"""YAML joint maps: loading, errors, and each shipped map against a real file of its rig."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from bvh_files import real_bvh_dir

from motionvar.core import cmu_joint_map, cmu_skeleton
from motionvar.core.extremities import foot_points
from motionvar.core.reroot import reroot
from motionvar.io import JointMapError, load_joint_map, read_bvh

MAPS = Path(__file__).resolve().parents[2] / "config/joint_maps"
# map -> real files of its rig (relative to the shared BVH folder)
RIG_FILES = {
    "cmu": ["cmu/02_01.bvh", "xia/old_01_000.bvh"],
    "cmu_3dsmax": ["cmu/131_01.bvh"],
    "bandai": ["bandai/dataset-1_walk_normal_001.bvh", "bandai/dataset-1_walk-left_normal_001.bvh"],
    "dfki_mosi": ["dfki/sidestep_001_4.bvh", "dfki/walk_001_1_leftStance_43_86.bvh"],
    "dfki_markerless": ["dfki/markerless_steps/101_0to51_1.bvh"],
    "reactidle": ["../real/reactidle_idle/000_genuine.bvh", "../real/reactidle_idle/003_acted.bvh"],
}


def test_every_shipped_map_has_a_rig_file_listed():
    assert sorted(p.stem for p in MAPS.glob("*.yaml")) == sorted(RIG_FILES)


def test_cmu_yaml_equals_cmu_joint_map():
    assert load_joint_map(MAPS / "cmu.yaml") == cmu_joint_map()


@pytest.mark.parametrize("name,rel", [(n, f) for n, fs in RIG_FILES.items() for f in fs])
def test_map_fits_its_rig(name, rel):
    path = real_bvh_dir() / rel
    if not path.is_file():
        pytest.skip(f"{path} absent")
    jm = load_joint_map(MAPS / f"{name}.yaml")
    m = reroot(read_bvh(path), jm.joints["hips"])  # as imported: the hips joint is the root
    sk = m.skeleton
    jm.validate(sk, source=name)
    # the groups partition the rig: every joint listed once
    listed = [n for g in jm.groups.values() for n in g]
    assert sorted(listed) == sorted(sk.names)
    # anatomy: left joints on the performer's left, the chain ordered upwards
    pos = m.positions()
    g = {s: pos[:, jm.index(sk, s)] for s in jm.joints}
    feet = foot_points(m, jm, pos)  # a rig without toe joints: the ankles' End Sites
    g["left_toe"], g["right_toe"] = feet[:, 0, 1], feet[:, 1, 1]
    forward = g["left_toe"] - g["left_ankle"] + g["right_toe"] - g["right_ankle"]
    forward[:, 1] = 0.0
    left = np.cross([0.0, 1.0, 0.0], forward)  # y up: left = up x forward

    def frac_left(a: str, b: str) -> float:
        return float(np.mean(np.sum((g[a] - g[b]) * left, axis=-1) > 0))

    def frac_above(a: str, b: str) -> float:  # above, or at the same point (ReActIdle's spine sits on its pelvis)
        return float(np.mean((g[a][:, 1] > g[b][:, 1]) | np.isclose(g[a], g[b]).all(axis=-1)))

    for part in ("hip", "shoulder", "hand", "knee"):
        if jm.has(f"left_{part}"):
            assert frac_left(f"left_{part}", f"right_{part}") > 0.9, part
    for upper, lower in [
        ("head", "neck"),
        ("neck", "chest"),
        ("chest", "spine"),
        ("spine", "hips"),
        ("left_hip", "left_knee"),
        ("right_knee", "right_ankle"),
        ("left_elbow", "left_hand"),
    ]:
        if jm.has(lower):
            assert frac_above(upper, lower) > 0.9, (upper, lower)


def _write(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "map.yaml"
    path.write_text(text)
    return path


CMU_TEXT = (MAPS / "cmu.yaml").read_text()
BAD_MAPS = {
    "invalid YAML": ("joints: {hips: Hips\ngroups: [", "not valid YAML at line"),
    "not a mapping": ("- Hips\n- Spine\n", "expected a mapping with 'joints'"),
    "unknown key": (CMU_TEXT + "extra: 1\n", "unknown keys ['extra']"),
    "missing semantic joint": (CMU_TEXT.replace("  head: Head\n", ""), "missing semantic joints ['head']"),
    "missing required, hands optional": (
        CMU_TEXT.replace("  head: Head\n", "").replace("  left_hand: LeftHand\n", ""),
        "missing semantic joints ['head']",
    ),
    "unknown semantic joint": (
        CMU_TEXT.replace("  head: Head\n", "  head: Head\n  tail: Tail\n"),
        "unknown semantic joints ['tail']",
    ),
    "non-string joint": (CMU_TEXT.replace("  head: Head\n", "  head: [Head]\n"), "non-empty strings: ['head']"),
    "unknown group": (CMU_TEXT.replace("  legs:", "  feet:"), "unknown groups ['feet']"),
    "group not a list": (
        CMU_TEXT.replace("  upper_body: [LowerBack, Spine, Spine1, Neck, Neck1, Head]", "  upper_body: Spine"),
        "groups ['upper_body'] must be lists",
    ),
    "joint in two groups": (
        CMU_TEXT.replace("upper_body: [LowerBack,", "upper_body: [LeftArm, LowerBack,"),
        "listed more than once in groups: ['LeftArm']",
    ),
}


@pytest.mark.parametrize("case", list(BAD_MAPS))
def test_bad_map_names_file(tmp_path, case):
    text, fragment = BAD_MAPS[case]
    path = _write(tmp_path, text)
    with pytest.raises(JointMapError) as info:
        load_joint_map(path)
    assert str(info.value).startswith(f"{path}: ")
    assert fragment in str(info.value)


def test_a_map_may_leave_out_the_hands_and_toes(tmp_path):
    """Hands and toes are optional (a rig may end at the forearm and the foot); the map says
    which it lacks."""
    text = "".join(
        line + "\n" for line in CMU_TEXT.splitlines() if not line.startswith(("  left_hand:", "  right_toe:"))
    )
    jm = load_joint_map(_write(tmp_path, text))
    assert jm.lacking == ("left_hand", "right_toe") and jm.has("right_hand", "left_toe")
    with pytest.raises(ValueError, match="has no left_hand: the rig lacks it"):
        jm.index(cmu_skeleton(), "left_hand")


def test_missing_map_file(tmp_path):
    with pytest.raises(JointMapError, match="nomap.yaml: cannot read"):
        load_joint_map(tmp_path / "nomap.yaml")


def test_map_that_does_not_fit_a_skeleton(tmp_path):
    path = real_bvh_dir() / "cmu/131_01.bvh"
    if not path.is_file():
        pytest.skip(f"{path} absent")
    with pytest.raises(ValueError, match="joints not in the skeleton"):
        load_joint_map(MAPS / "cmu.yaml").validate(read_bvh(path).skeleton, source="cmu.yaml")
