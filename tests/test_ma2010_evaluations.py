"""Ma et al. 2010 evaluations as library functions (motionvar.ma2010.evaluations) on toy
walkers: the walking cycles of a dataset, every evaluation's table, claims and figure, and
bad input named in the error."""

import matplotlib

matplotlib.use("Agg")  # noqa: E402  (tests draw figures to nowhere)

import json

import matplotlib.pyplot as plt
import numpy as np
import pandas as pd
import pytest
from claim_checks import check_value_bound
from ma2010_toywalk import toy_walk

from motionvar.claim_catalog import spec
from motionvar.claims import VERDICTS, NotApplicable
from motionvar.core import cmu_joint_map
from motionvar.io import load_dataset, save_dataset
from motionvar.ma2010 import figures
from motionvar.ma2010.comparison import METHODS, NATURALNESS_SCORES, ours_clips, ours_sequence
from motionvar.ma2010.evaluations.common import PAPER, loo_folds, walk_positions
from motionvar.ma2010.evaluations.fig3 import circular_sd, fig3_keyframes, step_phases
from motionvar.ma2010.evaluations.fig6 import fig6_leave_one_out
from motionvar.ma2010.evaluations.fig7b import fig7b_reliability
from motionvar.ma2010.evaluations.fig8 import fig8_fixed_style
from motionvar.ma2010.evaluations.sec7_4 import sec7_4_comparison
from motionvar.ma2010.evaluations.sec8 import sec8_timing
from motionvar.ma2010.examples import WalkCycles, joint_groups, walk_cycles
from motionvar.ma2010.settings import Ma2010Settings

JM = cmu_joint_map()
TOY = Ma2010Settings(n_frames=24)  # neutral forward walks, a short timeline
LINEAR = TOY.replace(variogram_model="linear")


def toy_dataset(path, styles, n_cycles=3):
    """Toy walkers of growing stride, some lengthening their strides as they walk (a steady
    walker's two support strides are equal: the style space would be a line)."""
    motions = [
        toy_walk(hip_amp=0.3 + 0.03 * i, arm_amp=0.2 + 0.1 * i, n_cycles=n_cycles, hip_growth=0.03 * (i % 3))
        for i in range(len(styles))
    ]
    meta = pd.DataFrame(
        {
            "clip_id": [f"w{i}" for i in range(len(styles))],
            "subject": [f"{i:02d}" for i in range(len(styles))],
            "behaviour": "walk",
            "style": styles,
            "variant": "forward",
        }
    )
    save_dataset(path, motions, meta)
    return load_dataset(path)


@pytest.fixture(scope="module")
def walks(tmp_path_factory):
    data = toy_dataset(tmp_path_factory.mktemp("data"), ["neutral"] * 4)
    clips, table = walk_cycles(data, JM, TOY)
    return WalkCycles(clips, table["subject"].tolist(), JM, source="toy walks", root_group="legs")


@pytest.fixture(scope="module")
def model(walks):
    return walks.fit_model(LINEAR)


def check(result, draw, claim_prefix):
    assert len(result.table) and result.claims
    json.dumps(result.measurements)  # plain numbers, strings, lists and dicts of them
    for c in result.claims:
        assert c.claim_id.startswith(f"{PAPER}.{claim_prefix}") and c.verdict in VERDICTS
        check_value_bound(c)  # the number the verdict comes from travels with the claim
        again = spec(c.claim_id).claim(result.measurements)  # the measurements alone decide the claim
        assert (again.verdict, again.measured, again.kind) == (c.verdict, c.measured, spec(c.claim_id).kind)
    fig = draw(result)
    assert fig.axes
    plt.close(fig)


def test_walk_cycles_cut_walks_into_cycles(tmp_path):
    data = toy_dataset(tmp_path, ["neutral"] * 3)
    clips, table = walk_cycles(data, JM, TOY)
    assert clips.rotations.shape[:2] == (len(table), 24) and table["clip_id"].tolist() == clips.clip_ids
    assert len(table) >= 3 and set(table["source_clip"]) == {"w0", "w1", "w2"}
    assert np.all(table["left_support_stride_cm"] > 50) and set(table["subject"]) == {"00", "01", "02"}


@pytest.mark.parametrize(
    "styles, n_cycles, expected", [(["proud", "proud"], 3, "no clip with"), (["neutral"], 1.2, "need at least 3")]
)
def test_walk_cycles_name_the_problem(tmp_path, styles, n_cycles, expected):
    data = toy_dataset(tmp_path, styles, n_cycles)
    with pytest.raises(ValueError, match=expected) as err:
        walk_cycles(data, JM, TOY, what="meta.csv (config ma2010.walk_styles)")
    assert str(err.value).startswith("meta.csv (config ma2010.walk_styles)")


