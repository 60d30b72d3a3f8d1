"""Progress lines of long loops (motionvar.core.progress): a line at the stated interval
(EVERY_S seconds between two lines of one loop, plus the first and the last step), read
back from a training rule's log; and in the CI run's logs every progress line follows the
format and the interval."""

from __future__ import annotations

import logging
import re

import pandas as pd
import pytest
from rule_scripts import FakeSnakemake, Named, helper_module, run, script

from motionvar.core import progress
from motionvar.core.progress import PROGRESS_LINE, ProgressLog

pytestmark = pytest.mark.usefixtures("one_torch_thread")  # tests/conftest.py


def progress_runs(text: str, label_start: str = "") -> list[list[dict]]:
    """The progress lines of a log, parsed, one list per loop (a loop starts again where its
    step does not grow)."""
    runs: dict[str, list[list[dict]]] = {}
    for raw in text.splitlines():
        message = raw.split(" INFO ", 1)[-1]
        m = PROGRESS_LINE.fullmatch(message)
        if not m or not m["label"].startswith(label_start):
            continue
        d = {k: v for k, v in m.groupdict().items()}
        d["step"], d["elapsed"] = int(d["step"]), float(d["elapsed"])
        loops = runs.setdefault(d["label"], [])
        if not loops or d["step"] <= loops[-1][-1]["step"]:
            loops.append([])
        loops[-1].append(d)
    return [loop for loops in runs.values() for loop in loops]


def assert_steady(loop: list[dict], every_s: float) -> None:
    """First step first (1, or 0 for a loop that logs before its first step); between lines
    before the last, at least ``every_s`` seconds (the elapsed field has 0.1 s resolution)."""
    assert loop[0]["step"] <= 1, loop[0]
    inner = loop[:-1] if loop[-1]["total"] and loop[-1]["step"] == int(loop[-1]["total"]) else loop
    for a, b in zip(inner, inner[1:]):
        assert b["elapsed"] - a["elapsed"] >= every_s - 0.1, (a, b)


def test_lines_at_the_interval_with_first_and_last_step(monkeypatch, caplog):
    clock = iter(float(t) for t in range(1000))  # one second per step
    monkeypatch.setattr(progress.time, "perf_counter", lambda: next(clock))
    log = ProgressLog("toy epoch", 35, every_s=10.0)
    with caplog.at_level(logging.INFO, logger="motionvar.progress"):
        for epoch in range(1, 36):
            log(epoch, 1.0 / epoch)
    lines = [r.getMessage() for r in caplog.records]
    assert [PROGRESS_LINE.fullmatch(x)["step"] for x in lines] == ["1", "11", "21", "31", "35"]
    assert lines[1] == "toy epoch 11/35, loss 0.0909091, elapsed 11.0 s, remaining ~24 s"
    bound = ProgressLog("fit iteration", 200, at_most=True, every_s=0).line(10.0, None)
    assert bound == "fit iteration 0/200, elapsed 10.0 s" and PROGRESS_LINE.fullmatch(bound)


def test_autoencoder_rule_log_shows_epochs_at_the_interval(tmp_path, monkeypatch):
    """Rule du2022_style_autoencoder through its script adapter, with the interval set to
    0.2 s: its log holds epoch lines 0.2 s or more apart, from epoch 1 to the last, with
    loss, elapsed and remaining time; the numbers are the history's."""
    from style_toy import tiny_settings
    from style_toy import toy_walk as style_toy_walk

    from motionvar.io import save_dataset

    every = 0.2
    monkeypatch.setattr(progress, "EVERY_S", every)
    epochs = 30
    motions = [style_toy_walk(n_frames=70, seed=k) for k in range(4)]
    meta = pd.DataFrame(
        {
            "clip_id": [f"c{k}" for k in range(4)],
            "primitive": "walk_leftStance",
            "style": "neutral",
            "variant": "forward",
            "turn_deg": 0.0,
        }
    )
    save_dataset(tmp_path / "data", motions, meta)
    out = tmp_path / "models"
    settings = tiny_settings(ae_epochs=epochs).to_dict()
    settings["autoencoder"]["max_windows"] = 48  # epochs long enough for several lines
    fake = FakeSnakemake(
        tmp_path,
        "du2022_style_autoencoder",
        input=Named(clips=str(tmp_path / "data" / "clips.npz"), metadata=str(tmp_path / "data" / "metadata.csv")),
        output=Named(
            model=str(out / "autoencoder.pt"),
            settings=str(out / "autoencoder.json"),
            history=str(out / "autoencoder_history.csv"),
        ),
        params=Named(settings=settings, joint_map=None),
    )
    helper_module("_style")
    run(fake, script("du2022_style_autoencoder").main)
    text = (tmp_path / "du2022_style_autoencoder.log").read_text()
    loops = progress_runs(text, "autoencoder epoch")
    assert len(loops) == 1, text
    loop = loops[0]
    history = pd.read_csv(out / "autoencoder_history.csv")
    assert loop[-1]["step"] == epochs and loop[-1]["remaining"] == "0"
    assert_steady(loop, every)
    took = history["seconds"].iloc[-1]
    assert len(loop) - 1 <= took / every + 1, text  # no more lines than the interval allows
    assert len(loop) >= min(3, 1 + int(took / every)), text  # first, last, one per interval (a fast machine: fewer)
    for line in loop:
        assert float(line["loss"]) == pytest.approx(history["loss"].iloc[line["step"] - 1], rel=1e-5)


@pytest.mark.e2e
def test_ci_run_logs_show_progress_at_the_interval(ci_run):
    """Every progress line in the CI run's logs follows the format and, within its loop,
    the interval; the SFPCA, GPLVM and style training rules log theirs."""
    logs = ci_run.work / "results" / "synthetic" / "logs"
    labels = set()
    for path in sorted(logs.rglob("*.log")):
        for loop in progress_runs(path.read_text(errors="replace")):
            assert_steady(loop, progress.EVERY_S)
            labels.add(re.sub(r" \(.*?\)", "", loop[0]["label"]))
    for expected in ("SFPCA L-BFGS-B iteration", "autoencoder epoch", "VAE epoch", "CVAE epoch"):
        assert expected in labels, labels
    assert any(label.startswith("Bayesian GPLVM") for label in labels), labels
