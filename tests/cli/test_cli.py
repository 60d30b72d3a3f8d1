"""The `motionvar` command (motionvar.cli): tiny models fitted with the library and saved in
a results/<dataset>/models/ layout, every subcommand run through main([...]), its BVH read
back; and every bad input answered with one line on stderr, exit status 2 and no output."""

from __future__ import annotations

import re

import numpy as np
import pandas as pd
import pytest
from cli_toy import DS, JM, run, toy_results

from motionvar.cli.common import CLIError, RigLayout, on_rig
from motionvar.cli.main import main
from motionvar.core import cmu_skeleton
from motionvar.io import load_dataset, save_dataset
from motionvar.io.bvh import read_bvh
from motionvar.ma2010.evaluations.common import PUBLISHED_MAX_STRIDE_ERROR_CM

# Foot skating (cm/s, Sec. 7.4's measure: the contact point's speed during detected contacts)
# of a generated walk: the bound the generator's own walks meet (< 1.0,
# tests/metrics/test_metrics_motion.py). The command's default cleanup ("root+feet": the paper's
# root, Sec. 6.3, then every foot in contact pinned by leg IK, [KSG02]) meets it (CI models:
# 0.00 cm/s); the paper's cleanup alone (--cleanup root) pins only the support foot, and the
# other foot of a double support slides: 0.9-2.8 cm/s on the CI models (the CI run's Sec. 7.4
# table: ours 1.3, the example cycles root-solved alike 0.7-2.0; Perlin noise 4-5).
MAX_GENERATED_SKATING_CM_S = 1.0


pytestmark = pytest.mark.usefixtures("one_torch_thread")  # tests/conftest.py


@pytest.fixture(scope="module")
def results(tmp_path_factory):
    """results/toy of tests/cli_toy.py (built once per session)."""
    return toy_results(tmp_path_factory)


def _ma2010_model(results):
    from motionvar.ma2010.storage import load_style_variation_model

    return load_style_variation_model(results / DS / "models" / "ma2010" / "style_variation.npz")


# ---------------------------------------------------------------- models


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


# ---------------------------------------------------------------- Ma 2010


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


# ---------------------------------------------------------------- Egges 2004


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


# ---------------------------------------------------------------- Du 2022 walk


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


# ---------------------------------------------------------------- Du 2022 style


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


# ---------------------------------------------------------------- missing models, rigs