def test_walk_cycles_need_one_subject_per_cycle(walks):
    with pytest.raises(ValueError, match="toy walks: 1 subjects"):
        WalkCycles(walks.clips, ["a"], JM, source="toy walks", root_group="legs")


def test_fig3_step_phases_and_key_frames(tmp_path):
    assert np.allclose(step_phases(np.array([5, 15, 40]), np.array([0, 10, 20])), [0.5, 0.5])
    assert circular_sd([0.2, 0.2, 0.2]) == pytest.approx(0.0, abs=1e-6) and circular_sd([0.0, 0.5]) > 0.3
    data = toy_dataset(tmp_path, ["neutral"] * 2)
    result = fig3_keyframes(data, JM, TOY.replace(fig3_max_clips=1))
    assert set(result.table["behaviour"]) == {"walk"} and set(result.figure["shown"]) == {"walk"}
    assert set(result.table["extremum"]) == {"max", "min"} and (result.table["part"] == "lower").all()
    # no run clips: no run claim (nothing to judge), and the walk's claim judged on its own scan
    assert [c.claim_id for c in result.claims] == ["ma2010.fig3.walk_keyframes_at_one_gait_phase"]
    assert set(result.measurements["behaviours"]) == {"walk"} and result.measurements["max_clips"] == 1
    check(result, figures.draw_fig3, "fig3.walk_keyframes")


def test_fig6_leave_one_out(walks):
    result = fig6_leave_one_out(walks, LINEAR.replace(loo_max_clips=2))
    t = result.table
    folds, summary = t[t["kind"] == "fold"], t[t["kind"] == "summary"]
    assert len(folds) == 2 and t.columns[0] == "kind" and {"clip_id", "subject", "source_clip", "closing"} <= set(t)
    assert np.all(folds["ours_own_xi_stride_error_cm"] >= 0) and np.all(folds["rbf_pose_error_cm"] >= 0)
    # own xi beside the network's (conditional mean, sampled), per group
    for kind in ("own", "mean", "sampled"):
        assert np.all(np.isfinite(folds[[f"{kind}_xi_{g}" for g in ("legs", "left_arm", "right_arm", "upper_body")]]))
    # the ablation (root rotation in the upper body) and steady / closing summaries
    assert {"ours_own_xi_root_upper_body", "least_squares", "kriging", "rbf"} <= set(summary["method"])
    assert set(summary["cycles"]) <= {"all", "steady", "closing"} and "all" in set(summary["cycles"])
    assert set(summary.loc[summary["method"] == "ours_own_xi", "root_group"]) == {"legs"}
    assert [c.claim_id for c in result.claims] == [
        "ma2010.fig6.loo_max_stride_error_below_1_2cm",
        "ma2010.mk05.kriging_beats_rbf",
    ]
    assert "steady cycles" in result.claims[0].measured and "upper_body" in result.claims[0].note
    stride, kriging = result.claims
    assert stride.value == folds["ours_own_xi_stride_error_cm"].max() and (stride.bound, stride.unit) == (1.2, "cm")
    diff = folds["kriging_pose_error_cm"].mean() - folds["rbf_pose_error_cm"].mean()
    assert kriging.value == pytest.approx(diff) and kriging.bound == -0.01 and kriging.direction == "<"
    check(result, figures.draw_fig6, "")


def test_fig6_compares_with_the_validation_cycle_through_the_same_measure(walks):
    """Fig. 6 compares the predicted clip's stride with the validation clip's: the held-out
    cycle goes through the same measure (default), and its own error against its style is
    reported as the measure's floor; "style" compares with the strides asked for."""
    lower_first = LINEAR.replace(structure="lower_first", loo_max_clips=2)
    result = fig6_leave_one_out(walks, lower_first, ablation=False)
    folds = result.table[result.table["kind"] == "fold"]
    validation = folds[["validation_left_cm", "validation_right_cm"]].to_numpy()
    ours = folds[["ours_own_xi_left_cm", "ours_own_xi_right_cm"]].to_numpy()
    style = folds[["true_left_cm", "true_right_cm"]].to_numpy()
    assert np.allclose(folds["ours_own_xi_stride_error_cm"], np.abs(ours - validation).max(axis=1))
    assert np.allclose(folds["ours_own_xi_style_error_cm"], np.abs(ours - style).max(axis=1))
    assert np.allclose(folds["validation_stride_error_cm"], np.abs(validation - style).max(axis=1))
    assert "validation" in set(result.table.loc[result.table["kind"] == "summary", "method"])
    assert "floor" in result.claims[0].note and result.figure["stride_reference"] == "validation"
    by_style = fig6_leave_one_out(walks, lower_first.replace(fig6_stride_reference="style"), ablation=False).table
    by_style = by_style[by_style["kind"] == "fold"]
    assert np.allclose(by_style["ours_own_xi_stride_error_cm"], by_style["ours_own_xi_style_error_cm"])
    with pytest.raises(ValueError, match="fig6_stride_reference must be one of"):
        lower_first.replace(fig6_stride_reference="truth")


