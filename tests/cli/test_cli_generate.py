"""The motionvar command on the CI models: models, and each paper's command (Ma 2010 walks, Egges 2004 idle, Du 2022 walk and style) with its refusals."""

from __future__ import annotations

import re

import numpy as np
import pytest
from cli_toy import DS, JM, run

from motionvar.cli.main import main
from motionvar.core import cmu_skeleton
from motionvar.io.bvh import read_bvh
from motionvar.ma2010.evaluations.common import PUBLISHED_MAX_STRIDE_ERROR_CM

pytestmark = pytest.mark.usefixtures("one_torch_thread")  # tests/conftest.py


# Foot skating (cm/s, Sec. 7.4's measure: the contact point's speed during detected contacts)
# of a generated walk: the bound the generator's own walks meet (< 1.0,
# tests/metrics/test_metrics_motion.py). The command's default cleanup ("root+feet": the paper's
# root, Sec. 6.3, then every foot in contact pinned by leg IK, [KSG02]) meets it (CI models:
# 0.00 cm/s); the paper's cleanup alone (--cleanup root) pins only the support foot, and the
# other foot of a double support slides: 0.9-2.8 cm/s on the CI models (the CI run's Sec. 7.4
# table: ours 1.3, the example cycles root-solved alike 0.7-2.0; Perlin noise 4-5).
MAX_GENERATED_SKATING_CM_S = 1.0


def _ma2010_model(results):
    from motionvar.ma2010.storage import load_style_variation_model

    return load_style_variation_model(results / DS / "models" / "ma2010" / "style_variation.npz")


def test_models_lists_what_is_fitted_and_what_each_command_takes(results, capsys):
    assert run(results, "models") == 0
    out = capsys.readouterr().out
    assert f"dataset {DS}" in out and "MISSING" not in out
    assert "style left_support_stride " in out and "cm (examples" in out
    assert "subjects: 01, 02, 03" in out
    assert "walking primitives: walk_leftStance, walk_rightStance (not modelled: walk_start, walk_end)" in out
    assert "style old: primitives walk_leftStance" in out and "style neutral: primitives walk_leftStance" in out


def test_models_names_the_snakemake_target_of_a_missing_model(results, tmp_path, capsys):
    (tmp_path / DS / "models").mkdir(parents=True)
    assert main(["models", "--results", str(tmp_path), "--dataset", DS]) == 0
    out = capsys.readouterr().out
    assert f"MISSING {tmp_path / DS / 'models' / 'ma2010' / 'style_variation.npz'}" in out
    assert f"<- snakemake --cores 2 results/{DS}/models/ma2010/style_variation.npz" in out
    assert f"<- snakemake --cores 2 results/{DS}/models/egges2004/idle_model.npz" in out


def test_ma2010_walks_have_the_requested_stride_length_and_few_foot_skating(results, tmp_path, capsys):
    from motionvar.ma2010.examples import root_solver
    from motionvar.ma2010.generate import walk_measures

    saved = _ma2010_model(results)
    stride = float(np.round(saved.model.style_.mean(), 1))  # inside the examples' range: one number, both strides
    assert (
        run(
            results,
            "ma2010",
            "--style",
            f"{stride}",
            "--seconds",
            "6",
            "--variants",
            "2",
            "--seed",
            "3",
            "--out",
            str(tmp_path),
        )
        == 0
    )
    files = sorted(tmp_path.glob("*.bvh"))
    assert [f.name for f in files] == [f"ma2010_{stride:g}_{stride:g}_v1.bvh", f"ma2010_{stride:g}_{stride:g}_v2.bvh"]
    out = capsys.readouterr().out
    assert out.count("measured strides") == 2
    solver = root_solver(saved.model.skeleton_, saved.joint_map)
    motions = [read_bvh(f) for f in files]
    for m in motions:
        assert m.fps == pytest.approx(saved.model.fps_) and m.n_frames == round(6 * m.fps) + 1  # 6 s exactly
        assert m.skeleton.names == saved.model.skeleton_.names  # the dataset's rig
        meas = walk_measures(m, solver)
        for side in ("left", "right"):
            assert abs(meas[f"{side}_support_stride_cm"] - stride) < PUBLISHED_MAX_STRIDE_ERROR_CM, meas
        assert meas["foot_skating_cm_s"] < MAX_GENERATED_SKATING_CM_S, meas
    assert not np.allclose(motions[0].rotations, motions[1].rotations)  # each variant draws its own xi


