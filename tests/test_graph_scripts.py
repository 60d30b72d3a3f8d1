"""Morphable Graph rule scripts (Du 2022 ch. 4) outside Snakemake: bad input gives one
clear error line naming the file or config key, exit status 1, and no output file."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from graph_toy import toy_clips
from test_workflow_scripts import FakeSnakemake, Named, script

from motionvar.du2022.graph import MotionPrimitive, PrimitiveOptions
from motionvar.io import save_dataset

GRAPH_OPTIONS = {
    "seed": 0, "dense_picks_per_subject": 0, "dense_grid_spacing_cm": 10.0,
    "model": {"n_basis": 8, "n_components": 4, "gmm_min": 1, "gmm_max": 2, "gmm_criterion": "bic",
              "reg_covar": 1e-3, "sfpca_max_iter": 0, "sfpca_weight_groups": "function", "sfpca_eval_frames": None},
    "search": {"primitives": ["walk_leftStance"], "n_samples": 200, "n_queries": 2, "beam": 2, "leaf_size": 8,
               "n_random": 10, "joints": {"walk_leftStance": "left_ankle"}, "default_joint": "right_hand",
               "pose_joints": ["hips", "left_hand"]},
}


@pytest.fixture(scope="module")
def prep_dir(tmp_path_factory):
    d = tmp_path_factory.mktemp("prep")
    clips = toy_clips(6)
    meta = pd.DataFrame(dict(clip_id=[f"c{i}" for i in range(6)], source_clip=[f"s{i // 2}" for i in range(6)],
                             primitive=["walk_leftStance"] * 4 + ["pick_reach"] * 2,
                             start_frame=[0] * 6, stop_frame=[c.n_frames for c in clips]))
    save_dataset(d, clips, meta)
    return d


def test_graph_primitive_fits_and_saves(tmp_path, prep_dir):
    out = tmp_path / "walk_leftStance.npz"
    sm = FakeSnakemake(tmp_path, "graph_primitive", input=Named(clips=str(prep_dir / "clips.npz")),
                       output=Named(model=str(out), meta=str(out.with_suffix(".json"))),
                       params=Named(options=GRAPH_OPTIONS), wildcards=Named(dataset="t", primitive="walk_leftStance"))
    script("graph_primitive").main(sm)
    assert MotionPrimitive.load(out).n_latent == 3  # capped at clips - 1


def test_graph_primitive_too_few_clips_names_file_and_key(tmp_path, prep_dir, capsys):
    from _rule import run

    out = tmp_path / "pick_reach.npz"
    sm = FakeSnakemake(tmp_path, "graph_primitive", input=Named(clips=str(prep_dir / "clips.npz")),
                       output=Named(model=str(out), meta=str(out.with_suffix(".json"))),
                       params=Named(options=GRAPH_OPTIONS), wildcards=Named(dataset="t", primitive="pick_reach"))
    with pytest.raises(SystemExit) as exc:
        run(sm, script("graph_primitive").main)
    assert exc.value.code == 1
    err = capsys.readouterr().err
    assert "clips.npz" in err and "graph.primitives" in err and "'pick_reach'" in err
    assert not out.exists()


def test_graph_search_bad_joint_names_config_key(tmp_path, capsys):
    from _rule import run

    model = MotionPrimitive.fit(toy_clips(6), "walk_leftStance", PrimitiveOptions(n_basis=8, n_components=3,
                                                                                  gmm_components=(1, 1),
                                                                                  sfpca_max_iter=0))
    model.save(tmp_path / "walk_leftStance")
    bad = {**GRAPH_OPTIONS, "search": {**GRAPH_OPTIONS["search"], "joints": {"walk_leftStance": "left_foot"}}}
    out = tmp_path / "search.csv"
    sm = FakeSnakemake(tmp_path, "graph_search", input=Named(model=str(tmp_path / "walk_leftStance.npz")),
                       output=Named(queries=str(out), trees=str(tmp_path / "trees.csv")),
                       params=Named(options=bad, joint_map=None),
                       wildcards=Named(dataset="t", primitive="walk_leftStance"))
    with pytest.raises(SystemExit):
        run(sm, script("graph_search").main)
    err = capsys.readouterr().err
    assert "graph.search.joints.walk_leftStance" in err and "left_foot" in err
    assert not out.exists()
    sm.params = Named(options=GRAPH_OPTIONS, joint_map=None)
    script("graph_search").main(sm)
    table = pd.read_csv(out)
    assert set(table["method"]) == {"kmeans", "gmm", "median", "random", "brute_force"}
    assert np.isfinite(table["error"]).all()


def test_dense_picks_need_the_synthetic_generator(tmp_path, capsys):
    from _rule import run

    out = tmp_path / "dense" / "clips.npz"
    sm = FakeSnakemake(tmp_path, "graph_dense_picks", output=Named(clips=str(out), metadata=str(out.parent / "m.csv")),
                       params=Named(entry={"source": "bvh"}, options=GRAPH_OPTIONS, prep={}, joint_map=None))
    with pytest.raises(SystemExit):
        run(sm, script("graph_dense_picks").main)
    assert "dense picks need the synthetic generator" in capsys.readouterr().err
    assert not out.exists()
