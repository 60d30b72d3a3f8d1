"""Egges 2004 from a dataset to claims: idle clips, per-subject databases, the four
evaluations on small idle-like recordings, and the rule scripts' handling of bad input."""

import importlib.util
import json
import sys
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pandas as pd
import pytest
import yaml

from idle_toy import toy_recording
from motionvar.core import cmu_joint_map
from motionvar.egges2004 import IdleSettings
from motionvar.egges2004.experiments import (
    FittingParams, IdentificationParams, RepetitionParams, SpeedParams, fitting, identification, repetition, speed,
)
from motionvar.egges2004.pipeline import (
    category_check, fit_idle_model, idle_clips, load_model, model_recordings, save_model, split_clips,
)
from motionvar.io import load_dataset, save_dataset

ROOT = Path(__file__).resolve().parents[1]
SCRIPTS = ROOT / "workflow" / "scripts"
sys.path.insert(0, str(SCRIPTS))
from _rule import run  # noqa: E402
SEQUENCES = [
    ["left", "both", "right", "left", "both", "right"],
    ["right", "left", "both", "left", "right", "both"],
    ["both", "right", "left", "both", "left", "right"],
]


def _dataset(folder: Path, subjects: int = 3, clips: int = 3) -> Path:
    motions, rows = [], []
    for s in range(subjects):
        for c in range(clips):
            rest = list(np.random.default_rng(10 * s + c).uniform(3.0, 5.0, 6))
            m, truth = toy_recording(SEQUENCES[(s + c) % 3], rest, seed=10 * s + c, lean=0.05 * s)
            motions.append(m)
            postures = ";".join(f"{n}:{a}:{b}" for n, a, b in truth)
            rows.append({"clip_id": f"idle_{s}_{c}", "subject": f"{s + 1:02d}", "behaviour": "idle",
                         "idle_postures": postures})
    save_dataset(folder, motions, pd.DataFrame(rows))
    return folder


@pytest.fixture(scope="module")
def fitted(tmp_path_factory):
    folder = _dataset(tmp_path_factory.mktemp("prep"))
    dataset = load_dataset(folder)
    train, test = split_clips(idle_clips(dataset, "prep"), 1)
    model, recordings = fit_idle_model(train, test, cmu_joint_map(), IdleSettings(variation_pcs=4), seed=0)
    return folder, dataset, train, model, recordings


def test_model_has_one_database_per_subject_and_round_trips(fitted, tmp_path):
    folder, dataset, train, model, recordings = fitted
    assert list(model.databases) == ["01", "02", "03"]
    assert model.train_clips["01"] == ["idle_0_0", "idle_0_1"] and model.test_clips["01"] == ["idle_0_2"]
    check = category_check(model, train)
    assert check["category_accuracy"].tolist() == [1.0, 1.0, 1.0]
    path = tmp_path / "m.pkl"
    save_model(path, model)
    again = load_model(path)
    assert np.array_equal(again.pca.components_, model.pca.components_)
    tr, held = model_recordings(again, dataset, cmu_joint_map(), "prep")
    assert np.allclose(tr["02"][1].pcs, recordings["02"][1].pcs) and len(held["03"]) == 1


def test_bad_inputs_name_the_problem(fitted, tmp_path):
    folder, dataset, *_ = fitted
    with pytest.raises(ValueError, match="subjects .* 3 or fewer idle clips"):
        split_clips(idle_clips(dataset, "prep"), 3)
    walks = load_dataset(folder)
    walks.metadata["behaviour"] = "walk"
    with pytest.raises(ValueError, match="no idle clips"):
        idle_clips(walks, "prep")
    (tmp_path / "bad.pkl").write_bytes(b"not a pickle")
    with pytest.raises(ValueError, match="bad.pkl: not a readable idle model"):
        load_model(tmp_path / "bad.pkl")