def test_root_group_choice_moves_only_the_root_rotation(walks):
    """Config ma2010.root_group: the root joint (0, the pelvis) goes with the legs by default
    (as every shipped joint map says), or with the upper body; nothing else moves."""
    sk = walks.clips.skeleton
    legs, upper = joint_groups(JM, sk, "legs"), joint_groups(JM, sk, "upper_body")
    assert 0 in legs["legs"] and 0 not in legs["upper_body"]
    assert 0 in upper["upper_body"] and 0 not in upper["legs"]
    for g in ("legs", "upper_body"):
        assert np.array_equal(np.setdiff1d(legs[g], [0]), np.setdiff1d(upper[g], [0]))
    for groups in (legs, upper):
        assert np.array_equal(np.sort(np.concatenate(list(groups.values()))), np.arange(sk.n_joints))
    assert np.array_equal(legs["left_arm"], JM.group_indices(sk)["left_arm"])
    assert sk.names[0] in JM.groups["legs"]  # the shipped CMU map: the root with the legs
    moved = WalkCycles(walks.clips, walks.subjects, JM, "toy walks", root_group="upper_body")
    lower_first = LINEAR.replace(structure="lower_first")
    assert 0 in moved.groups["upper_body"] and 0 in walks.groups["legs"]
    with pytest.raises(ValueError, match="root_group must be one of"):
        joint_groups(JM, sk, "left_arm")
    # the model follows the groups: the root's rotation is interpolated in its group
    a, b = walks.fit_model(lower_first), moved.fit_model(lower_first)
    assert 0 in a.interpolators_["legs"][0].joints and 0 in b.interpolators_["upper_body"][0].joints


def test_whole_walk_folds_never_train_on_a_sibling_cycle():
    walks_of = ["a", "a", "a", "b", "c", "c"]
    position, closing = walk_positions(walks_of)
    assert position.tolist() == [0, 1, 2, 0, 0, 1] and closing.tolist() == [False, False, True, True, False, True]
    folds = loo_folds(walks_of, [1, 2, 4], "walk")
    assert [t.tolist() for _, t in folds] == [[1, 2], [4]]
    for train, test in folds:
        assert not {walks_of[i] for i in train} & {walks_of[i] for i in test}
        assert len(train) + sum(w == walks_of[test[0]] for w in walks_of) == len(walks_of)
    cycle = loo_folds(walks_of, [1], "cycle")  # the literal per-cycle fold keeps the siblings
    assert cycle[0][1].tolist() == [1] and {0, 2} <= set(cycle[0][0].tolist())
    with pytest.raises(ValueError, match="unit must be one of"):
        loo_folds(walks_of, [0], "subject")
    with pytest.raises(ValueError, match="need each cycle's source clip"):
        loo_folds(None, [0], "walk")


def test_fig6_whole_walk_folds_leave_out_every_sibling(walks):
    settings = LINEAR.replace(structure="lower_first", loo_max_clips=3)
    result = fig6_leave_one_out(walks, settings, ablation=False)
    folds = result.table[result.table["kind"] == "fold"]
    size = pd.Series(walks.source_clips).value_counts()
    assert np.array_equal(folds["n_train"], walks.clips.n_clips - size[folds["source_clip"]].to_numpy())
    assert "ours_own_xi_root_upper_body_stride_error_cm" not in folds
    per_cycle = fig6_leave_one_out(walks, settings.replace(loo_unit="cycle"), ablation=False).table
    assert np.all(per_cycle.loc[per_cycle["kind"] == "fold", "n_train"] == walks.clips.n_clips - 1)


def test_fig7b_reliability(walks, model):
    result = fig7b_reliability(walks, model, TOY.replace(reliability_grid=3, reliability_margin=0.2))
    assert len(result.table) == 9 and np.all(result.table["nearest_example_cm"] >= 0)
    assert len(result.figure["failed"]) == 9
    assert result.claims[0].value == result.figure["rho"] or np.isnan(result.figure["rho"])
    check(result, figures.draw_fig7b, "fig7b")