def test_ma2010_cleanup_root_is_the_papers_and_slides_more(results, tmp_path, capsys):
    """--cleanup root: the paper's footskate cleanup alone (Sec. 6.3). Same xi, same root,
    only the legs differ from the default ("root+feet"), whose feet slide less."""
    from motionvar.ma2010.examples import root_solver
    from motionvar.ma2010.generate import walk_measures

    saved = _ma2010_model(results)
    stride = f"{saved.model.style_.mean():.1f}"
    walks = {}
    for cleanup in ("root", "root+feet"):
        out = tmp_path / cleanup
        assert run(results, "ma2010", "--style", stride, "--seconds", "3", "--cleanup", cleanup, "--out", str(out)) == 0
        assert f"(cleanup {cleanup})" in capsys.readouterr().out
        walks[cleanup] = read_bvh(next(out.glob("*.bvh")))
    paper, pinned = walks["root"], walks["root+feet"]
    assert np.allclose(paper.root_pos, pinned.root_pos, atol=1e-4)
    solver = root_solver(saved.model.skeleton_, saved.joint_map)
    legs = np.concatenate(
        [[j, paper.skeleton.parents[j], paper.skeleton.parents[paper.skeleton.parents[j]]] for j in solver.feet[:, 0]]
    )
    others = np.setdiff1d(np.arange(paper.skeleton.n_joints), legs)
    assert np.allclose(paper.rotations[:, others], pinned.rotations[:, others], atol=1e-5)
    assert walk_measures(pinned, solver)["foot_skating_cm_s"] <= walk_measures(paper, solver)["foot_skating_cm_s"]
    with pytest.raises(SystemExit):
        run(results, "ma2010", "--style", stride, "--cleanup", "feet", "--out", str(tmp_path / "bad"))
    assert "--cleanup: invalid choice: 'feet'" in capsys.readouterr().err


def test_ma2010_cleanup_choices_are_the_librarys():
    from motionvar.cli.ma2010 import CLEANUPS as CLI_CLEANUPS
    from motionvar.ma2010.postprocess import CLEANUPS

    assert CLI_CLEANUPS == CLEANUPS


def test_ma2010_seed_reproduces_the_output_and_xi_fixes_groups(results, tmp_path, capsys):
    saved = _ma2010_model(results)
    stride = f"{saved.model.style_.mean():.1f}"
    paths = []
    for k, seed in enumerate(("5", "5", "6")):
        out = tmp_path / str(k)
        assert run(results, "ma2010", "--style", stride, "--seconds", "2", "--seed", seed, "--out", str(out)) == 0
        paths.append(next(out.glob("*.bvh")))
    assert paths[0].read_bytes() == paths[1].read_bytes()
    assert paths[0].read_bytes() != paths[2].read_bytes()
    xi = np.median(saved.model.xi_["legs"])
    assert (
        run(results, "ma2010", "--style", stride, "--seconds", "2", "--xi", f"A={xi}", "--out", str(tmp_path / "xi"))
        == 0
    )
    assert f"xi: legs {xi:.3g}," in capsys.readouterr().out


@pytest.mark.parametrize(
    "style,message",
    [
        (
            "60",
            r"style left_support_stride 60, right_support_stride 60 is outside the model's range \(left_support_stride "
            r"\d+\.\d-\d+\.\d cm, right_support_stride \d+\.\d-\d+\.\d cm: the examples' .* widened by 25%",
        ),
        ("1,2,3", "the model takes 2 style parameters"),
        ("fast", "--style: expected comma-separated numbers; got 'fast'"),
    ],
)
def test_ma2010_style_out_of_range_says_the_range(results, tmp_path, capsys, style, message):
    assert run(results, "ma2010", "--style", style, "--out", str(tmp_path / "out")) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith("motionvar ma2010: error: ") and "Traceback" not in err
    assert re.search(message, err), err
    assert not (tmp_path / "out").exists() or not any((tmp_path / "out").iterdir())


def test_ma2010_unequal_strides_off_the_examples_are_refused(results, tmp_path, capsys):
    saved = _ma2010_model(results)
    c = saved.model.style_.mean(axis=0)
    assert run(results, "ma2010", "--style", f"{c[0] - 3:.1f},{c[1] + 3:.1f}", "--out", str(tmp_path)) == 2
    err = capsys.readouterr().err
    assert "lies off the examples: their style parameters vary together" in err and "nearly equal strides" in err
    assert not list(tmp_path.glob("*.bvh"))


@pytest.mark.parametrize(
    "xi,message",
    [
        ("E=1", re.escape("xi: unknown joint group 'E' (groups: A=legs, B=left_arm, C=right_arm, D=upper_body)")),
        ("A=1000", r"xi A=1000 is outside the model's range for legs \("),
        ("1,2", "--xi: give 4 numbers"),
    ],
)
def test_ma2010_bad_xi(results, tmp_path, capsys, xi, message):
    stride = f"{_ma2010_model(results).model.style_.mean():.1f}"
    assert run(results, "ma2010", "--style", stride, "--xi", xi, "--out", str(tmp_path)) == 2
    assert re.search(message, capsys.readouterr().err)
    assert not list(tmp_path.glob("*.bvh"))


def test_egges2004_idle_of_one_subject(results, tmp_path, capsys):
    out = tmp_path / "idle.bvh"
    assert run(results, "egges2004", "--subject", "02", "--seconds", "12", "--seed", "1", "--out", str(out)) == 0
    m = read_bvh(out)
    assert m.n_frames == round(12 * m.fps) + 1 and m.fps == pytest.approx(30.0)
    assert m.skeleton.names == cmu_skeleton().names  # the subject's own skeleton: the dataset's rig
    assert np.ptp(m.root_pos[:, 0]) > 1.0  # the balance shifts move the pelvis sideways
    assert "idle motion of subject 02" in capsys.readouterr().out


