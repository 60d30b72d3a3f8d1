"""Morphable Graph rule scripts (Du 2022 ch. 4) outside Snakemake, as thin adapters: a
fit through the script saves a loadable model; bad input gives one clear error line
naming the file or config key, exit status 1, and no output file. The evaluations
themselves are tested in the other test_graph_*.py modules."""

from __future__ import annotations

import sys

import pandas as pd
import pytest
import rule_scripts
from graph_toy import toy_clips
from rule_scripts import FakeSnakemake, Named, run, script

from motionvar.du2022.graph import MotionPrimitive, PrimitiveOptions
from motionvar.io import save_dataset

sys.modules.setdefault("_graph", rule_scripts._load("_graph", "_graph"))  # the scripts' shared loaders

MODEL_SETTINGS = {  # params.settings of du2022_graph_primitive: config.du2022_graph's seed and model
    "seed": 0,
    "model": {
        "n_basis": 8,
        "n_components": 4,
        "gmm_min": 1,
        "gmm_max": 2,
        "gmm_criterion": "bic",
        "reg_covar": 1e-3,
        "sfpca_max_iter": 0,
        "sfpca_weight_groups": "function",
        "sfpca_eval_frames": None,
    },
}

SMALL = PrimitiveOptions(n_basis=8, n_components=4, gmm_components=(1, 2), sfpca_max_iter=0)


@pytest.fixture(scope="module")
def prep_dir(tmp_path_factory):
    d = tmp_path_factory.mktemp("prep")
    clips = toy_clips(6)
    meta = pd.DataFrame(
        dict(
            clip_id=[f"c{i}" for i in range(6)],
            source_clip=[f"s{i // 2}" for i in range(6)],
            primitive=["walk_leftStance"] * 4 + ["pick_reach"] * 2,
            start_frame=[0] * 6,
            stop_frame=[c.n_frames for c in clips],
        )
    )
    save_dataset(d, clips, meta)
    return d


def _primitive_rule(tmp_path, prep_dir, primitive):
    out = tmp_path / f"{primitive}.npz"
    return out, FakeSnakemake(
        tmp_path,
        "du2022_graph_primitive",
        input=Named(clips=str(prep_dir / "clips.npz")),
        output=Named(model=str(out), meta=str(out.with_suffix(".json"))),
        params=Named(settings=MODEL_SETTINGS),
        wildcards=Named(dataset="t", primitive=primitive),
    )


def test_graph_primitive_fits_and_saves(tmp_path, prep_dir):
    out, sm = _primitive_rule(tmp_path, prep_dir, "walk_leftStance")
    script("du2022_graph_primitive").main(sm)
    model = MotionPrimitive.load(out)
    assert model.n_latent == 3 and model.options.gmm_components == (1, 2)  # latent capped at clips - 1


def test_graph_primitive_too_few_clips_names_file_and_key(tmp_path, prep_dir, capsys):
    out, sm = _primitive_rule(tmp_path, prep_dir, "pick_reach")
    with pytest.raises(SystemExit) as exc:
        run(sm, script("du2022_graph_primitive").main)
    assert exc.value.code == 1
    err = capsys.readouterr().err
    assert "clips.npz" in err and "du2022_graph.primitives" in err and "'pick_reach'" in err
    assert not out.exists()


def test_dense_picks_need_the_synthetic_generator(tmp_path, capsys):
    out = tmp_path / "dense" / "clips.npz"
    sm = FakeSnakemake(
        tmp_path,
        "du2022_graph_dense_picks",
        output=Named(clips=str(out), metadata=str(out.parent / "m.csv")),
        params=Named(entry={"source": "bvh"}, settings={}, prep={}, joint_map=None),
    )
    with pytest.raises(SystemExit):
        run(sm, script("du2022_graph_dense_picks").main)
    assert "dense picks need the synthetic generator" in capsys.readouterr().err
    assert not out.exists()


def _compactness_rule(tmp_path, models, clips, dense_clips=()):
    out = tmp_path / "out"
    out.mkdir(exist_ok=True)
    return out, FakeSnakemake(
        tmp_path,
        "du2022_sec4_6_1",
        input=Named(
            models=Named([str(p) for m in models for p in (m, m.with_suffix(".json"))]),
            metadata=str(clips.parent / "metadata.csv"),
            dense=Named(),
            clips=str(clips),
            dense_clips=Named(list(dense_clips)),
        ),
        output=Named(table=str(out / "t.csv"), figure=str(out / "f.png"), claims=str(out / "c.json")),
        params=Named(settings={"seed": 0}),
    )


def test_compactness_refits_half_of_the_clips(tmp_path):
    """Rule du2022_sec4_6_1: each model is refitted with its saved options to half of its clips
    (6 walks: 3), measured in a temporary folder; both Sec. 4.6.1 claims are written."""
    import json

    d = tmp_path / "prep"
    clips = toy_clips(6, seed=1)
    meta = pd.DataFrame(
        dict(
            clip_id=[f"c{i}" for i in range(6)],
            source_clip=[f"s{i}" for i in range(6)],
            primitive=["walk_leftStance"] * 6,
            start_frame=[0] * 6,
            stop_frame=[c.n_frames for c in clips],
        )
    )
    save_dataset(d, clips, meta)
    model = MotionPrimitive("walk_leftStance", SMALL).fit(clips)
    model.save(tmp_path / "walk_leftStance")
    out, sm = _compactness_rule(tmp_path, [tmp_path / "walk_leftStance.npz"], d / "clips.npz")
    script("du2022_sec4_6_1").main(sm)
    table = pd.read_csv(out / "t.csv")
    assert list(table["primitive"]) == ["walk_leftStance", "all"] and table.loc[0, "half_clips"] == 3
    assert (table.loc[0, "latent"], table.loc[0, "half_latent"]) == (4, 2)  # capped at clips - 1
    claims = json.loads((out / "c.json").read_text())
    assert [c["claim_id"].split(".")[-1] for c in claims] == [
        "model_much_smaller_than_data",
        "model_size_constant_as_data_doubles",
    ]
    assert claims[1]["value"] == pytest.approx(table.loc[0, "model_growth"], rel=1e-5)  # the table: 6 digits
    assert len(list(tmp_path.glob("**/*.npz"))) == 2  # the model and the clips: the half's model left nothing


def test_compactness_dense_model_needs_dense_clips(tmp_path, prep_dir, capsys):
    model = MotionPrimitive("pick_reach_dense", SMALL).fit(toy_clips(4))
    model.save(tmp_path / "pick_reach_dense")
    out, sm = _compactness_rule(tmp_path, [tmp_path / "pick_reach_dense.npz"], prep_dir / "clips.npz")
    with pytest.raises(SystemExit) as exc:
        run(sm, script("du2022_sec4_6_1").main)
    assert exc.value.code == 1
    assert "pick_reach_dense needs the dense picks' clips" in capsys.readouterr().err
    assert not (out / "c.json").exists()
