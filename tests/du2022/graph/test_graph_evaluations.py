"""Du 2022 ch. 4 the evaluations Fig. 4.9, Fig. 4.10 and Sec. 4.6.1 on a dataset, their verdicts, and the settings' one owner."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from claim_checks import check_value_bound
from graph_toy import OPT

from motionvar.core import cmu_joint_map
from motionvar.du2022.graph import MotionPrimitive, PrimitiveOptions, SynthesisSettings, primitive_clips
from motionvar.du2022.graph.evaluations import evaluate_fig4_9, evaluate_fig4_10, evaluate_sec4_6_1, motion_bytes
from motionvar.du2022.graph.figures import animate_fig4_10, draw_fig4_9, draw_fig4_10, draw_sec4_6_1
from motionvar.du2022.graph.settings import GraphSettings


def test_fig4_9_coverage_of_the_training_clips(prim, dataset):
    settings = GraphSettings.from_dict({"seed": 0, "diversity": {"n_samples": 2000, "grid": 32}})
    result = evaluate_fig4_9({"walk_leftStance": prim, "pick_reach": prim}, dataset, cmu_joint_map(), settings)
    t = result.table
    assert len(t) == 9 and list(t["joint"].unique()) == ["left_ankle", "left_hand", "right_hand"]
    assert list(t["n_training"]) == [4] * 3 + [8] * 6 and t["coverage"].between(0, 1).all()
    assert t["samples_inside"].between(0, 1).all()
    assert result.claims[0].claim_id == "du2022.fig4_9.samples_cover_training"
    worst = min(t["coverage"].min(), t["samples_inside"].min())
    assert result.claims[0].value == worst and result.claims[0].bound == 0.9
    check_value_bound(result.claims[0])
    assert result.figure["panels"][0]["density"].shape == (32, 32)
    assert len(draw_fig4_9(result).axes) == 9


def test_fig4_10_follows_path_and_reaches(prim, right, clips, dataset, tmp_path):
    pick = MotionPrimitive("pick_reach", OPT).fit(clips[8:])  # the dataset's pick_reach clips
    models = {"walk_leftStance": prim, "walk_rightStance": right, "pick_reach": pick}
    synthesis = {"path": [[0.0, 0.0], [200.0, 0.0]], "reach_targets": 2, "tree_samples": 300, "max_nfev": 30}
    synthesis.update(reach_offset_cm=1.0, reach_range_samples=2000)  # the toy's hand range is nearly a line
    settings = GraphSettings.from_dict({"synthesis": dict(synthesis, max_steps=4)})
    st = settings.synthesis
    assert (st.look_ahead, st.receding_horizon, st.joint_steps) == (2, False, "all")  # the schema's defaults
    result = evaluate_fig4_10(models, dataset, cmu_joint_map(), settings)
    t = result.table
    assert list(t["task"].unique()) == ["path", "path_greedy", "path_receding", "reach"]
    assert (t["task"] == "reach").sum() == 2
    greedy = t[t["task"] == "path_greedy"]
    assert (greedy["position_error_cm"] <= greedy["position_error_tree_cm"] + 1e-6).all()  # LM improves the seed
    assert np.allclose(greedy["position_error_cm"], greedy["position_error_step_cm"])  # no later optimisation
    path = t[t["task"] == "path"]
    assert (path["max_deviation_cm"] >= path["path_distance_cm"] - 1e-9).all()
    assert "T = 2 by the mean motions" in result.claims[0].note
    assert "(greedy, receding)" in result.claims[0].note
    assert {"path_greedy", "path_receding"} <= set(result.table["task"])
    assert [c.claim_id for c in result.claims] == ["du2022.fig4_10.follows_path", "du2022.fig4_10.reaches_targets"]
    p = result.measurements["path"]
    assert p["max_deviation_cm"] == pytest.approx(path["max_deviation_cm"].max())
    assert result.claims[0].value == pytest.approx(max(p["mean_step_cm"] / 10.0, p["max_deviation_cm"] / 20.0))
    r = result.measurements["reach"]
    assert r["log_prob"] == pytest.approx(list(t.loc[t["task"] == "reach", "log_prob"]))
    assert min(r["training_distance_cm"]) <= 1.0 + 1e-9  # each target 1 cm from a training hand position
    for c in result.claims:
        check_value_bound(c)
    assert len(result.figure["reaches"]) == 2
    assert len(draw_fig4_10(result).axes) == 2
    animate_fig4_10(result, tmp_path / "fig4_10.gif", max_seconds=0.5, panel_px=60)
    assert (tmp_path / "fig4_10.gif").stat().st_size > 0
    far = GraphSettings.from_dict({"synthesis": dict(synthesis, max_steps=2, reach_offset_cm=500.0)})
    none = evaluate_fig4_10(
        models, dataset, cmu_joint_map(), far.replace(synthesis=far.synthesis.replace(compare_variants=False))
    )
    assert (none.table["task"] == "reach").sum() == 0 and none.claims[1].verdict == "not testable"
    check_value_bound(none.claims[1])
    assert len(draw_fig4_10(none).axes) == 2


def test_fig4_10_verdicts_follow_the_numbers():
    """follows_path needs both the mean step error (<= 10 cm) and the largest distance from the
    path (<= 20 cm), partial up to twice each; reaches_targets needs each target reached (<= 2 cm)
    with log p at or above the samples' 5th percentile."""
    from motionvar.du2022.claims import CLAIMS
    from motionvar.du2022.graph.evaluations.fig4_10 import fig4_10_measurements

    specs = {s.claim_id.rsplit(".", 1)[1]: s for s in CLAIMS if s.evaluation == "du2022_fig4_10"}
    ref = dict(offset_cm=15.0, range_samples=1000, draws=100, natural_log_prob=-5.0, train_log_prob_p5=0.0)

    def verdicts(step, deviation, reach, log_prob):
        path = [
            dict(
                task="path",
                position_error_tree_cm=step,
                position_error_step_cm=step,
                position_error_cm=step,
                heading_error_deg=1.0,
            )
        ] * 3
        rows = [
            dict(
                task="reach",
                position_error_tree_cm=5.0,
                position_error_cm=e,
                log_prob=lp,
                target_training_distance_cm=15.0,
            )
            for e, lp in zip(reach, log_prob)
        ]
        m = fig4_10_measurements(pd.DataFrame(path + rows), 3, 2.0, deviation, ref)
        return tuple(specs[k].claim(m).verdict for k in ("follows_path", "reaches_targets"))

    assert verdicts(3.0, 15.0, [0.1, 1.5], [-1.0, -4.9]) == ("reproduced", "reproduced")
    assert verdicts(3.0, 30.0, [0.1, 2.5], [-1.0, -4.9]) == ("partial", "partial")
    assert verdicts(12.0, 15.0, [0.1, 0.1], [-1.0, -5.1]) == ("partial", "partial")
    assert verdicts(25.0, 15.0, [3.0, 0.1], [-1.0, -9.0]) == ("not reproduced", "not reproduced")
    assert verdicts(3.0, 41.0, [], [])[0] == "not reproduced"