@pytest.mark.parametrize(
    "argv,target",
    [
        (["ma2010", "--style", "130"], "results/toy/models/ma2010/style_variation.npz"),
        (["egges2004"], "results/toy/models/egges2004/idle_model.npz"),
        (["du2022", "walk", "--path", "0,0 100,0"], "results/toy/models/du2022/graph/graph/edges.npz"),
        (["du2022", "style", "--style", "old"], "results/toy/models/du2022_style/autoencoder.pt"),
    ],
)
def test_a_missing_model_names_the_snakemake_target(tmp_path, capsys, argv, target):
    (tmp_path / "results" / DS / "models").mkdir(parents=True)
    out = tmp_path / ("out.bvh" if argv[0] == "egges2004" or "walk" in argv else "out")
    assert main([*argv, "--results", str(tmp_path / "results"), "--dataset", DS, "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and f"run `snakemake --cores 2 {target}` first" in err and "is missing" in err
    assert not out.exists()


def test_an_unknown_dataset_names_those_there(results, tmp_path, capsys):
    assert main(["egges2004", "--results", str(results), "--dataset", "cmu", "--out", str(tmp_path / "i.bvh")]) == 2
    err = capsys.readouterr().err
    assert f"no results for dataset 'cmu' in {results} (datasets there: {DS})" in err
    assert not (tmp_path / "i.bvh").exists()


def test_output_follows_the_rig_layout_and_unit(results, tmp_path):
    from motionvar.egges2004.storage import load_idle_model

    out = tmp_path / "idle_m.bvh"
    assert run(results, "egges2004", "--seconds", "1", "--unit-cm", "100", "--out", str(out)) == 0
    cm = run(results, "egges2004", "--seconds", "1", "--out", str(tmp_path / "idle_cm.bvh"))
    assert cm == 0
    a, b = read_bvh(out, scale=100.0), read_bvh(tmp_path / "idle_cm.bvh")
    assert np.allclose(a.root_pos, b.root_pos, atol=1e-3)
    model = load_idle_model(results / DS / "models" / "egges2004" / "idle_model")
    sk = next(iter(model.skeletons.values()))
    rig = RigLayout(sk.names, sk.parents, ("XYZ",) * sk.n_joints, (True,) * sk.n_joints, {})
    m = on_rig(b, rig)
    assert m.skeleton.rotation_orders == ("XYZ",) * sk.n_joints and np.allclose(m.skeleton.offsets, b.skeleton.offsets)
    with pytest.raises(CLIError, match="is not the dataset's rig"):
        on_rig(b, RigLayout(sk.names[:3], sk.parents[:3], ("XYZ",) * 3, (True,) * 3, {}))


def test_progress_bar_on_stderr(results, tmp_path, capsys):
    assert (
        main(
            [
                "egges2004",
                "--results",
                str(results),
                "--dataset",
                DS,
                "--seconds",
                "1",
                "--out",
                str(tmp_path / "i.bvh"),
            ]
        )
        == 0
    )
    err = capsys.readouterr().err
    assert "egges2004 idle [" in err and "1/1" in err


# ---------------------------------------------------------------- the rules that save what the command reads


def test_model_rule_scripts_save_what_the_command_loads(tmp_path):
    """Rules ma2010_model, du2022_graph_edges and du2022_style_rig as adapters: each writes a model
    file (npz + json) that the command's loaders read back."""
    import rule_scripts
    from ma2010_toywalk import clips_fake, walks_folder
    from rule_scripts import FakeSnakemake, Named, script
    from rule_scripts import run as run_rule

    from motionvar.du2022.graph.storage import load_graph
    from motionvar.du2022.style.generate import load_rig
    from motionvar.ma2010.storage import load_style_variation_model

    for helper in ("_ma2010", "_graph", "_style"):
        rule_scripts.helper_module(helper)
    out, fake = clips_fake(tmp_path, walks_folder(tmp_path, ["neutral"] * 3))
    run_rule(fake, script("ma2010_clips").main)
    options = {"structure": "auto", "variogram_model": "linear", "root_group": "legs"}
    run_rule(
        FakeSnakemake(
            tmp_path,
            "ma2010_model",
            input=fake.output,
            output=Named(model=str(out / "style_variation.npz"), settings=str(out / "style_variation.json")),
            params=Named(settings={"model": options}, joint_map=None),
        ),
        script("ma2010_model").main,
    )
    saved = load_style_variation_model(out / "style_variation.npz")
    assert saved.settings == options and saved.model.style_.shape[1] == 2

    meta = pd.DataFrame(
        {
            "clip_id": ["a", "b", "c", "d"],
            "source_clip": ["w0", "w0", "w0", "w1"],
            "primitive": ["walk_start", "walk_leftStance", "walk_rightStance", "walk_leftStance"],
            "start_frame": [0, 40, 90, 0],
        }
    )
    meta.to_csv(tmp_path / "metadata.csv", index=False)
    edges = tmp_path / "graph" / "edges.npz"
    run_rule(
        FakeSnakemake(
            tmp_path,
            "du2022_graph_edges",
            input=Named(metadata=str(tmp_path / "metadata.csv")),
            output=Named(model=str(edges), settings=str(edges.with_suffix(".json"))),
            params=Named(settings={"synthesis": {"tree_samples": 100, "look_ahead": 1}}, joint_map=None),
        ),
        script("du2022_graph_edges").main,
    )
    graph = load_graph(edges)
    assert graph.graph.edges["walk_start"] == {"walk_leftStance": 1} and graph.settings["tree_samples"] == 100
    assert graph.graph.start_nodes == {"walk_start": 1, "walk_leftStance": 1}

    data = tmp_path / "data"  # the toy walks, as a prep dataset of one primitive
    prep = load_dataset(data)
    prep.metadata["primitive"] = "walk_leftStance"
    save_dataset(tmp_path / "prep", list(prep), prep.metadata)
    rig = tmp_path / "rig.npz"
    run_rule(
        FakeSnakemake(
            tmp_path,
            "du2022_style_rig",
            input=Named(clips=str(tmp_path / "prep" / "clips.npz")),
            output=Named(model=str(rig), settings=str(rig.with_suffix(".json"))),
            params=Named(settings={"canonical_frames": 60}, joint_map=None),
        ),
        script("du2022_style_rig").main,
    )
    loaded = load_rig(rig)
    assert loaded.layout.n_joints == 21 and set(loaded.fps) == {"walk_leftStance"} and loaded.n_frames == 60


def test_a_model_the_dataset_cannot_have_says_why(tmp_path, capsys):
    """Where the run's applicability.csv says the dataset supports none of the evaluations
    a model is fitted for, the command says why instead of naming a target that would fail."""
    ds = tmp_path / "results" / DS
    (ds / "models").mkdir(parents=True)
    pd.DataFrame(
        {
            "evaluation": ["egges2004_speed", "egges2004_identification"],
            "applicable": [False, False],
            "reason": ["needs at least 2 idle recordings", "needs idle clips of 2 subjects"],
        }
    ).to_csv(ds / "applicability.csv", index=False)
    out = tmp_path / "idle.bvh"
    assert main(["egges2004", "--results", str(tmp_path / "results"), "--dataset", DS, "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert "the dataset does not support it: needs at least 2 idle recordings" in err and "snakemake" not in err
    assert main(["models", "--results", str(tmp_path / "results"), "--dataset", DS]) == 0
    assert "<- not applicable: needs at least 2 idle recordings" in capsys.readouterr().out
    assert not out.exists()


def test_du2022_walk_without_transitions_is_refused(results, tmp_path, capsys):
    """A graph whose clips are one primitive each (DFKI's single steps) has no transitions:
    the walk would stop after one step, so the command says so instead."""
    import shutil

    from motionvar.du2022.graph import MorphableGraph
    from motionvar.du2022.graph.storage import load_graph, save_graph

    models = tmp_path / "results" / DS / "models"
    shutil.copytree(results / DS / "models" / "du2022", models / "du2022")
    saved = load_graph(models / "du2022" / "graph" / "graph" / "edges")
    nodes = {n: {} for n in ("walk_leftStance", "walk_rightStance")}
    save_graph(models / "du2022" / "graph" / "graph" / "edges", MorphableGraph(nodes, {}, {}), JM, saved.settings)
    out = tmp_path / "walk.bvh"
    assert (
        main(
            [
                "du2022",
                "walk",
                "--results",
                str(tmp_path / "results"),
                "--dataset",
                DS,
                "--path",
                "0,0 100,0",
                "--out",
                str(out),
            ]
        )
        == 2
    )
    assert "has no transitions between its walking primitives" in capsys.readouterr().err and not out.exists()


# ---------------------------------------------------------------- request sizes, --version, help


@pytest.mark.parametrize(
    "argv, message",
    [
        (
            ["ma2010", "--style", "133", "--seconds", "1e9", "--out", "{tmp}/walks"],
            "--seconds x --variants = 1e+09: at most 600 s of walks per command",
        ),
        (
            ["ma2010", "--style", "133", "--seconds", "100", "--variants", "7", "--out", "{tmp}/walks"],
            "--seconds x --variants = 700: at most 600 s of walks per command",
        ),
        (
            ["egges2004", "--seconds", "1e12", "--out", "{tmp}/idle.bvh"],
            "--seconds 1e+12: at most 600 s of idle motion per command",
        ),
        (
            ["du2022", "style", "--style", "old", "--n", "100000", "--out", "{tmp}/styles"],
            "--n 100000: at most 200 samples per command (run again with another --seed for more)",
        ),
        (
            ["du2022", "walk", "--path", "0,0 1e9,0", "--out", "{tmp}/walk.bvh"],
            "--path of length 1e+09: at most 10000 cm per walk",
        ),
        (
            ["du2022", "walk", "--path", "0,0 300,0", "--max-steps", "5000", "--out", "{tmp}/walk.bvh"],
            "--max-steps 5000: at most 400 steps per walk",
        ),
    ],
    ids=["ma2010-seconds", "ma2010-variants", "egges2004-seconds", "style-n", "walk-path", "walk-steps"],
)
def test_an_oversized_request_is_refused_at_once(results, tmp_path, capsys, monkeypatch, argv, message):
    """Exit status 2 before any model is loaded (so at once), one line stating the limit,
    nothing written."""
    from motionvar.cli.common import ResultsDir

    def no_loading(*args, **kwargs):
        raise AssertionError("a model was loaded before the request's size was checked")

    monkeypatch.setattr(ResultsDir, "load", no_loading)  # every read of a command goes through it
    assert run(results, *[a.format(tmp=tmp_path) for a in argv]) == 2
    err = capsys.readouterr().err
    command = " ".join(argv[:2] if argv[0] == "du2022" else argv[:1]).split()[0]
    assert err == f"motionvar {command}: error: {message}\n"
    assert not any(tmp_path.iterdir())


def test_version_and_top_level_help_with_examples():
    import subprocess
    import sys
    from importlib.metadata import version

    r = subprocess.run(
        [sys.executable, "-m", "motionvar.cli.main", "--version"], capture_output=True, text=True, timeout=120
    )
    assert r.returncode == 0 and r.stdout == f"motionvar {version('motionvar')}\n" and not r.stderr
    from motionvar.cli.main import build_parser

    text = build_parser().format_help()
    examples = [line.strip() for line in text.split("examples:", 1)[1].splitlines() if line.startswith("  motionvar")]
    assert examples == ["motionvar models", "motionvar ma2010 --style 135 --seconds 20 --variants 3 --out walks/"]
    for example in examples:  # each parses as written
        build_parser().parse_args(example.split()[1:])


@pytest.mark.parametrize("option", [["--seed", "3"], ["--unit-cm", "100"], ["--force"], ["--quiet"]])
def test_models_takes_only_the_options_it_uses(results, capsys, option):
    with pytest.raises(SystemExit) as stop:
        main(["models", "--results", str(results), *option])
    assert stop.value.code == 2 and f"unrecognized arguments: {option[0]}" in capsys.readouterr().err


def test_each_command_takes_only_its_options():
    """The options of each subcommand are those its run function reads."""
    from motionvar.cli.main import build_parser

    parser = build_parser()
    sub = next(a for a in parser._actions if a.dest == "command").choices
    kinds = next(a for a in sub["du2022"]._actions if a.dest == "kind").choices

    def options(p):
        return {o for a in p._actions for o in a.option_strings if o.startswith("--") and o != "--help"}

    shared = {"--dataset", "--results", "--seed", "--unit-cm", "--force", "--quiet"}
    assert options(sub["models"]) == {"--dataset", "--results"}
    assert options(sub["ma2010"]) == shared | {"--style", "--xi", "--seconds", "--variants", "--cleanup", "--out"}
    assert options(sub["egges2004"]) == shared | {"--subject", "--seconds", "--no-variations", "--out"}
    assert options(kinds["walk"]) == shared | {"--path", "--max-steps", "--out"}
    assert options(kinds["style"]) == shared | {"--style", "--primitive", "--n", "--out"}


def test_a_walk_shows_its_steps_as_progress_lines(results, tmp_path, capsys):
    """Without --quiet the library's progress lines (each graph-walk step, at the interval)
    come on stderr with the progress bar."""
    argv = ["du2022", "walk", "--results", str(results), "--dataset", DS, "--path", "0,0 150,0"]
    assert main([*argv, "--out", str(tmp_path / "walk.bvh")]) == 0
    err = capsys.readouterr().err
    assert re.search(r"^motionvar: graph walk \(150 cm path\) step 1/\d+, elapsed [\d.]+ s", err, flags=re.M), err
