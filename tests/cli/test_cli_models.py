"""The motionvar command: missing models and rigs, output layout, progress, the rules that save what it reads, request sizes, --version and help."""

from __future__ import annotations

import re

import numpy as np
import pandas as pd
import pytest
from cli_toy import DS, JM, run

from motionvar.cli.common import CLIError, RigLayout, on_rig
from motionvar.cli.main import main
from motionvar.io import load_dataset, save_dataset
from motionvar.io.bvh import read_bvh

pytestmark = pytest.mark.usefixtures("one_torch_thread")  # tests/conftest.py


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
    out, fake = clips_fake(tmp_path, walks_folder(tmp_path / "data", ["neutral"] * 3))
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