def test_egges2004_unknown_subject_lists_the_valid_ones(results, tmp_path, capsys):
    out = tmp_path / "idle.bvh"
    assert run(results, "egges2004", "--subject", "99", "--out", str(out)) == 2
    err = capsys.readouterr().err
    assert err == "motionvar egges2004: error: subject '99' has no idle database; the model has subjects 01, 02, 03\n"
    assert not out.exists()


@pytest.mark.parametrize("seconds", ["0", "-3", "nan"])
def test_seconds_must_be_positive(results, tmp_path, capsys, seconds):
    out = tmp_path / "idle.bvh"
    assert run(results, "egges2004", "--seconds", seconds, "--out", str(out)) == 2
    assert "error: --seconds must be > 0" in capsys.readouterr().err and not out.exists()


def test_du2022_walk_follows_the_path(results, tmp_path, capsys):
    out = tmp_path / "walk.bvh"
    assert run(results, "du2022", "walk", "--path", "0,0 120,0 160,40", "--out", str(out)) == 0
    m = read_bvh(out)
    assert m.skeleton.names == cmu_skeleton().names
    assert m.n_frames > 40 and m.fps == pytest.approx(120.0)
    text = capsys.readouterr().out
    assert "steps (leftStance" in text and "path 177 cm" in text
    assert np.linalg.norm(m.root_pos[-1, [0, 2]]) > 60.0  # it walked


@pytest.mark.parametrize(
    "path,message",
    [
        ("0,0", "--path: needs at least 2 points x,z (cm); got 1 in '0,0'"),
        ("0,0 1,2,3", "--path: point '1,2,3' is not x,z"),
        ("0,0 ten,0", "--path point 'ten,0': expected comma-separated numbers"),
        ("0,0 0,0", "path: consecutive points must differ"),
        ("", "--path: needs at least 2 points"),
    ],
)
def test_du2022_walk_bad_path(results, tmp_path, capsys, path, message):
    out = tmp_path / "walk.bvh"
    assert run(results, "du2022", "walk", "--path", path, "--out", str(out)) == 2
    err = capsys.readouterr().err
    assert message in err and err.count("\n") == 1
    assert not out.exists()


def test_du2022_style_samples(results, tmp_path, capsys):
    from motionvar.du2022.style.generate import load_rig

    assert run(results, "du2022", "style", "--style", "old", "--n", "3", "--seed", "2", "--out", str(tmp_path)) == 0
    files = sorted(tmp_path.glob("*.bvh"))
    assert [f.name for f in files] == [f"old_walk_leftStance_{k}.bvh" for k in (1, 2, 3)]
    rig = load_rig(results / DS / "models" / "du2022_style" / "rig")
    for f in files:
        m = read_bvh(f)
        assert m.n_frames == rig.n_frames and m.fps == pytest.approx(rig.fps["walk_leftStance"], rel=1e-6)
        assert m.skeleton.names == rig.skeleton.names
    assert capsys.readouterr().out.count("old walk_leftStance") == 3
    assert run(results, "du2022", "style", "--style", "neutral", "--out", str(tmp_path / "n")) == 0


def test_du2022_style_unknown_style_lists_the_valid_ones(results, tmp_path, capsys):
    assert run(results, "du2022", "style", "--style", "sexy", "--out", str(tmp_path)) == 2
    err = capsys.readouterr().err
    assert "style 'sexy' has no model for dataset 'toy'; styles with models: neutral, old" in err
    assert not list(tmp_path.glob("*.bvh"))
    assert run(results, "du2022", "style", "--style", "old", "--primitive", "pick_reach", "--out", str(tmp_path)) == 2
    assert "primitive 'pick_reach' has no old model; primitives with one: walk_leftStance" in capsys.readouterr().err


def test_positions_to_motion_recovers_a_walk_on_its_rig():
    """The decoding's last step: joint rotations on the rig from feature-joint positions
    (a generator walk's own positions come back within a fraction of a cm)."""
    from motionvar.du2022.style.features import features_to_positions, motion_features, style_joints
    from motionvar.du2022.style.generate import feature_position_error, positions_to_motion
    from motionvar.synth import generate_walk, make_subjects, sample_walk_params

    s = make_subjects(1, seed=3)[0]
    m, _ = generate_walk(s, sample_walk_params(s, np.random.default_rng(0), "old", n_steps=3))
    layout = style_joints(m.skeleton, JM)
    positions = features_to_positions(motion_features(m, layout), layout)
    back = positions_to_motion(positions, m.skeleton, layout, m.fps)
    assert feature_position_error(back, positions, layout) < 0.5
    with pytest.raises(ValueError, match="positions must be"):
        positions_to_motion(positions[:, :5], m.skeleton, layout, m.fps)
