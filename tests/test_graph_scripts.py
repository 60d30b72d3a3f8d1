"""Morphable Graph rule scripts (Du 2022 ch. 4) outside Snakemake, as thin adapters: a
fit through the script saves a loadable model; bad input gives one clear error line
naming the file or config key, exit status 1, and no output file. The evaluations
themselves are tested in test_graph.py."""

from __future__ import annotations

import sys

import pandas as pd
import pytest
import rule_scripts
from graph_toy import toy_clips
from rule_scripts import FakeSnakemake, Named, run, script

from motionvar.du2022.graph import MotionPrimitive
from motionvar.io import save_dataset

sys.modules.setdefault("_graph", rule_scripts._load("_graph", "_graph"))  # the scripts' shared loaders

MODEL_SETTINGS = {  # params.settings of du2022_graph_primitive: config.graph's seed and model
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
    assert "clips.npz" in err and "graph.primitives" in err and "'pick_reach'" in err
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
