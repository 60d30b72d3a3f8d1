"""Ma 2010 rule scripts as adapters (the measurements are tested at library level in
the test_ma2010_*.py modules of evaluations): the clips script writes a model file (npz + json) and the
cycle table; bad input is one error line naming the config key or file, with no output
left behind."""

import json

import numpy as np
import pandas as pd
import pytest
import rule_scripts
from ma2010_toywalk import SETTINGS, clips_fake, walks_folder
from rule_scripts import FakeSnakemake, Named, run, script

# the scripts import their loaders as Snakemake runs them, from their own folder
rule_scripts.helper_module("_ma2010")


def test_clips_script_writes_the_cycles_as_a_model_file(tmp_path):
    out, fake = clips_fake(tmp_path, walks_folder(tmp_path / "data", ["neutral"] * 3))
    run(fake, script("ma2010_clips").main)
    table = pd.read_csv(out / "walk_cycles.csv")
    with np.load(out / "walk_clips.npz", allow_pickle=False) as z:
        assert z["rotations"].shape[:2] == (len(table), 24)
    settings = json.loads((out / "walk_clips.json").read_text())
    assert settings["kind"] == "ma2010.ClipSet" and settings["n_frames"] == 24
    assert len(table) >= 3 and set(table["source_clip"]) == {"w0", "w1", "w2"}


@pytest.mark.parametrize(
    "styles, n_cycles, expected",
    [(["proud", "proud"], 3, "config ma2010.clips.walk_styles"), (["neutral"], 1.2, "need at least 3")],
)
def test_clips_script_names_the_problem(tmp_path, capsys, styles, n_cycles, expected):
    out, fake = clips_fake(tmp_path, walks_folder(tmp_path / "data", styles, n_cycles))
    with pytest.raises(SystemExit):
        run(fake, script("ma2010_clips").main)
    err = capsys.readouterr().err
    assert err.startswith("ERROR rule ma2010_clips: ") and expected in err and "metadata.csv" in err
    assert not any(out.iterdir())


def test_evaluation_scripts_reject_a_stale_cycle_table(tmp_path, capsys):
    out, fake = clips_fake(tmp_path, walks_folder(tmp_path / "data", ["neutral"] * 3))
    run(fake, script("ma2010_clips").main)
    table = pd.read_csv(out / "walk_cycles.csv")
    table.iloc[:-1].to_csv(out / "walk_cycles.csv", index=False)
    ev = tmp_path / "ev"
    fake = FakeSnakemake(
        tmp_path,
        "ma2010_sec8",
        input=Named(clips=str(out / "walk_clips.npz"), table=str(out / "walk_cycles.csv")),
        output=Named(table=str(ev / "t.csv"), figure=str(ev / "f.png"), claims=str(ev / "c.json")),
        params=Named(
            settings={**SETTINGS, "model": {"variogram_model": "linear"}, "sec8": {"seconds": 2.0, "repeats": 1}},
            joint_map=None,
        ),
    )
    with pytest.raises(SystemExit):
        run(fake, script("ma2010_sec8").main)
    assert "rerun ma2010_clips" in capsys.readouterr().err and not ev.exists()