def test_fig4_10_training_latents_and_targets(clips, dataset):
    """The training clips' latent vectors are the scores of the fit (the model keeps no data);
    other clips are refused. Each reaching target lies reach_offset_cm from a training hand
    position and within the reach bound of a natural sample's hand (inside the range)."""
    from motionvar.du2022.graph.evaluations.fig4_10 import _reach_targets

    pick = MotionPrimitive("pick_reach", OPT).fit(clips[8:])
    assert np.allclose(pick.training_latents(clips[8:]), pick.training_latent_, atol=1e-9)
    with pytest.raises(ValueError, match="toy.npz: the 8 clips of pick_reach are not the ones"):
        pick.training_latents(clips[:8], "toy.npz")
    rng = np.random.default_rng(0)
    ends = rng.normal(size=(5, 3)) * 10.0
    grid = np.stack(np.meshgrid(*[np.arange(-40.0, 41.0, 1.0)] * 3), -1).reshape(-1, 3)
    inside = grid[np.linalg.norm(grid, axis=1) < 25.0]  # the range: a ball of 25 cm
    st = SynthesisSettings(reach_targets=4, reach_offset_cm=15.0)
    targets, draws = _reach_targets(ends, inside, st, rng)
    assert len(targets) == 4 and draws == 200
    assert np.isclose(np.linalg.norm(targets[:, None] - ends[None], axis=-1), 15.0).any(axis=1).all()
    assert (np.linalg.norm(targets, axis=1) < 25.0 + 2.0).all()
    outside, _ = _reach_targets(ends, inside + 1000.0, st, rng)
    assert outside.shape == (0, 3)
    with pytest.raises(ValueError, match="reach_range_samples"):
        SynthesisSettings(reach_range_samples=10)


def test_sec4_6_1_compactness(prim, dataset, tmp_path):
    files = prim.save(tmp_path / "walk_leftStance")
    size = sum(f.stat().st_size for f in files)
    dense = pd.DataFrame(dict(start_frame=[0, 0], stop_frame=[50, 70]))
    models = {"walk_leftStance": prim, "pick_reach_dense": prim}
    result = evaluate_sec4_6_1(models, {"walk_leftStance": size, "pick_reach_dense": size}, dataset.metadata, dense)
    t = result.table.set_index("primitive")
    assert list(t.index) == ["walk_leftStance", "pick_reach_dense", "all"]
    J = prim.skeleton.n_joints
    assert t.loc["pick_reach_dense", "data_bytes"] == motion_bytes(120, J)
    assert t.loc["walk_leftStance", "clips"] == 4 and t.loc["all", "model_bytes"] == 2 * size
    assert result.claims[0].claim_id == "du2022.sec4_6_1.model_much_smaller_than_data"
    assert result.claims[0].value == t.loc["all", "ratio"]
    check_value_bound(result.claims[0])
    assert len(draw_sec4_6_1(result).axes) == 1
    assert result.claims[1].verdict == "not applicable"  # no model of half of the clips given
    with pytest.raises(ValueError, match="dense picks"):
        evaluate_sec4_6_1(models, {"walk_leftStance": size, "pick_reach_dense": size}, dataset.metadata)


