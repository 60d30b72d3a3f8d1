"""Egges 2004 from a dataset to claims, at library level: idle clips, per-subject
databases, the model file (.npz + .json) round trip, the evaluations on small idle-like
recordings and their figures, and bad input named."""

import json
from dataclasses import fields
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np
import pytest
import yaml
from claim_checks import check_value_bound
from egges2004_toy import toy_dataset
from matplotlib.figure import Figure

from motionvar.claims import EvaluationResult
from motionvar.core import cmu_joint_map
from motionvar.egges2004 import figures
from motionvar.egges2004.evaluations import category_check, idle_animation, pc_extrema
from motionvar.egges2004.evaluations.fitting import FIGURE_BALANCE_S, fitting
from motionvar.egges2004.evaluations.identification import binomial_power, identification
from motionvar.egges2004.evaluations.repetition import repetition
from motionvar.egges2004.evaluations.speed import speed
from motionvar.egges2004.pipeline import (
    clip_part,
    fit_idle_model,
    idle_clips,
    model_recordings,
    split_clips,
    split_idle,
)
from motionvar.egges2004.settings import Egges2004Settings
from motionvar.egges2004.storage import load_idle_model, save_idle_model
from motionvar.io import load_dataset

ROOT = Path(__file__).resolve().parents[2]

# the toy model: 4 varied PCs (the toy recordings are short)
SETTINGS = Egges2004Settings.from_dict({"analysis": {"variation_pcs": 4}})


def with_(section, **changes):
    """SETTINGS with ``changes`` in one subsection."""
    return SETTINGS.replace(**{section: getattr(SETTINGS, section).replace(**changes)})


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    plt.close("all")


@pytest.fixture(scope="module")
def fitted(tmp_path_factory):
    folder = toy_dataset(tmp_path_factory.mktemp("prep"))
    dataset = load_dataset(folder)
    train, test = split_clips(idle_clips(dataset, "prep"), 1)
    model, recordings = fit_idle_model(train, test, cmu_joint_map(), SETTINGS)
    return folder, dataset, train, model, recordings


def _assert_same(a, b, where="model"):
    """Exact equality of two fitted objects, field by field (arrays: values, dtype, shape)."""
    if isinstance(a, np.ndarray):
        assert isinstance(b, np.ndarray) and a.dtype == b.dtype, where
        assert np.array_equal(a, b, equal_nan=a.dtype.kind == "f"), where
    elif hasattr(a, "__dataclass_fields__"):
        assert type(a) is type(b), where
        for f in fields(a):
            _assert_same(getattr(a, f.name), getattr(b, f.name), f"{where}.{f.name}")
    elif hasattr(a, "__dict__") and any(k.endswith("_") for k in vars(a)):  # an estimator: its learned attributes
        assert type(a) is type(b), where
        for k in [k for k in vars(a) if k.endswith("_")]:
            _assert_same(getattr(a, k), getattr(b, k), f"{where}.{k}")
    elif isinstance(a, dict):
        assert list(a) == list(b), where
        for k in a:
            _assert_same(a[k], b[k], f"{where}[{k!r}]")
    elif isinstance(a, (list, tuple)):
        assert type(a) is type(b) and len(a) == len(b), where
        for i, (x, y) in enumerate(zip(a, b)):
            _assert_same(x, y, f"{where}[{i}]")
    else:
        assert type(a) is type(b) and a == b, where


def test_model_has_one_database_per_subject_and_round_trips(fitted, tmp_path):
    folder, dataset, train, model, recordings = fitted
    assert list(model.databases) == ["01", "02", "03"]
    assert model.train_clips["01"] == ["idle_0_0", "idle_0_1"] and model.test_clips["01"] == ["idle_0_2"]
    paths = save_idle_model(tmp_path / "idle_model.npz", model)
    assert sorted(p.name for p in paths) == ["idle_model.json", "idle_model.npz"]
    settings = json.loads((tmp_path / "idle_model.json").read_text())
    assert settings["kind"] == "egges2004_idle_model"
    assert [s["subject"] for s in settings["subjects"]] == ["01", "02", "03"]
    with np.load(tmp_path / "idle_model.npz", allow_pickle=False) as z:  # plain arrays only
        assert "pca.components" in z.files
    again = load_idle_model(tmp_path / "idle_model.npz")
    _assert_same(model, again)
    tr, held = model_recordings(again, dataset, cmu_joint_map(), "prep")
    assert np.array_equal(tr["02"][1].pcs, recordings["02"][1].pcs) and len(held["03"]) == 1


def test_categories_match_the_truth_and_draw(fitted):
    _, _, train, model, _ = fitted
    result = category_check(model, train, SETTINGS.replace(figure_subjects=2))
    assert isinstance(result, EvaluationResult) and result.claims == []
    assert result.table["category_accuracy"].tolist() == [1.0, 1.0, 1.0]
    assert list(result.figure["graphs"]) == ["01", "02"]
    assert isinstance(figures.draw_categories(result), Figure)