def test_fig8_variants_vary_and_interpolations_do_not(walks, model):
    settings = LINEAR.replace(fig8_variants=3, seed=1, spread_ratio_bounds=(0.1, 10.0))
    result = fig8_fixed_style(walks, model, settings)
    t = result.table
    assert (t["kind"] == "variant").sum() == 3 and (t["kind"] == "spread_cm").sum() == 6
    assert (t["kind"] == "ceiling").sum() == 3 and np.all(t.loc[t["kind"] == "ceiling", "stride_error_cm"] >= 0)
    spreads = result.figure["spreads"]
    assert min(spreads["ours"].values()) > 0 and max(spreads["RBF"].values()) < 1e-6
    assert min(spreads["ceiling (their own xi)"].values()) > 0 and "ceiling" in result.claims[0].note
    assert result.claims[1].verdict == "reproduced"  # RBF and Kriging give no variation
    assert result.claims[1].value == max(max(spreads["RBF"].values()), max(spreads["Kriging"].values()))
    assert result.claims[0].unit == "share" and result.claims[0].value in (0.0, 1 / 3, 2 / 3, 1.0)
    assert len(result.figure["motions"]) == 3
    check(result, figures.draw_fig8, "")


def test_sec7_4_comparison(walks):
    settings = LINEAR.replace(
        comparison_examples=3,
        comparison_seconds=2.0,
        comparison_sequences=2,
        gplvm_iterations=2,
        gplvm_frame_step=4,
        dbn_max_parents=4,
    )
    result = sec7_4_comparison(walks, settings)
    t = result.table
    assert set(t["method"]) == {*METHODS, "examples"} and (t["method"] != "examples").sum() == 2 * len(METHODS)
    assert list(result.figure["sequences"]) == list(METHODS)
    ours = t[t["method"] == "ours"]["variation_between_sequences_cm"]
    rbf = t[t["method"] == "rbf"]["variation_between_sequences_cm"]
    assert np.all(ours > 0) and np.allclose(rbf, 0.0)
    for col in (
        "jerk_cm_s3",
        "root_free_jerk_cm_s3",
        "foot_skating_cm_s",
        "low_joint_speed_cm_s",
        "contact_share",
        *NATURALNESS_SCORES,
    ):
        assert col in t
    ex = t[t["method"] == "examples"]
    assert np.isfinite(ex[["jerk_cm_s3", "root_free_jerk_cm_s3", "foot_skating_cm_s"]].to_numpy()).all()
    assert f"/{len(NATURALNESS_SCORES)} naturalness scores" in result.claims[0].measured
    assert "once per sequence" in result.claims[0].note and "Bayesian GPLVM" in result.claims[0].note
    check(result, figures.draw_sec7_4, "sec7_4")
    with pytest.raises(NotApplicable, match="toy walks: 1 subject"):
        sec7_4_comparison(
            WalkCycles(walks.clips, ["one"] * walks.clips.n_clips, JM, "toy walks", root_group="legs"), settings
        )


def test_ours_draws_xi_once_per_sequence_or_per_clip(walks, model):
    """Sec. 7.4 does not say: per sequence (the default) every cycle of a sequence is the
    same person (identical cycles), per clip each cycle has its own xi."""
    style = np.median(walks.clips.style, axis=0)
    same = ours_clips(model, style, 3, np.random.default_rng(0), xi_per="sequence")
    assert np.allclose(same.rotations, same.rotations[:1]) and np.allclose(same.key_times, same.key_times[:1])
    each = ours_clips(model, style, 3, np.random.default_rng(0), xi_per="clip")
    assert np.abs(each.rotations - each.rotations[:1]).max() > 1e-6
    sequence = ours_sequence(model, style, 2, walks.solver, np.random.default_rng(0), "sequence", "significant_maximum")
    assert sequence.n_frames > 2
    with pytest.raises(ValueError, match="xi_per"):
        ours_clips(model, style, 3, np.random.default_rng(0), xi_per="frame")


def test_sec8_timing_with_a_fake_clock(walks, model):
    ticks = iter(np.arange(0.0, 100.0, 0.5))
    settings = TOY.replace(timing_seconds=2.0, timing_repeats=2)
    result = sec8_timing(walks, model, settings, clock=lambda: float(next(ticks)))
    row = result.table.iloc[0]
    assert row["seconds_per_second"] == pytest.approx(0.5 / row["motion_seconds"])
    assert row["example_cycles"] == walks.clips.n_clips and row["subjects"] == 4
    (claim,) = result.claims
    assert claim.value == row["seconds_per_second"] and (claim.bound, claim.unit) == (0.15, "s per s")
    check(result, figures.draw_sec8, "sec8")
