"""Ma 2010 rule scripts outside Snakemake: the walking clips they cut, and bad input
reported as one error line naming the config key or file, with no output left behind."""

import numpy as np
import pandas as pd
import pytest
from ma2010_toywalk import toy_walk
from test_workflow_scripts import FakeSnakemake, Named, run, script

from motionvar.io import save_dataset

OPTIONS = {
    "walk_styles": ["neutral"], "walk_variants": ["forward"], "n_frames": 24, "keyframe_prominence": 0.1,
    "keyframe_min_separation_s": 0.1, "structure": "auto", "variogram_model": "linear", "seed": 0,
}


def toy_dataset(tmp_path, styles):
    motions = [toy_walk(hip_amp=0.3 + 0.03 * i, arm_amp=0.2 + 0.1 * i, n_cycles=3) for i in range(len(styles))]
    meta = pd.DataFrame({"clip_id": [f"w{i}" for i in range(len(styles))], "subject": [f"{i:02d}" for i in range(len(styles))],
                         "behaviour": "walk", "style": styles, "variant": "forward"})
    save_dataset(tmp_path / "data", motions, meta)
    return tmp_path / "data"


def clips_fake(tmp_path, data, **options):
    out = tmp_path / "models"
    fake = FakeSnakemake(
        tmp_path, "ma2010_clips",
        input=Named(clips=str(data / "clips.npz"), metadata=str(data / "metadata.csv")),
        output=Named(clips=str(out / "walk_clips.npz"), table=str(out / "walk_cycles.csv")),
        params=Named(options={**OPTIONS, **options}, joint_map=None),
    )
    out.mkdir()
    return out, fake


def test_clips_script_cuts_walks_into_cycles(tmp_path):
    data = toy_dataset(tmp_path, ["neutral"] * 3)
    out, fake = clips_fake(tmp_path, data)
    run(fake, script("ma2010_clips").main)
    table = pd.read_csv(out / "walk_cycles.csv")
    with np.load(out / "walk_clips.npz") as z:
        assert z["rotations"].shape[:2] == (len(table), 24)
    assert len(table) >= 3 and set(table["source_clip"]) == {"w0", "w1", "w2"}
    assert np.all(table["left_support_stride_cm"] > 50)


@pytest.mark.parametrize(
    "styles, options, expected",
    [
        (["proud", "proud"], {}, "config ma2010.walk_styles"),
        (["neutral"], {}, "need at least 3"),
    ],
)
def test_clips_script_names_the_problem(tmp_path, capsys, styles, options, expected):
    data = toy_dataset(tmp_path, styles)
    if expected == "need at least 3":  # one clip of one cycle: too few examples
        from motionvar.io import load_dataset
        d = load_dataset(data)
        save_dataset(data, [d.motion(0).slice(0, 200)], d.metadata)
    out, fake = clips_fake(tmp_path, data, **options)
    with pytest.raises(SystemExit):
        run(fake, script("ma2010_clips").main)
    err = capsys.readouterr().err
    assert err.startswith("ERROR rule ma2010_clips: ") and expected in err
    assert not any(out.iterdir())


def test_evaluation_scripts_reject_a_stale_cycle_table(tmp_path, capsys):
    data = toy_dataset(tmp_path, ["neutral"] * 3)
    out, fake = clips_fake(tmp_path, data)
    run(fake, script("ma2010_clips").main)
    table = pd.read_csv(out / "walk_cycles.csv")
    table.iloc[:-1].to_csv(out / "walk_cycles.csv", index=False)
    ev = tmp_path / "ev"
    fake = FakeSnakemake(
        tmp_path, "ma2010_sec8",
        input=Named(clips=str(out / "walk_clips.npz"), table=str(out / "walk_cycles.csv")),
        output=Named(table=str(ev / "t.csv"), figure=str(ev / "f.png"), claims=str(ev / "c.json")),
        params=Named(options={**OPTIONS, "timing_seconds": 2.0, "timing_repeats": 1}, joint_map=None),
    )
    with pytest.raises(SystemExit):
        run(fake, script("ma2010_sec8").main)
    assert "rerun ma2010_clips" in capsys.readouterr().err and not ev.exists()