def test_a_subject_with_too_few_clips_is_left_out_with_a_line(fitted, caplog):
    """held_out_by clips: a subject with no more clips than held out is left out of the model,
    named in the log; the others are split as before."""
    _, dataset, *_ = fitted
    clips = idle_clips(dataset, "prep")
    first = next(iter(clips))
    short = {s: (c[:1] if s == first else c) for s, c in clips.items()}
    with caplog.at_level("WARNING"):
        train, test = split_clips(short, 1)
    assert first not in train and first not in test and set(train) == set(clips) - {first}
    assert f"subject {first} left out of Egges 2004: 1 idle clip(s)" in caplog.text


def test_time_split_holds_out_the_end_of_every_recording(fitted):
    """held_out_by time: every recording's first 70 % trains and its last 30 % is held out, as
    parts named <clip_id>[start:stop]; model_recordings finds the parts in the dataset again."""
    _, dataset, *_ = fitted
    clips = idle_clips(dataset, "prep")
    settings = SETTINGS.replace(held_out_by="time", held_out_fraction=0.3)
    train, test = split_idle(clips, settings)
    assert set(train) == set(test) == set(clips)
    for subject, rows in clips.items():
        assert len(train[subject]) == len(test[subject]) == len(rows)
        for (row, motion), (tr, tm), (te, em) in zip(rows, train[subject], test[subject]):
            cut = clip_part(tr["clip_id"])[1].stop  # a rest within 3 s of the 70 % point
            assert abs(cut - (motion.n_frames - round(0.3 * motion.n_frames))) <= round(3 * motion.fps)
            assert clip_part(tr["clip_id"]) == (row["clip_id"], slice(0, cut))
            assert clip_part(te["clip_id"]) == (row["clip_id"], slice(cut, motion.n_frames))
            assert np.array_equal(np.concatenate([tm.rotations, em.rotations]), motion.rotations)
    model, _ = fit_idle_model(train, test, cmu_joint_map(), settings)
    trained, held = model_recordings(model, dataset, cmu_joint_map(), "prep")
    subject = next(iter(held))
    assert len(held[subject][0].pcs) == test[subject][0][1].n_frames
    assert clip_part("a[b]") == ("a[b]", slice(None))
    with pytest.raises(ValueError, match="held_out_fraction"):
        SETTINGS.replace(held_out_fraction=1.0)


def test_the_cut_falls_in_a_rest_not_in_a_shift():
    """A pelvis that rests, shifts between 60 and 62 s and rests again: asked to cut at 61 s,
    the cut moves into a rest within the search window, never into the shift."""
    from motionvar.core import Motion, cmu_skeleton
    from motionvar.egges2004.pipeline import rest_cut

    fps, n = 24.0, 24 * 100
    t = np.arange(n) / fps
    x = np.clip((t - 60.0) / 2.0, 0.0, 1.0) * 15.0  # 15 cm over 2 s
    root = np.stack([x, np.full(n, 90.0), np.zeros(n)], axis=1)
    skel = cmu_skeleton()  # only the root moves
    rot = np.zeros((n, skel.n_joints, 4))
    rot[..., 0] = 1.0
    motion = Motion(skel, root, rot, fps)
    cut = rest_cut(motion, int(61 * fps), search_s=3.0)
    assert not 59.5 * fps <= cut <= 62.5 * fps and abs(cut - 61 * fps) <= 3 * fps
    assert rest_cut(motion, int(30 * fps), search_s=0.0) == int(30 * fps)


def test_bad_inputs_name_the_problem(fitted, tmp_path):
    folder, dataset, _, model, _ = fitted
    with pytest.raises(ValueError, match="every subject has 3 or fewer idle clips"):
        split_clips(idle_clips(dataset, "prep"), 3)
    walks = load_dataset(folder)
    walks.metadata["behaviour"] = "walk"
    with pytest.raises(ValueError, match="no idle clips"):
        idle_clips(walks, "prep")
    with pytest.raises(FileNotFoundError, match="missing.npz: model file missing"):
        load_idle_model(tmp_path / "missing.npz")
    save_idle_model(tmp_path / "m", model)
    (tmp_path / "bad.npz").write_bytes(b"not an npz")
    (tmp_path / "bad.json").write_text((tmp_path / "m.json").read_text())
    with pytest.raises(ValueError, match="bad.npz: not a readable model array file"):
        load_idle_model(tmp_path / "bad.npz")
    (tmp_path / "other.npz").write_bytes((tmp_path / "m.npz").read_bytes())
    (tmp_path / "other.json").write_text(json.dumps({"kind": "ma2010.ClipSet"}))
    with pytest.raises(ValueError, match="other.json: not a saved egges2004_idle_model"):
        load_idle_model(tmp_path / "other.npz")
    with np.load(tmp_path / "m.npz") as z:
        np.savez(tmp_path / "cut.npz", **{k: z[k] for k in z.files if k != "s1.animations"})
    (tmp_path / "cut.json").write_text((tmp_path / "m.json").read_text())
    with pytest.raises(ValueError, match="cut.npz/.json: not a complete idle model .*s1.animations"):
        load_idle_model(tmp_path / "cut.npz")


