"""Sanity gates on imported motion: the generator's humans and the real sets pass; a
floor point named as the hips, a wrong unit, a wrong frame time, mislabelled behaviours
and NaN fail, each with a message that says what to change."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from motionvar.core import JointMap, cmu_joint_map
from motionvar.io import import_bvh_folder, load_joint_map
from motionvar.io.plausibility import PlausibilityError, check_plausibility, plausibility_gate

ROOT = Path(__file__).resolve().parents[2]
REAL = ROOT.parent / "shared/data/real"
MAPS = ROOT / "config/joint_maps"


@pytest.fixture(scope="module")
def synthetic():
    from motionvar.synth import SynthSpec, generate_dataset

    spec = SynthSpec(subjects=1, walks_per_style=1, turning_walks=2, idle_clips=1, idle_duration_s=5.0)
    return generate_dataset(spec)


def test_synthetic_humans_pass(synthetic):
    motions, meta = synthetic
    report = check_plausibility(motions, meta, cmu_joint_map())
    assert report.problems == []
    m = report.measures
    assert set(m["behaviour"]) == {"idle", "pick", "place", "run", "sidestep", "walk"}
    assert 80 < m["pelvis_height_cm"].median() < 105 and 70 < m["leg_length_cm"].median() < 95
    assert "speed walk" in report.summary()


def _meta(motions, behaviour="walk"):
    return pd.DataFrame({"clip_id": [f"c{i}" for i in range(len(motions))], "behaviour": behaviour})


def _walks(synthetic):
    motions, meta = synthetic
    return [m for m, b in zip(motions, meta["behaviour"]) if b == "walk"]


def test_a_floor_point_named_as_hips_fails(synthetic):
    """A joint map whose hips is at floor level (Bandai's joint_Root): the pelvis check names it."""
    walks = _walks(synthetic)
    jm = cmu_joint_map()
    floor = JointMap({**jm.joints, "hips": "LeftToeBase"}, jm.groups, origin="config/joint_maps/mine.yaml")
    problems = check_plausibility(walks, _meta(walks), floor).problems
    n = len(walks)
    assert any(
        p.startswith("pelvis (joint map hips = LeftToeBase) is ")
        and f"{n}/{n} clips outside" in p
        and "a standing human pelvis is 60-130 cm high: check the joint map's 'hips' (config/joint_maps/mine.yaml)" in p
        for p in problems
    ), problems


def test_a_wrong_unit_fails_with_the_unit_that_fits(synthetic):
    walks = [replace(m, skeleton=m.skeleton.scaled(0.01), root_pos=m.root_pos * 0.01) for m in _walks(synthetic)]
    problems = check_plausibility(walks, _meta(walks), cmu_joint_map(), unit_cm=0.01).problems
    assert "check unit_cm (now 0.01 cm per file unit; about 1" in problems[0]
    assert any(p.startswith("pelvis") and "see the leg length" in p for p in problems)
    assert len(problems) == 2  # the speeds follow from the unit: not checked until it is right


def test_a_wrong_frame_time_and_mislabelled_behaviours_fail(synthetic):
    motions, meta = synthetic
    idle = [m for m, b in zip(motions, meta["behaviour"]) if b == "idle"]
    problems = check_plausibility(idle, _meta(idle, "run"), cmu_joint_map()).problems
    assert problems == [p for p in problems if p.startswith("run clips move at")] and len(problems) == 1
    assert "check the labels' behaviour column" in problems[0]
    slow = [replace(m, fps=5.0) for m in idle]
    problems = check_plausibility(slow, _meta(slow, "idle"), cmu_joint_map()).problems
    assert problems[0].startswith("frame rate 5 fps in 1/1 clips") and "'Frame Time'" in problems[0]


def test_nan_fails(synthetic):
    walk = _walks(synthetic)[0]
    rot = walk.rotations.copy()
    rot[3, 4] = np.nan
    problems = check_plausibility([replace(walk, rotations=rot)], _meta([walk]), cmu_joint_map()).problems
    assert problems[0].startswith("NaN or infinite positions in 1/1 clips (c0)")


def test_gate_raises_one_line_and_can_be_switched_off(synthetic, caplog):
    walks = _walks(synthetic)
    jm = cmu_joint_map()
    floor = JointMap({**jm.joints, "hips": "LeftToeBase"}, jm.groups)
    with pytest.raises(PlausibilityError) as info:
        plausibility_gate(walks, _meta(walks), floor)
    assert "\n" not in str(info.value) and "plausibility_check: false" in str(info.value)
    assert "joint_map: null, the CMU 31-joint rig" in str(info.value)
    with caplog.at_level("WARNING"):
        assert plausibility_gate(walks, _meta(walks), floor, enabled=False) is None
    assert "plausibility checks switched off" in caplog.text


# ---------------------------------------------------------------- the real sets

BANDAI_ALIASES = {
    "sidestep_left": {"behaviour": "sidestep", "variant": "left"},
    "sidestep_right": {"behaviour": "sidestep", "variant": "right"},
}
REAL_SETS = {
    # name: (unit_cm, joint map, import keywords, clips kept)
    "xia": (5.644444, None, {}, 16),
    "bandai_ds1": (1.0, "bandai.yaml", {"neutral_style": "normal", "behaviour_aliases": BANDAI_ALIASES}, 75),
    "dfki_markerless": (0.1, "dfki_markerless.yaml", {"behaviour_aliases": {"walk_step": "walk"}}, 396),
}


def _real(name: str):
    folder = REAL / name
    if not folder.is_dir():
        pytest.skip(f"{folder} absent")
    unit, jm_file, kw, _ = REAL_SETS[name]
    jm = load_joint_map(MAPS / jm_file) if jm_file else cmu_joint_map()
    return folder, unit, jm, kw


@pytest.mark.parametrize("name", list(REAL_SETS))
def test_real_sets_import_as_given_and_pass(name):
    folder, unit, jm, kw = _real(name)
    motions, meta = import_bvh_folder(folder, "labels.csv", unit, joint_map=jm, **kw)
    assert len(motions) == REAL_SETS[name][3]
    assert set(meta["behaviour"]) <= {"walk", "run", "sidestep"}
    assert jm.index(motions[0].skeleton, "hips") == 0  # Bandai: re-rooted at Hips
    report = check_plausibility(motions, meta, jm, unit)
    assert report.problems == [], report.problems
    assert 80 < report.measures["pelvis_height_cm"].median() < 100


def test_real_bandai_with_the_floor_root_as_hips_fails(tmp_path):
    folder, unit, jm, kw = _real("bandai_ds1")
    text = (MAPS / "bandai.yaml").read_text().replace("hips: Hips", "hips: joint_Root")
    wrong = tmp_path / "bandai_root.yaml"
    wrong.write_text(text)
    jm = load_joint_map(wrong)
    motions, meta = import_bvh_folder(folder, "labels.csv", unit, joint_map=jm, **kw)
    problems = check_plausibility(motions, meta, jm, unit).problems
    assert any(
        p.startswith("pelvis (joint map hips = joint_Root) is ")
        and "75/75 clips outside 60-130 cm" in p
        and f"check the joint map's 'hips' ({wrong})" in p
        for p in problems
    ), problems
