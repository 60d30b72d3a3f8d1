"""Preprocessing (motionvar.prep): the pipeline over a packed dataset, what it drops and how its errors name the clip."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from prep_toy import FPS, JM, WALK_STEPS, facing_heading, standing, stepping, turned

from motionvar.core import JointMap
from motionvar.io import load_dataset, save_dataset
from motionvar.prep import (
    DROPPED_COLUMNS,
    PrepOptions,
    Segment,
    align_motions,
    apply_warp,
    drop_summary,
    dtw_warp,
    preprocess_dataset,
    resample_motion,
    warp_to_median,
)
from motionvar.prep.pipeline import too_short


def small_dataset(tmp_path: Path, with_truth: bool = True) -> Path:
    walk = turned(stepping(WALK_STEPS, 2.5), 1.2, (100.0, -40.0))
    idle = turned(standing(90), -2.0, (-30.0, 60.0))
    motions = [walk, idle]
    meta = pd.DataFrame(
        {
            "clip_id": ["w1", "i1"],
            "subject": ["s1", "s1"],
            "behaviour": ["walk", "idle"],
            "style": ["neutral", "neutral"],
            "primitive": ["", ""],
        }
    )
    if with_truth:
        meta["segments"] = ["walk_start:0:70;walk_rightStance:70:130;walk_leftStance:130:301", "idle:0:90"]
    d = tmp_path / "data"
    save_dataset(d, motions, meta)
    return d


def test_preprocess_dataset_detected_and_ground_truth(tmp_path):
    ds = load_dataset(small_dataset(tmp_path))
    motions, meta, dropped = preprocess_dataset(ds, JM, PrepOptions())
    assert dropped.empty and list(dropped.columns) == list(DROPPED_COLUMNS)
    assert meta["clip_id"].tolist() == ["w1_00", "w1_01", "w1_02", "w1_03", "w1_04", "i1_00"]
    assert meta["primitive"].tolist()[:2] == ["walk_start", "walk_rightStance"]
    assert meta["source_clip"].tolist() == ["w1"] * 5 + ["i1"]
    assert (meta["n_frames"] == meta["stop_frame"] - meta["start_frame"]).all()
    assert [m.n_frames for m in motions] == meta["n_frames"].tolist()
    assert meta["subject"].eq("s1").all() and meta["style"].eq("neutral").all()
    for m in motions:
        assert np.allclose(m.root_pos[0, [0, 2]], 0.0, atol=1e-9)
        assert np.allclose(facing_heading(m), [1.0, 0.0, 0.0], atol=1e-6)
    gt_motions, gt, _ = preprocess_dataset(ds, JM, PrepOptions(use_ground_truth_segments=True))
    assert gt[["primitive", "start_frame", "stop_frame"]].values.tolist() == [
        ["walk_start", 0, 70],
        ["walk_rightStance", 70, 130],
        ["walk_leftStance", 130, 301],
        ["idle", 0, 90],
    ]
    assert gt_motions[1].n_frames == 60
    # round trip through a packed dataset
    save_dataset(tmp_path / "prep", gt_motions, gt)
    assert load_dataset(tmp_path / "prep").metadata["clip_id"].tolist() == gt["clip_id"].tolist()


def test_preprocess_dataset_errors(tmp_path):
    ds = load_dataset(small_dataset(tmp_path, with_truth=False))
    with pytest.raises(ValueError, match="lacks columns \\['segments'\\].*use_ground_truth_segments"):
        preprocess_dataset(ds, JM, PrepOptions(use_ground_truth_segments=True))
    bad = replace(ds, metadata=ds.metadata.assign(behaviour=["walk", "dance"]))
    with pytest.raises(ValueError, match="clip i1: .*unknown behaviour 'dance'"):
        preprocess_dataset(bad, JM)
    nobeh = replace(ds, metadata=ds.metadata.drop(columns=["behaviour"]))
    with pytest.raises(ValueError, match="lacks columns \\['behaviour'\\]"):
        preprocess_dataset(nobeh, JM)
    beyond = replace(ds, metadata=ds.metadata.assign(segments=["walk_start:0:999", "idle:0:90"]))
    with pytest.raises(ValueError, match="clip w1: segments .* beyond the clip's 301 frames"):
        preprocess_dataset(beyond, JM, PrepOptions(use_ground_truth_segments=True))
    garbled = replace(ds, metadata=ds.metadata.assign(segments=["walk_start:0", "idle:0:90"]))
    with pytest.raises(ValueError, match="segments of clip w1"):
        preprocess_dataset(garbled, JM, PrepOptions(use_ground_truth_segments=True))
    with pytest.raises(ValueError, match="joint map.*missing semantic joints \\['head'\\]"):
        preprocess_dataset(ds, JointMap(joints={k: v for k, v in JM.joints.items() if k != "head"}))
    # a "run" standing still has no step: dropped and listed (default), or an error naming it
    one_step = replace(ds, metadata=ds.metadata.assign(behaviour=["idle", "run"]))
    with pytest.raises(
        ValueError, match="1 of 2 clips of dataset d1 .*clip i1: no run primitive found.*skip_unsegmentable: true"
    ):
        preprocess_dataset(one_step, JM, PrepOptions(skip_unsegmentable=False), name="d1")
    _, meta, dropped = preprocess_dataset(one_step, JM)
    assert meta["clip_id"].tolist() == ["w1_00"]
    assert dropped[["clip_id", "behaviour", "primitive", "n_frames", "reason"]].values.tolist() == [
        ["i1", "run", "", 90, "no primitive found"]
    ]


def test_too_short_primitives_are_dropped_and_counted(tmp_path):
    ds = load_dataset(small_dataset(tmp_path))
    assert too_short([Segment("a", 0, 1), Segment("b", 0, 23), Segment("c", 0, 24)], FPS, 0.2).tolist() == [
        True,
        True,
        False,
    ]  # 24 frames at 120 fps are 0.2 s: kept
    assert too_short([Segment("a", 5, 6)], FPS, 0.0).tolist() == [True]  # one frame is never a primitive
    segs = ["walk_start:0:70;walk_rightStance:70:71;walk_leftStance:71:93;walk_end:93:301", "idle:0:20"]
    short = replace(ds, metadata=ds.metadata.assign(segments=segs))
    opt = PrepOptions(use_ground_truth_segments=True)
    result = preprocess_dataset(short, JM, opt, name="d1")
    assert result.metadata["clip_id"].tolist() == ["w1_00", "w1_01"]
    assert result.metadata["primitive"].tolist() == ["walk_start", "walk_end"]
    assert [m.n_frames for m in result.motions] == [70, 208]
    assert result.dropped[["clip_id", "primitive", "start_frame", "n_frames", "reason"]].values.tolist() == [
        ["w1", "walk_rightStance", 70, 1, "too short"],
        ["w1", "walk_leftStance", 71, 22, "too short"],
        ["i1", "idle", 0, 20, "too short"],
    ]
    assert np.allclose(result.dropped["duration_s"], [1 / 120, 22 / 120, 20 / 120])
    summary = drop_summary(result, len(short), "d1", 0.2)
    assert "dataset d1: 2 clips -> 2 primitives from 1 clips (walk_end 1, walk_start 1)" in summary
    assert "dropped 3 primitives shorter than 0.2 s (idle 1, walk_leftStance 1, walk_rightStance 1)" in summary
    assert "dropped 1 clips with no primitive left (0 with none found, 1 with all too short; idle 1)" in summary
    # the threshold is a config value: at 0 only the one-frame sliver goes
    kept = preprocess_dataset(short, JM, replace(opt, min_primitive_s=0.0))
    assert kept.metadata["primitive"].tolist() == ["walk_start", "walk_leftStance", "walk_end", "idle"]
    # a clip left empty stops the run when skip_unsegmentable is off, naming it
    with pytest.raises(
        ValueError, match="1 of 2 clips of dataset d1.*clip i1: all 1 idle primitives shorter than 0.2 s"
    ):
        preprocess_dataset(short, JM, replace(opt, skip_unsegmentable=False), name="d1")


def test_preprocess_script_lists_and_logs_what_it_dropped(tmp_path, capsys):
    from rule_scripts import FakeSnakemake, Named, run, script

    ds = load_dataset(small_dataset(tmp_path))
    segs = ["walk_start:0:70;walk_rightStance:70:71;walk_end:71:301", "idle:0:20"]
    save_dataset(tmp_path / "short", [ds.motion(0), ds.motion(1)], ds.metadata.assign(segments=segs))
    out = tmp_path / "results" / "prep"

    def fake(options):
        return FakeSnakemake(
            tmp_path,
            "preprocess",
            input=Named(clips=str(tmp_path / "short" / "clips.npz")),
            output=Named(clips=str(out / "clips.npz"), metadata=str(out / "metadata.csv")),
            params=Named(settings=options, joint_map=None),
            wildcards=Named(dataset="mine"),
        )

    run(fake({"use_ground_truth_segments": True}), script("preprocess").main)
    dropped = pd.read_csv(out / "dropped.csv")
    assert dropped[["clip_id", "primitive", "n_frames", "reason"]].values.tolist() == [
        ["w1", "walk_rightStance", 1, "too short"],
        ["i1", "idle", 20, "too short"],
    ]
    assert pd.read_csv(out / "metadata.csv")["clip_id"].tolist() == ["w1_00", "w1_01"]
    log = (tmp_path / "preprocess.log").read_text()
    assert "WARNING dataset mine: 2 clips -> 2 primitives from 1 clips" in log and "shorter than 0.2 s" in log
    # nothing left: one error line naming the dataset, no output
    for f in out.iterdir():
        f.unlink()
    with pytest.raises(SystemExit):
        run(fake({"use_ground_truth_segments": True, "min_primitive_s": 5.0}), script("preprocess").main)
    err = capsys.readouterr().err
    assert "ERROR rule preprocess: preprocess_dataset: no primitive left in dataset mine (2 clips)" in err
    assert not any(out.iterdir())


def test_nothing_left_names_the_dataset_and_the_commonest_reason(tmp_path):
    ds = load_dataset(small_dataset(tmp_path))
    slivers = replace(ds, metadata=ds.metadata.assign(segments=["walk_start:0:3;walk_end:3:5", "idle:0:2"]))
    with pytest.raises(
        ValueError,
        match="no primitive left in dataset d1 \\(2 clips\\); most common reason: in 2 "
        "clips every primitive was shorter than prep.min_primitive_s = 0.2 s",
    ):
        preprocess_dataset(slivers, JM, PrepOptions(use_ground_truth_segments=True), name="d1")
    still = [turned(standing(90), 0.3 * k, (10.0 * k, 0.0)) for k in range(3)]
    meta = pd.DataFrame({"clip_id": ["a", "b", "c"], "subject": "s", "style": "neutral", "behaviour": "run"})
    save_dataset(tmp_path / "still", still, meta)
    with pytest.raises(
        ValueError,
        match="no primitive left in dataset d2 \\(3 clips\\); most common reason: no "
        "primitive found in 3 clips \\(run: 3\\)",
    ):
        preprocess_dataset(load_dataset(tmp_path / "still"), JM, name="d2")


def test_errors_name_the_clip():
    m = stepping(WALK_STEPS, 2.5)
    one = m.slice(0, 1)
    with pytest.raises(ValueError, match="resample_motion: clip w7_03 has 1 frame\\(s\\); need at least 2"):
        resample_motion(one, 30, clip_id="w7_03")
    with pytest.raises(ValueError, match="dtw_warp: source clip w7_03 has 1 frame\\(s\\)"):
        dtw_warp(one, m, clip_id="w7_03")
    with pytest.raises(ValueError, match="dtw_warp: reference clip r1 has 1 frame"):
        dtw_warp(m, one, reference_id="r1")
    with pytest.raises(ValueError, match="source clip w7_03 features contain NaN"):
        dtw_warp(np.full((10, 2), np.nan), np.zeros((13, 2)), clip_id="w7_03")
    with pytest.raises(ValueError, match="warp_to_median: clips w7_03 \\(1 frame\\(s\\)\\) have fewer than 2"):
        warp_to_median([m, one, m], clip_ids=["a", "w7_03", "b"])
    with pytest.raises(ValueError, match="apply_warp: clip w7_03: warp must be non-decreasing"):
        apply_warp(m, np.array([0.0, 3.0, 2.0]), clip_id="w7_03")
    bad = replace(m, root_pos=np.where(np.arange(m.n_frames)[:, None] == 5, np.nan, m.root_pos))
    with pytest.raises(ValueError, match="sample_motion: clip w7_03 has NaN or inf"):
        resample_motion(bad, 30, clip_id="w7_03")
    with pytest.raises(ValueError, match="alignment: clip w7_03 has NaN or inf"):
        align_motions([m, bad], JM, clip_ids=["a", "w7_03"])
    with pytest.raises(ValueError, match="alignment: clip w7_03 has no frames"):
        align_motions([m, m.slice(0, 0)], JM, clip_ids=["a", "w7_03"])