def test_sec4_6_1_model_size_at_half_of_the_clips(clips, dataset, tmp_path):
    """Sec. 4.6.1 at N and 2N clips: each primitive refitted with its own options to a seeded
    half of its clips; a primitive whose half is under 3 clips is left out and named."""
    from motionvar.du2022.graph.evaluations.sec4_6_1 import fit_half, half_clip_indices

    assert np.array_equal(half_clip_indices(9, 0), half_clip_indices(9, 0)) and len(half_clip_indices(9, 0)) == 4
    assert len(set(half_clip_indices(9, 0))) == 4
    assert not np.array_equal(half_clip_indices(9, 0), half_clip_indices(9, 1))
    picks, _ = primitive_clips(dataset, "pick_reach")
    walks, _ = primitive_clips(dataset, "walk_leftStance")
    models = {"pick_reach": MotionPrimitive("pick_reach", OPT).fit(picks), "walk_leftStance": prim_of(walks)}
    sizes = {n: sum(f.stat().st_size for f in m.save(tmp_path / n)) for n, m in models.items()}
    fitted = fit_half(models, {"pick_reach": picks, "walk_leftStance": walks}, 0)
    assert list(fitted) == ["pick_reach"]  # 4 walks: a half of 2 cannot be fitted
    idx, small = fitted["pick_reach"]
    assert len(idx) == 4 and small.options == models["pick_reach"].options and small.n_latent == 3
    half = {"pick_reach": (idx, small, sum(f.stat().st_size for f in small.save(tmp_path / "half" / "pick_reach")))}
    result = evaluate_sec4_6_1(models, sizes, dataset.metadata, None, half)
    t = result.table.set_index("primitive")
    J = small.skeleton.n_joints
    rows = dataset.metadata[dataset.metadata["primitive"] == "pick_reach"]
    frames = (rows["stop_frame"] - rows["start_frame"]).to_numpy()[idx]
    assert t.loc["pick_reach", "half_data_bytes"] == sum(motion_bytes(f, J) for f in frames)
    assert t.loc["pick_reach", "model_growth"] == sizes["pick_reach"] / half["pick_reach"][2]
    assert np.isnan(t.loc["walk_leftStance", "half_model_bytes"])
    claim = result.claims[1]
    assert claim.claim_id == "du2022.sec4_6_1.model_size_constant_as_data_doubles"
    assert claim.value == pytest.approx(t.loc["pick_reach", "model_growth"]) and claim.bound == 1.1
    assert "walk_leftStance" in claim.measured and "latent 3->5" in claim.measured  # capped at clips - 1
    assert claim.verdict == "partial"  # 4 of 8 clips cap the latent dimension at 3, all of them at 5 (OPT): x1.44
    check_value_bound(claim)
    assert len(draw_sec4_6_1(result).axes) == 1
    none = evaluate_sec4_6_1(models, sizes, dataset.metadata, None, {})
    assert none.claims[1].verdict == "not applicable" and "6 clips" in none.claims[1].note


def prim_of(motions):
    return MotionPrimitive("walk_leftStance", OPT).fit(motions)


def test_settings_have_one_owner():
    """GraphSettings holds every default: the primitive options, the graph walk's settings
    (SynthesisSettings, also read back by `motionvar du2022 walk`) and the search settings."""
    from motionvar.du2022.graph.generate import walk_settings

    s = GraphSettings()
    assert PrimitiveOptions() == PrimitiveOptions.from_settings(s.model, s.seed)
    assert PrimitiveOptions.from_settings(s.model, 3).gmm_components == (s.model.gmm_min, s.model.gmm_max)
    saved = {"seed": 1, **s.synthesis.replace(tree_samples=5).to_dict()}
    assert walk_settings(saved) == s.synthesis.replace(tree_samples=5)
    assert walk_settings({"seed": 1}, max_steps=3) == s.synthesis.replace(max_steps=3)
    assert s.search.candidates == (2, 3, 4) and s.search.replace(beam=6).candidates == (2, 3, 4, 6)
    assert s.search.joint("walk_leftStance") == "left_ankle" and s.search.joint("other") == s.search.default_joint
    with pytest.raises(ValueError, match="du2022_graph.synthesis.*joint_steps"):
        GraphSettings.from_dict({"synthesis": {"joint_steps": "some"}})
    with pytest.raises(ValueError, match="du2022_graph.search.beams"):
        GraphSettings.from_dict({"search": {"beams": []}})
