"""Egges 2004 rule scripts as adapters (the measurements are tested at library level in
test_egges2004_pipeline.py): the model script writes the model file (npz + json), the
categories table and the graph figure; an evaluation script reads that model and writes
table, figure and claims; data without idle clips is one error line, no model left."""

import json
import sys
from pathlib import Path

import pandas as pd
import pytest
import rule_scripts
from egges2004_toy import toy_dataset
from rule_scripts import FakeSnakemake, Named, run, script

from motionvar.io import load_dataset, save_dataset

# the scripts import their loaders as Snakemake runs them, from their own folder
sys.modules.setdefault("_egges2004", rule_scripts._load("_egges2004", "_egges2004"))

# config.egges2004 as a rule passes it (params.settings): keys left out take their defaults
SETTINGS = {"figure_subjects": 2, "analysis": {"variation_pcs": 4}}


def model_fake(tmp_path, folder, name="idle_model"):
    out = tmp_path / "out"
    return out, FakeSnakemake(
        tmp_path,
        "egges2004_model",
        input=Named(clips=str(folder / "clips.npz"), metadata=str(folder / "metadata.csv")),
        output=Named(
            model=str(out / f"{name}.npz"),
            model_settings=str(out / f"{name}.json"),
            categories=str(out / "categories.csv"),
            graph=str(out / "graph.png"),
        ),
        params=Named(settings=SETTINGS, joint_map=None),
    )


def test_model_and_speed_scripts_write_their_outputs(tmp_path):
    out, fake = model_fake(tmp_path, toy_dataset(tmp_path / "prep"))
    out.mkdir()
    run(fake, script("egges2004_model").main)
    assert json.loads((out / "idle_model.json").read_text())["kind"] == "egges2004_idle_model"
    assert len(pd.read_csv(out / "categories.csv")) == 3 and (out / "graph.png").stat().st_size > 0

    speed = FakeSnakemake(
        tmp_path,
        "egges2004_speed",
        input=Named(model=str(out / "idle_model.npz")),
        output=Named(table=str(out / "speed.csv"), figure=str(out / "speed.png"), claims=str(out / "speed.json")),
        params=Named(settings={**SETTINGS, "speed": {"sequence_s": 5.0, "repeats": 1, "subjects": 1}}),
    )
    run(speed, script("egges2004_speed").main)
    claims = json.loads((out / "speed.json").read_text())
    assert [c["claim_id"] for c in claims] == ["egges2004.sec8.real_time"] and len(pd.read_csv(out / "speed.csv")) == 1


def test_model_script_rejects_data_without_idle(tmp_path):
    walks = load_dataset(toy_dataset(tmp_path / "prep", subjects=1, clips=2))
    walks.metadata["behaviour"] = "walk"
    save_dataset(tmp_path / "walks", list(walks), walks.metadata.drop(columns=["n_frames", "fps"]))
    out, fake = model_fake(tmp_path, tmp_path / "walks")
    with pytest.raises(SystemExit) as exc:
        run(fake, script("egges2004_model").main)
    assert exc.value.code == 1
    assert "no idle clips" in Path(fake.log[0]).read_text()
    assert not out.exists() or not any(out.iterdir())
