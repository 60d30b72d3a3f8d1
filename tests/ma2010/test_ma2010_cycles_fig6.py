"""Ma 2010 evaluations on toy walks: the walking cycles, Fig. 3's key frames and Fig. 6's leave-one-out with its baselines, folds and root-group ablation."""

import dataclasses

import numpy as np
import pandas as pd
import pytest
from claim_checks import check_value_bound
from ma2010_toy import JM, LINEAR, TOY, check, toy_dataset

from motionvar.claim_catalog import spec
from motionvar.ma2010 import figures
from motionvar.ma2010.evaluations.common import loo_folds, walk_positions
from motionvar.ma2010.evaluations.fig3 import circular_sd, fig3_keyframes, step_phases
from motionvar.ma2010.evaluations.fig6 import failure_causes, fig6_leave_one_out
from motionvar.ma2010.examples import WalkCycles, joint_groups, walk_cycles
from motionvar.ma2010.settings import Ma2010Settings


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
        walk_cycles(data, JM, TOY, what="meta.csv (config ma2010.clips.walk_styles)")
    assert str(err.value).startswith("meta.csv (config ma2010.clips.walk_styles)")


def test_walk_cycles_need_one_subject_per_cycle(walks):
    with pytest.raises(ValueError, match="toy walks: 1 subjects"):
        WalkCycles(walks.clips, ["a"], JM, source="toy walks", root_group="legs")


def test_fig3_step_phases_and_key_frames(tmp_path):
    assert np.allclose(step_phases(np.array([5, 15, 40]), np.array([0, 10, 20])), [0.5, 0.5])
    assert circular_sd([0.2, 0.2, 0.2]) == pytest.approx(0.0, abs=1e-6) and circular_sd([0.0, 0.5]) > 0.3
    data = toy_dataset(tmp_path, ["neutral"] * 2)
    result = fig3_keyframes(data, JM, TOY.replace(fig3__max_clips=1))
    assert set(result.table["behaviour"]) == {"walk"} and set(result.figure["shown"]) == {"walk"}
    assert set(result.table["extremum"]) == {"max", "min"} and (result.table["part"] == "lower").all()
    # no run clips: the run claim is not applicable, and the walk's claim judged on its own scan
    claims = {c.claim_id: c for c in result.claims}
    run = claims.pop("ma2010.fig3.run_keyframes_at_one_gait_phase")
    assert run.verdict == "not applicable" and run.note == "no run clips in the dataset"
    assert list(claims) == ["ma2010.fig3.walk_keyframes_at_one_gait_phase"]
    assert claims["ma2010.fig3.walk_keyframes_at_one_gait_phase"].verdict != "not applicable"
    assert set(result.measurements["behaviours"]) == {"walk"} and result.measurements["max_clips"] == 1
    check(result, figures.draw_fig3, "fig3.")


def test_fig6_leave_one_out(walks):
    result = fig6_leave_one_out(walks, LINEAR.replace(fig6__max_clips=2))
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
    # the verdict on the network's conditional-mean xi (ma2010.fig6.xi), the others as diagnostics
    assert stride.value == folds["ours_mean_xi_stride_error_cm"].max() and (stride.bound, stride.unit) == (1.2, "cm")
    assert "conditional-mean xi" in stride.note and {"ours_own_xi", "ours_sampled_xi"} <= set(summary["method"])
    own = fig6_leave_one_out(walks, LINEAR.replace(fig6__max_clips=2, fig6__xi="own"), ablation=False)
    assert own.claims[0].value == own.table["ours_own_xi_stride_error_cm"].max()
    # two folds: too few for a paired test to reach p < 0.05
    assert kriging.verdict == "not testable" and "fewer than 5 differing folds" in kriging.note
    assert result.measurements["mk05"]["folds"] == folds["fold"].nunique() == 2
    check(result, figures.draw_fig6, "")


def test_fig6_failure_causes_follow_the_stated_rule():
    """Each cycle above the bound gets the first matching cause: the measure's own floor, then no
    style-only interpolant within the bound, then ours; cycles within the bound get none; the
    note names them, most frequent first."""
    from motionvar.ma2010.claims import _failure_causes

    folds = pd.DataFrame(
        {
            "ours_mean_xi_stride_error_cm": [0.5, 2.0, 2.0, 2.0, 2.0],
            "validation_stride_error_cm": [0.1, 1.5, 0.2, 0.2, 0.2],
            "kriging_stride_error_cm": [0.4, 0.3, 1.9, 1.9, 0.8],
            "least_squares_stride_error_cm": [0.4, 0.3, 1.6, 1.4, 1.6],
        }
    )
    causes = failure_causes(folds, "ours_mean_xi", 1.2)
    assert causes == {"measure_floor": 1, "no_interpolant": 2, "ours": 1}
    note = _failure_causes({"failure_causes": causes})
    assert note.index("2 the data") < note.index("1 the method") and "1 our measure" in note
    assert _failure_causes({"failure_causes": failure_causes(folds.iloc[:1], "ours_mean_xi", 1.2)}) == ""