def test_evaluations_on_toy_subjects(fitted):
    _, dataset, _, model, recordings = fitted
    jm = cmu_joint_map()
    _, held = model_recordings(model, dataset, jm, "prep")
    table, confusion, claim = identification(
        model, recordings, held, jm, IdentificationParams(window_s=5.0, feature_pcs=4, generated_s=20.0), 0.1, 0
    )
    assert set(table["source"]) == {"recorded (held out)", "generated (Egges 2004)", "Perlin noise on PCs"}
    assert confusion["confusion"].sum() == table.query("source.str.startswith('generated') and features == 'all'",
                                                       engine="python")["windows"].iloc[0]
    assert claim.claim_id == "egges2004.sec8.generated_idle_identifies_person"

    table, pooled, claim = repetition(
        model, recordings, RepetitionParams(sequence_s=30.0, window_s=3.0, fps=10.0, loop_clip_s=5.0), 0
    )
    assert pooled["looped recorded clip"].min() > 0.99 and pooled["looped rest variations"].min() > 0.99
    assert np.median(pooled["generated variations (Sec. 6)"]) < 0.99
    assert claim.verdict in ("reproduced", "partial", "not reproduced")

    # windows longer than half the recorded rests: those are left out, the rest is still measured
    table, pooled, claim = repetition(
        model, recordings, RepetitionParams(sequence_s=60.0, window_s=25.0, fps=10.0, loop_clip_s=5.0), 0
    )
    short = table[table["source"] == "recorded rest variations"]
    left_out = short["windows"] == 0
    assert left_out.any() and short.loc[left_out, "median_best_ncc"].isna().all()
    assert len(pooled["generated variations (Sec. 6)"]) == 3 * (60 // 25)
    assert f"{(~left_out).sum()} of them with recorded resting segments" in claim.note
    table, pooled, claim = repetition(
        model, recordings, RepetitionParams(sequence_s=60.0, window_s=29.0, fps=10.0, loop_clip_s=5.0), 0
    )
    assert len(pooled["recorded rest variations"]) == 0 and claim.verdict in ("partial", "not reproduced")

    table, example, claim = fitting(model, FittingParams(pairs=4, sequence_s=20.0, between_s=10.0), 0)
    assert table[["max_start_error_cm", "max_end_error_cm"]].to_numpy().max() < 1e-6
    assert claim.verdict in ("reproduced", "partial") and "01" in example

    table, claim = speed(model, SpeedParams(sequence_s=10.0, repeats=1, subjects=1), 0)
    assert len(table) == 1 and table["realtime_ratio"].iloc[0] > 1 and claim.verdict == "reproduced"


def _script(name):
    spec = importlib.util.spec_from_file_location(f"script_{name}", SCRIPTS / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _options(**sections):
    def defaults(schema):
        if schema.get("type") == "object" and "properties" in schema:
            return {k: defaults(v) for k, v in schema["properties"].items()}
        return schema.get("default")

    opts = defaults(yaml.safe_load((ROOT / "config" / "schema.yaml").read_text())["properties"]["idle"])
    for k, v in sections.items():
        opts[k].update(v)
    return opts


def test_model_script_writes_outputs_and_rejects_data_without_idle(fitted, tmp_path):
    folder = fitted[0]
    out = SimpleNamespace(model=str(tmp_path / "m.pkl"), categories=str(tmp_path / "c.csv"),
                          graph=str(tmp_path / "g.png"))
    fake = SimpleNamespace(
        rule="egges2004_model", input=SimpleNamespace(clips=str(folder / "clips.npz")), output=out,
        params=SimpleNamespace(options=_options(analysis={"variation_pcs": 4}), joint_map=None),
        wildcards={}, log=[str(tmp_path / "model.log")],
    )
    run(fake, _script("egges2004_model").main)
    assert Path(out.graph).stat().st_size > 0 and len(pd.read_csv(out.categories)) == 3

    walks = load_dataset(folder)
    walks.metadata["behaviour"] = "walk"
    other = tmp_path / "walks"
    save_dataset(other, list(walks), walks.metadata.drop(columns=["n_frames", "fps"]))
    fake.input = SimpleNamespace(clips=str(other / "clips.npz"))
    fake.output = SimpleNamespace(model=str(tmp_path / "m2.pkl"), categories=str(tmp_path / "c2.csv"),
                                  graph=str(tmp_path / "g2.png"))
    with pytest.raises(SystemExit) as exc:
        run(fake, _script("egges2004_model").main)
    assert exc.value.code == 1
    assert "no idle clips" in (tmp_path / "model.log").read_text()
    assert not Path(fake.output.model).exists()
    assert json.dumps(_options())  # the schema's defaults are plain data