def test_evaluations_on_toy_subjects(fitted):
    _, dataset, _, model, recordings = fitted
    jm = cmu_joint_map()
    _, held = model_recordings(model, dataset, jm, "prep")
    settings = with_("identification", window_s=5.0, feature_pcs=4, generated_s=20.0)
    result = identification(model, recordings, held, jm, settings)
    table, (claim,) = result.table, result.claims
    assert set(table["source"]) == {"recorded (held out)", "generated (Egges 2004)", "Perlin noise on PCs"}
    assert (
        result.figure["confusion"].sum()
        == table.query("source.str.startswith('generated') and features == 'all'", engine="python")["windows"].iloc[0]
    )
    assert result.figure["labels"] == ["01", "02", "03"] and result.figure["window_s"] == 5.0
    assert claim.claim_id == "egges2004.sec8.generated_idle_identifies_person"
    assert set(table["features"]) == {"all", "posture", "dynamics"}
    gen = table[table["source"] == "generated (Egges 2004)"].set_index("features")
    m = result.measurements
    for fs in ("all", "dynamics"):  # the paired comparison with the Perlin windows, per feature set
        assert gen.loc[fs, "better_than_perlin"] + gen.loc[fs, "worse_than_perlin"] <= gen.loc[fs, "windows"]
        assert m["vs_perlin"][fs]["p_value"] == gen.loc[fs, "p_vs_perlin"]
    rec = table[table["source"] == "recorded (held out)"].set_index("features")
    for fs in ("all", "dynamics"):  # power at the recordings' accuracy with the generated windows
        assert m["power"][fs] == binomial_power(int(gen.loc[fs, "windows"]), 1 / 3, rec.loc[fs, "accuracy"], 0.01)
    # 12 windows of 5 s: a failing test against chance has too little power to count
    tests = (gen.loc["all", "p_value"], gen.loc["all", "p_vs_perlin"], gen.loc["dynamics", "p_value"])
    weak = [t >= 0.01 and m["power"][fs] < 0.8 for fs, t in (("all", tests[0]), ("dynamics", tests[2]))]
    assert (claim.verdict == "not testable") == any(weak)
    if any(weak):
        assert claim.value is None and "Too few generated windows" in claim.note
    else:
        assert (claim.value, claim.bound, claim.direction) == (max(tests), 0.01, "<")
    check_value_bound(claim)  # reproduced needs all three tests below alpha
    assert isinstance(figures.draw_identification(result), Figure)

    params = with_("repetition", sequence_s=30.0, window_s=3.0, fps=10.0, loop_clip_s=5.0)
    result = repetition(model, recordings, params)
    pooled, (claim, structure) = result.figure["pooled"], result.claims
    assert structure.claim_id == "egges2004.sec6.variations_keep_recorded_structure"
    check_value_bound(structure)
    spectral = result.table.set_index(["subject", "source"])["spectral_distance_db"]
    assert (
        spectral.xs("white noise (recorded variance)", level=1).min()
        > spectral.xs("generated variations (Sec. 6)", level=1).max()
    )
    assert spectral.xs("recorded idle", level=1).isna().all()  # balance shifts are not variations
    assert set(result.figure["spectra"]["psd"]) >= {"generated variations (Sec. 6)", "recorded rest variations"}
    assert pooled["looped recorded clip"].min() > 0.99 and pooled["looped rest variations"].min() > 0.99
    assert np.median(pooled["generated variations (Sec. 6)"]) < 0.99
    assert claim.verdict in ("reproduced", "partial", "not reproduced") and result.figure["n_pcs"] == 4
    cut, rec = (
        np.median(pooled[k]) for k in ("generated variations, cut to the recorded length", "recorded rest variations")
    )
    tol = Egges2004Settings().repetition.tolerance
    assert (claim.value, claim.bound, claim.direction) == (cut, pytest.approx(rec * (1 + tol)), "<=")
    check_value_bound(claim)
    assert isinstance(figures.draw_repetition(result), Figure)

    # windows longer than half the recorded rests: those are left out, the rest is still measured
    params = with_("repetition", sequence_s=60.0, window_s=25.0, fps=10.0, loop_clip_s=5.0)
    result = repetition(model, recordings, params)
    short = result.table[result.table["source"] == "recorded rest variations"]
    left_out = short["windows"] == 0
    assert left_out.any() and short.loc[left_out, "median_best_ncc"].isna().all()
    assert len(result.figure["pooled"]["generated variations (Sec. 6)"]) == 3 * (60 // 25)
    assert f"{(~left_out).sum()} of them with recorded resting segments" in result.claims[0].note
    params = with_("repetition", sequence_s=60.0, window_s=29.0, fps=10.0, loop_clip_s=5.0)
    result = repetition(model, recordings, params)
    assert len(result.figure["pooled"]["recorded rest variations"]) == 0
    assert result.claims[0].verdict in ("partial", "not reproduced")
    assert np.isnan(result.claims[0].bound)  # no recorded rest to compare with

    result = fitting(model, with_("fitting", pairs=4, sequence_s=20.0, between_s=10.0))
    assert result.table[["max_start_error_cm", "max_end_error_cm"]].to_numpy().max() < 1e-6
    t = result.table
    assert (t["velocity_kink"] == (t["max_junction_accel_ratio"] > 1)).all()
    assert "velocity kink at the junctions" in result.claims[0].measured
    assert result.claims[0].verdict in ("reproduced", "partial")
    linear = result.table[result.table["ramp"] == "linear"]
    assert result.claims[0].value == linear["max_junction_step_ratio"].max() and result.claims[0].bound == 1.0
    check_value_bound(result.claims[0])
    f = result.figure
    assert f["subject"] == "01" and set(f["fitted"]) == {"linear", "smoothstep"}
    for curve in f["fitted"].values():  # Fig. 4: the fitted shift starts at p and ends at q
        assert np.isclose(curve[0], f["p"]) and np.isclose(curve[-1], f["q"])
    assert len(f["balance"]) == int(round(FIGURE_BALANCE_S * f["fps"])) + 1
    assert isinstance(figures.draw_fitting(result), Figure)

    result = speed(model, with_("speed", sequence_s=10.0, repeats=1, subjects=1))
    assert len(result.table) == 1 and result.table["realtime_ratio"].iloc[0] > 1
    assert result.claims[0].verdict == "reproduced"
    assert result.claims[0].value == result.table["realtime_ratio"].min() and result.claims[0].unit == "ratio"
    assert "mean of 1 run) on " in result.claims[0].measured and result.measurements["cores"] >= 1
    check_value_bound(result.claims[0])
    assert isinstance(figures.draw_speed(result), Figure)


def test_extrema_figure_and_animation(fitted):
    _, _, _, model, recordings = fitted
    data = pc_extrema(model, recordings, SETTINGS.replace(figure_subjects=2))
    assert [p["subject"] for p in data["panels"]] == ["01", "02"] and data["pc"] == 0
    for p in data["panels"]:
        assert len(p["extrema"]) >= 2 and np.all(np.diff(p["extrema"]) > 0) and len(p["is_max"]) == len(p["extrema"])
    assert isinstance(figures.draw_pc_extrema(data), Figure)
    motions, labels = idle_animation(model, with_("animation", seconds=1.0).replace(figure_subjects=2))
    assert labels == ["subject 01 (generated)", "subject 02 (generated)"]
    assert [m.n_frames for m in motions] == [int(round(model.databases["01"].fps)) + 1] * 2


def test_settings_from_the_schema_defaults_are_the_class_defaults():
    """The rule scripts build Egges2004Settings from config.egges2004, the schema filling
    what a config leaves out: the schema's defaults (plain data) build the class's defaults,
    and an unknown or misplaced key is named with its section."""

    def defaults(schema):
        if schema.get("type") == "object" and "properties" in schema:
            return {k: defaults(v) for k, v in schema["properties"].items()}
        return schema.get("default")

    opts = defaults(yaml.safe_load((ROOT / "config" / "schema.yaml").read_text())["properties"]["egges2004"])
    assert json.dumps(opts)
    assert Egges2004Settings.from_dict(opts) == Egges2004Settings()
    assert Egges2004Settings.from_dict(opts).to_dict() == opts
    with pytest.raises(ValueError, match="egges2004.repetition.perlin_frequency_hz"):
        Egges2004Settings.from_dict({"repetition": {"perlin_frequency_hz": 1.0}})


def test_components_for_a_share_of_the_posture_variance(fitted):
    """The fewest leading PCs holding a share of the variance: all of it needs every PC, a
    first PC alone holds its own share."""
    *_, model, _ = fitted
    pca = model.pca
    first = pca.explained_variance_[0] / pca.explained_variance_.sum()
    assert pca.components_for(first * 0.999) == 1 and pca.components_for(1.0) <= len(pca.explained_variance_)
    assert pca.components_for(0.9) <= pca.components_for(0.95) <= pca.components_for(0.99)