def test_fig6_compares_with_the_strides_asked_for(walks):
    """Fig. 6 compares each synthesized cycle's strides with the strides asked for (the held-out
    cycle's style, which the same measure gave it); the held-out cycle's own clip on the common
    timeline, retimed and measured alike, is a diagnostic row."""
    lower_first = LINEAR.replace(model__structure="lower_first", fig6__max_clips=2)
    result = fig6_leave_one_out(walks, lower_first, ablation=False)
    folds = result.table[result.table["kind"] == "fold"]
    validation = folds[["validation_left_cm", "validation_right_cm"]].to_numpy()
    ours = folds[["ours_own_xi_left_cm", "ours_own_xi_right_cm"]].to_numpy()
    style = folds[["true_left_cm", "true_right_cm"]].to_numpy()
    assert np.allclose(style, walks.clips.style[[walks.clips.clip_ids.index(c) for c in folds["clip_id"]]])
    assert np.allclose(folds["ours_own_xi_stride_error_cm"], np.abs(ours - style).max(axis=1))
    assert np.allclose(folds["validation_stride_error_cm"], np.abs(validation - style).max(axis=1))
    assert "validation" in set(result.table.loc[result.table["kind"] == "summary", "method"])
    assert not any(c.endswith("_style_error_cm") for c in result.table.columns)
    assert "strides asked for" in result.claims[0].note and "own clip retimed" in result.claims[0].note
    with pytest.raises(ValueError, match="unknown config key.*fig6_stride_reference"):
        Ma2010Settings.from_dict({"fig6_stride_reference": "validation"})


def test_mk05_rbf_reaches_the_held_out_walks_and_the_paired_test_decides(walks):
    """On whole-walk folds the RBF with one kernel per walk (Rose et al.'s radius: twice the
    distance to the nearest other example, here walk) reaches the held-out walks between the
    others, where its clips differ from least squares; where no kernel reaches, it is the
    least-squares fit. The claim is a one-sided Wilcoxon signed-rank test over the folds (p < 0.05)."""
    result = fig6_leave_one_out(
        walks, LINEAR.replace(model__structure="lower_first", fig6__unit="walk"), ablation=False
    )
    folds = result.table[result.table["kind"] == "fold"]
    mk05 = result.measurements["mk05"]
    assert mk05["reached"] == {name: int(folds[f"{name}_reaches"].sum()) for name in ("rbf", "rbf_cycles")}
    assert mk05["reached"]["rbf"] >= 1 and mk05["least_squares_gap_cm"]["rbf"] > 0.01
    for name in ("rbf", "rbf_cycles"):
        away = ~folds[f"{name}_reaches"].to_numpy(bool)
        gap = np.abs(folds[f"{name}_pose_error_cm"] - folds["least_squares_pose_error_cm"]).to_numpy()
        assert np.all(gap[away] < 1e-6)
    per_fold = folds.groupby("fold")[["kriging_pose_error_cm", "rbf_pose_error_cm"]].mean()
    diff = per_fold["kriging_pose_error_cm"] - per_fold["rbf_pose_error_cm"]
    assert mk05["folds"] == 4 and mk05["median_difference_cm"] == pytest.approx(float(diff.median()))
    assert result.claims[1].verdict == "not testable"  # four walks: four folds
    m = dict(result.measurements)
    for p, verdict in ((0.016, "reproduced"), (0.98, "not reproduced")):
        m["mk05"] = mk05 | {"folds": 6, "folds_differing": 6, "p": p}
        claim = spec("ma2010.mk05.kriging_beats_rbf").claim(m)
        assert claim.verdict == verdict and (claim.value, claim.bound, claim.direction) == (p, 0.05, "<")
        check_value_bound(claim)


def test_root_group_choice_moves_only_the_root_rotation(walks):
    """Config ma2010.model.root_group: the root joint (0, the pelvis) goes with the legs by default
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
    lower_first = LINEAR.replace(model__structure="lower_first")
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
    settings = LINEAR.replace(model__structure="lower_first", fig6__max_clips=3, fig6__unit="walk")
    result = fig6_leave_one_out(walks, settings, ablation=False)
    folds = result.table[result.table["kind"] == "fold"]
    size = pd.Series(walks.source_clips).value_counts()
    assert np.array_equal(folds["n_train"], walks.clips.n_clips - size[folds["source_clip"]].to_numpy())
    assert "ours_own_xi_root_upper_body_stride_error_cm" not in folds
    per_cycle = fig6_leave_one_out(walks, settings.replace(fig6__unit="cycle"), ablation=False).table
    assert np.all(per_cycle.loc[per_cycle["kind"] == "fold", "n_train"] == walks.clips.n_clips - 1)


def test_trend_rcond_reaches_every_trend_fit(walks):
    """ma2010.model.trend_rcond is the cut-off of every trend hyperplane: ours (the model's), and in
    Fig. 6's folds Kriging's, the RBFs' linear part and the least-squares reference. On a design
    whose styles lie on a line but for one example, a cut of 0.3 drops the thin direction, so
    the least-squares clips off the line differ from the literal fit's; on the line they agree."""
    from motionvar.ma2010.evaluations.fig6 import least_squares_clips

    assert walks.fit_model(LINEAR.replace(model__trend_rcond=0.3)).trend_rcond == 0.3
    clips = walks.clips
    t = np.linspace(-1.0, 1.0, clips.n_clips)
    on_line = np.column_stack([60.0 + 5.0 * t, 62.0 + 5.0 * t])
    on_line[0, 1] += 0.05  # the one example off the line: a thin second direction
    degenerate = dataclasses.replace(clips, style=on_line)
    off, on = np.array([[60.0, 66.0]]), np.array([[60.0, 62.0]])
    literal, cut = (least_squares_clips(degenerate, off, r).rotations for r in (0.0, 0.3))
    assert np.abs(literal - cut).max() > 1e-3
    literal, cut = (least_squares_clips(degenerate, on, r).rotations for r in (0.0, 0.3))
    assert (
        np.abs(literal - cut).max()
        < 0.5
        * np.abs(
            least_squares_clips(degenerate, off, 0.0).rotations - least_squares_clips(degenerate, off, 0.3).rotations
        ).max()
    )
    with pytest.raises(ValueError, match="trend_rcond"):
        LINEAR.replace(model__trend_rcond=1.0)
