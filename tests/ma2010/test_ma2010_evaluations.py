"""Ma et al. 2010 evaluations as library functions (motionvar.ma2010.evaluations) on toy
walkers: the walking cycles of a dataset, every evaluation's table, claims and figure, and
bad input named in the error."""

import matplotlib

matplotlib.use("Agg")  # noqa: E402  (tests draw figures to nowhere)

import dataclasses
import json
import os

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
from motionvar.ma2010.comparison import (
    METHODS,
    NATURALNESS_MEASURES,
    NATURALNESS_SCORES,
    NaturalnessReference,
    covering,
    family,
    held_out_pose_distance,
    method_variants,
    naturalness_scores,
    ours_clips,
    ours_sequence,
)
from motionvar.ma2010.evaluations.common import PAPER, loo_folds, walk_positions
from motionvar.ma2010.evaluations.fig3 import circular_sd, fig3_keyframes, step_phases
from motionvar.ma2010.evaluations.fig6 import failure_causes, fig6_leave_one_out
from motionvar.ma2010.evaluations.fig7b import fig7b_reliability, reliability_correlation
from motionvar.ma2010.evaluations.fig8 import GROUPS, fig8_fixed_style
from motionvar.ma2010.evaluations.sec7_4 import sec7_4_comparison, sequence_rows
from motionvar.ma2010.evaluations.sec8 import cpu_model, sec8_timing
from motionvar.ma2010.examples import WalkCycles, joint_groups, walk_cycles
from motionvar.ma2010.settings import Ma2010Settings

JM = cmu_joint_map()
TOY = Ma2010Settings().replace(clips__n_frames=24)  # neutral forward walks, a short timeline
LINEAR = TOY.replace(model__variogram_model="linear")


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


def test_fig7b_reliability(walks, model):
    result = fig7b_reliability(walks, model, TOY.replace(fig7b__grid=3, fig7b__margin=0.2))
    t = result.table
    assert len(t) == 9 and np.all(t["nearest_example_cm"] >= 0) and np.all(t["examples_line_cm"] >= 0)
    assert t["on_examples_line"].any() and not t["on_examples_line"].all()
    assert np.array_equal(t["failed"], t["stride_error_cm"].isna())
    m = result.measurements
    assert m["all"]["n"] == 9 and m["on_line"]["n"] + m["off_line"]["n"] == 9 and m["succeeded"]["n"] == 9 - m["failed"]
    off = t[~t["on_examples_line"]]
    assert np.allclose(off["asymmetry_floor_cm"], np.abs(off["left_cm"] - off["right_cm"]) / 2)
    c = result.claims[0]
    assert c.verdict == "not testable" or (c.value == m["all"]["rho"] and c.bound == 0.5 and c.direction == ">=")
    check(result, figures.draw_fig7b, "fig7b")


def test_fig7b_ranks_failed_syntheses_worst_and_asks_for_a_strong_correlation():
    """A failed synthesis ranks as the largest error (never left out); a weak correlation
    (rho < 0.5) does not reproduce "a strong correlation", however small its p; failures far from
    the examples strengthen it, failures at the examples weaken it."""
    rng = np.random.default_rng(0)
    dist = np.linspace(0.0, 20.0, 200)
    error = 0.05 * dist + rng.normal(0.0, 0.6, 200)  # grows with distance, but weakly
    on = np.arange(200) % 5 == 0
    table = pd.DataFrame({"stride_error_cm": error, "nearest_example_cm": dist, "on_examples_line": on})
    table["failed"] = False
    table.loc[:9, "failed"] = True
    table.loc[:9, "stride_error_cm"] = np.nan
    m = reliability_correlation(table) | {"margin": 0.5}
    assert m["failed"] == 10 and m["all"]["n"] == 200 and m["succeeded"]["n"] == 190 and m["failed_on_line"] == 2
    assert m["all"]["rho"] < m["succeeded"]["rho"]  # failures at the examples count against the claim
    claim = spec("ma2010.fig7b.error_grows_with_distance").claim(m)
    assert 0 < m["succeeded"]["rho"] < 0.5 and m["succeeded"]["p"] < 1e-3 and claim.verdict == "not reproduced"
    assert "the 10 failed syntheses rank as the largest errors" in claim.note
    strong = table.assign(stride_error_cm=0.2 * dist, failed=False)
    far = strong.assign(failed=dist > 19.0)  # the farthest points fail: the most unreliable, ranked so
    judged = spec("ma2010.fig7b.error_grows_with_distance").claim(reliability_correlation(far) | {"margin": 0.5})
    assert judged.verdict == "reproduced" and judged.value == pytest.approx(1.0, abs=1e-3)  # failures tie


def test_fig7b_asymmetry_floor_is_taken_off_the_off_line_points():
    """Off the examples' line a symmetric model errs by |L - R| / 2 at least: with that floor
    removed, an error that is only the floor leaves no correlation with distance."""
    dist = np.linspace(1.0, 20.0, 40)
    floor = 0.3 * dist  # the asked-for asymmetry grows with the distance from the line
    table = pd.DataFrame(
        {
            "stride_error_cm": floor + 0.01 * np.sin(np.arange(40)),
            "asymmetry_floor_cm": floor,
            "nearest_example_cm": dist,
            "on_examples_line": False,
            "failed": False,
        }
    )
    m = reliability_correlation(table)
    assert m["off_line"]["rho"] > 0.9 and abs(m["off_line_excess"]["rho"]) < 0.5


def test_fig8_variants_vary_and_interpolations_do_not(walks, model):
    settings = LINEAR.replace(
        fig8__variants=3, fig8__draws=40, fig8__bootstrap=200, seed=1, fig8__spread_ratio_bounds=(0.1, 10.0)
    )
    result = fig8_fixed_style(walks, model, settings)
    t = result.table
    assert (t["kind"] == "variant").sum() == 3 and (t["kind"] == "spread_cm").sum() == 6
    # ours' spread over the 40 draws; the data's (3 nearest cycles) with its bootstrap interval around it
    m = result.measurements
    assert m["draws"] == 40 and "40 cycles at the median stride" in result.claims[0].note
    for g in GROUPS:
        lo, hi = m["data_interval_cm"][g]
        assert lo <= m["spread_cm"]["data"][g] * 1.0001 and hi >= lo and "bootstrap" in result.claims[0].measured
    assert (t["kind"] == "ceiling").sum() == 3 and np.all(t.loc[t["kind"] == "ceiling", "stride_error_cm"] >= 0)
    spreads = result.figure["spreads"]
    assert min(spreads["ours"].values()) > 0 and max(spreads["RBF"].values()) < 1e-6
    assert min(spreads["ceiling (their own xi)"].values()) > 0 and "ceiling" in result.claims[0].note
    assert result.claims[1].verdict == "reproduced"  # RBF and Kriging give no variation
    assert result.claims[1].value == max(max(spreads["RBF"].values()), max(spreads["Kriging"].values()))
    assert result.claims[0].unit == "share" and result.claims[0].value in (0.0, 0.5, 1.0)
    assert result.measurements["examples"] == result.measurements["subjects"] == 3  # one per subject
    assert len(result.figure["motions"]) == 3
    check(result, figures.draw_fig8, "")


def test_fig8_is_not_testable_without_enough_examples_near_the_style(walks, model):
    """Fig. 8a compares the variants' spread with that of the example cycles nearest the style, one
    per subject: with fewer than three of them (or two subjects) the claim is not testable, and
    the requirements table says so before the run."""
    from motionvar.applicability import unmet_reason
    from motionvar.ma2010.requirements import requirements

    settings = LINEAR.replace(fig8__variants=2, seed=1)
    claim = fig8_fixed_style(walks, model, settings).claims[0]
    assert claim.verdict == "not testable" and "2 from 2 subject" in claim.note
    one = WalkCycles(walks.clips, ["a"] * walks.clips.n_clips, JM, "one walker", root_group="legs")
    claim = fig8_fixed_style(one, model, LINEAR.replace(seed=1)).claims[0]
    assert claim.verdict == "not testable" and "1 from 1 subject" in claim.note
    meta = pd.DataFrame(
        {"clip_id": list("abcd"), "subject": ["1", "1", "2", "2"], "behaviour": "walk", "style": "neutral"}
        | {"variant": "forward", "n_frames": 600, "fps": 120.0}
    )
    fig8 = next(r for r in requirements(LINEAR) if r.evaluation == "ma2010_fig8")
    assert "at least 3 subjects" in unmet_reason(fig8, {"data": meta})
    assert unmet_reason(fig8, {"data": meta.assign(subject=["1", "2", "3", "3"])}) is None


def test_sec7_4_comparison(walks):
    settings = LINEAR.replace(
        sec7_4__examples=3,
        sec7_4__seconds=2.0,
        sec7_4__sequences=2,
        sec7_4__gplvm_iterations=2,
        sec7_4__gplvm_frame_step=4,
        sec7_4__perlin_amplitude_sweep_rad=(0.05, 0.2),
        sec7_4__dbn_max_parents_sweep=(4,),
    )
    result = sec7_4_comparison(walks, settings)
    t = result.table
    variants = ["ours", "perlin_0.05", "perlin_0.2", "gplvm", "rbf", "kriging", "dbn_4"]
    assert list(method_variants(settings)) == variants and list(result.figure["sequences"]) == variants
    assert set(t["method"]) == {*variants, "examples"} and (t["method"] != "examples").sum() == 2 * len(variants)
    assert set(t["family"]) == {*METHODS, "examples"}
    ours = t[t["method"] == "ours"]["variation_between_sequences_cm"]
    rbf = t[t["method"] == "rbf"]["variation_between_sequences_cm"]
    assert np.all(ours > 0) and np.allclose(rbf, 0.0)
    for col in (
        "jerk_cm_s3",
        "root_free_jerk_cm_s3",
        "foot_skating_cm_s",
        "low_joint_speed_cm_s",
        "contact_share",
        "pose_distance_cm",
        *NATURALNESS_SCORES,
    ):
        assert col in t
    ex = t[t["method"] == "examples"]
    assert np.isfinite(ex[["jerk_cm_s3", "root_free_jerk_cm_s3", "foot_skating_cm_s"]].to_numpy()).all()
    assert np.all(ex["pose_excess_vs_held_out"] == 0.0)  # the examples themselves: no excess
    m = result.measurements
    assert set(m["scores"]) == set(variants) and m["held_out_pose_cm"] > 0
    assert set(m["ours_best"]) == set(NATURALNESS_SCORES) and set(m["best_rival"].values()) <= set(variants[1:])
    assert set(m["example_worst"]) == set(NATURALNESS_SCORES) and set(m["natural"]) == set(variants)
    ex_worst = ex[list(NATURALNESS_SCORES)].max()
    assert all(m["natural"]["ours"][k] == (m["scores"]["ours"][k] <= ex_worst[k]) for k in NATURALNESS_SCORES)
    ours_claim, perlin, gplvm, dbn = result.claims
    assert "within the examples' range on" in ours_claim.measured and "once per sequence" in ours_claim.note
    assert "/2 amplitudes" in perlin.measured and "Perlin noise 0.05 rad" in perlin.measured
    assert "GPLVM rival is Bayesian" in gplvm.note and "/1 parent limits" in dbn.measured
    for claim in result.claims:
        check_value_bound(claim)
    check(result, figures.draw_sec7_4, "sec7_4")
    with pytest.raises(NotApplicable, match="toy walks: 1 subject"):
        sec7_4_comparison(
            WalkCycles(walks.clips, ["one"] * walks.clips.n_clips, JM, "toy walks", root_group="legs"), settings
        )


def test_sequences_cover_the_seconds_with_the_same_draws():
    """Sec. 7.4's sequences: a walker whose cycles are shorter than the examples' mean gets more
    cycles from the same draws (the same sequence, longer) instead of ending early and scoring
    as broken down; a sequence that lasts is made once, as before, and leaves the generator where
    one make leaves it."""
    from motionvar.core import Motion, cmu_skeleton

    sk = cmu_skeleton()

    def make(cycle_s: float):
        def walker(n: int, rng: np.random.Generator) -> Motion:
            values = rng.normal(size=n)  # one draw per cycle, in order
            frames = int(round(cycle_s * 120))
            root = np.zeros((n * frames, 3))
            root[:, 0] = np.repeat(values, frames)
            rotations = np.tile([1.0, 0.0, 0.0, 0.0], (n * frames, sk.n_joints, 1))
            return Motion(skeleton=sk, root_pos=root, rotations=rotations, fps=120.0)

        return walker

    slow, fast = make(1.0), make(0.8)
    lasting = covering(slow, 12, 10.0, rng := np.random.default_rng(3))
    reference = np.random.default_rng(3)
    once = slow(12, reference)
    np.testing.assert_array_equal(lasting.root_pos, once.root_pos[: lasting.n_frames])
    assert rng.bit_generator.state == reference.bit_generator.state
    short = fast(12, np.random.default_rng(3))
    assert short.duration < 10.0 - 1 / 120
    covered = covering(fast, 12, 10.0, np.random.default_rng(3))
    assert covered.duration == pytest.approx(10.0)
    np.testing.assert_array_equal(covered.root_pos[: short.n_frames], short.root_pos)


def test_sec7_4_pose_cause_class():
    """Ours outside the examples' range on the pose score: the data when its excess stays within
    what one held-out example alone shows over the examples' mean, the method beyond it; nothing
    when ours is inside."""
    from motionvar.ma2010.claims import _pose_cause

    def m(excess, inside=False):
        return {
            "natural": {"ours": {"pose_excess_vs_held_out": inside, "jerk_vs_examples": True}},
            "scores": {"ours": {"pose_excess_vs_held_out": excess}},
            "held_out_pose_spread": 0.1,
        }

    assert "by the data" in _pose_cause(m(0.08)) and "by the method" in _pose_cause(m(0.15))
    assert _pose_cause(m(0.0, inside=True)) == ""


def test_sec7_4_pose_score_does_not_reward_copying():
    """Sec. 7.4: the distance to the example poses counts only beyond a held-out example's, so a
    copy of an example and a new walker as close as a held-out one both score 0; farther poses
    score the log of the excess."""
    examples = [np.random.default_rng(i).normal(size=(20, 6)) + i for i in range(3)]
    held_out = held_out_pose_distance(examples)
    assert held_out > 0
    base = {"jerk_cm_s3": 2.0, "root_free_jerk_cm_s3": 1.0, "foot_skating_cm_s": 0.5, "discontinuities_per_min": 0.0}
    copy = naturalness_scores({**base, "pose_distance_cm": 0.0}, 2.0, 1.0, held_out)
    new = naturalness_scores({**base, "pose_distance_cm": held_out}, 2.0, 1.0, held_out)
    far = naturalness_scores({**base, "pose_distance_cm": 2 * held_out}, 2.0, 1.0, held_out)
    assert copy["pose_excess_vs_held_out"] == new["pose_excess_vs_held_out"] == 0.0
    assert far["pose_excess_vs_held_out"] == pytest.approx(np.log(2.0))
    assert copy["jerk_vs_examples"] == 0.0 and set(copy) == set(NATURALNESS_SCORES)
    with pytest.raises(ValueError, match="2 or more examples"):
        held_out_pose_distance(examples[:1])


def test_sec7_4_claims_judge_the_examples_range():
    """Sec. 7.4's judges: ours natural on every score yet without variation is not reproduced,
    outside the range on one score of five (varying) partial; a swept rival is unnatural only
    where some score leaves the range or it broke down; the GPLVM's fault is a jerk score."""
    labels = {"ours": "ours", "perlin_0.1": "Perlin 0.1", "perlin_0.3": "Perlin 0.3", "gplvm": "GPLVM", "rbf": "RBF"}
    worst = dict.fromkeys(NATURALNESS_SCORES, 1.0)
    scores = {x: dict.fromkeys(NATURALNESS_SCORES, 0.5) for x in labels}

    def measurements(variation_ours: float, diverged=None) -> dict:
        return {
            "scores": scores,
            "example_worst": worst,
            "natural": {x: {k: scores[x][k] <= worst[k] for k in NATURALNESS_SCORES} for x in labels},
            "variation_cm": {"ours": variation_ours, "perlin_0.1": 2.0, "perlin_0.3": 2.0, "gplvm": 1.0, "rbf": 0.0},
            "labels": labels,
            "families": {x: family(x) for x in labels},
            "score_labels": dict(NATURALNESS_SCORES),
            "diverged_s": diverged or {},
            "examples": 5,
            "held_out_pose_cm": 1.5,
            "xi_per": "sequence",
        }

    ours = spec("ma2010.sec7_4.ours_natural_and_varied").claim
    perlin = spec("ma2010.sec7_4.perlin_unnatural_even_tuned").claim
    gplvm = spec("ma2010.sec7_4.gplvm_jerks").claim
    assert (ours(measurements(3.0)).verdict, ours(measurements(3.0)).value) == ("reproduced", 1.0)
    assert ours(measurements(0.0)).verdict == "not reproduced"  # no variation: what RBF gives
    scores["ours"]["foot_skating_cm_s"] = 1.5
    assert (ours(measurements(3.0)).verdict, ours(measurements(3.0)).value) == ("partial", 0.8)
    assert perlin(measurements(3.0)).verdict == "not reproduced"  # both amplitudes within range
    scores["perlin_0.3"]["jerk_vs_examples"] = 2.0
    assert (perlin(measurements(3.0)).verdict, perlin(measurements(3.0)).value) == ("partial", 0.5)
    scores["perlin_0.1"] = dict.fromkeys(NATURALNESS_SCORES, np.inf)  # broke down
    judged = perlin(measurements(3.0, {"perlin_0.1": 4.2}))
    assert judged.verdict == "reproduced" and "broke down after 4.2 s" in judged.measured
    assert gplvm(measurements(3.0)).verdict == "not reproduced"
    scores["gplvm"]["foot_skating_cm_s"] = 3.0  # skating is not a jerk
    assert gplvm(measurements(3.0)).verdict == "not reproduced"
    scores["gplvm"]["discontinuities_per_min"] = 4.0
    assert (gplvm(measurements(3.0)).verdict, gplvm(measurements(3.0)).value) == ("reproduced", 1.0)


@pytest.mark.parametrize(
    "key, value, expected",
    [
        ("perlin_amplitude_sweep_rad", (), "perlin_amplitude_sweep_rad must be a non-empty list"),
        ("perlin_amplitude_sweep_rad", (0.1, -0.1), "amplitudes \\(rad\\) >= 0"),
        ("perlin_amplitude_sweep_rad", (0.1, 0.1), "distinct"),
        ("dbn_max_parents_sweep", (4, 2.5), "whole numbers of parents"),
    ],
)
def test_sec7_4_sweeps_name_the_bad_key(key, value, expected):
    with pytest.raises(ValueError, match=expected):
        Ma2010Settings().replace(**{f"sec7_4__{key}": value})


@pytest.mark.parametrize(
    "given, expected",
    [
        ({"loo_max_clips": 3}, "ma2010.loo_max_clips is now ma2010.fig6.max_clips"),
        ({"timing_repeats": 2}, "ma2010.timing_repeats is now ma2010.sec8.repeats"),
        ({"perlin_amplitude_rad": 0.1}, "ma2010.perlin_amplitude_rad is now ma2010.sec7_4.perlin_amplitude_sweep_rad"),
        (
            {"sec7_4": {"dbn_max_parents": 8}},
            "ma2010.sec7_4.dbn_max_parents is now ma2010.sec7_4.dbn_max_parents_sweep",
        ),
    ],
)
def test_former_keys_name_their_place_in_the_nested_section(given, expected):
    """The section is nested per stage; a key of the flat section (or an older name) stops the
    run naming the key that replaced it."""
    with pytest.raises(ValueError, match=expected):
        Ma2010Settings.from_dict(given)
    nested = Ma2010Settings.from_dict({"sec7_4": {"perlin_amplitude_sweep_rad": [0, 0.3]}, "fig6": {"max_clips": 3}})
    assert nested.sec7_4.perlin_amplitude_sweep_rad == (0, 0.3) and nested.fig6.max_clips == 3


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


def test_a_sequence_breaks_down_at_its_first_failed_synthesis(walks, model):
    """Under ma2010.model.key_timing absolute a predicted clip may have key times that do not
    increase: Sec. 7.4's sequence stops before it (and so scores as broken down) instead of
    clamping it into a zero-length segment; a first clip that fails leaves one frame."""
    from motionvar.ma2010.comparison import until_failed
    from motionvar.ma2010.svi import ClipPrediction
    from motionvar.ma2010.synthesis import sequence_motion

    style = np.median(walks.clips.style, axis=0)
    good = ours_clips(model, style, 4, np.random.default_rng(0), xi_per="clip")
    assert until_failed(good) is good
    bad = good.key_times.copy()
    bad[2, 2] = bad[2, 1] - 0.01  # the third clip runs backwards
    cut = until_failed(ClipPrediction(good.rotations, bad, good.root_height))
    assert len(cut) == 2 and np.array_equal(cut.key_times, good.key_times[:2])
    bad[0, 1] = bad[0, 0]  # and the first stands still
    first = until_failed(ClipPrediction(good.rotations, bad, good.root_height))
    motion = sequence_motion(first.rotations, first.key_times, model.reference_keys_, walks.solver, model.fps_)
    assert len(first) == 1 and motion.n_frames == 1
    from motionvar.ma2010.comparison import example_pose_sequences

    examples = [walks.solver.motion(r, walks.clips.fps) for r in example_pose_sequences(walks.clips)]
    ref = NaturalnessReference.from_examples(examples, walks.solver, 3.0, 3.0)
    row = sequence_rows({"ours": [motion]}, examples, ref, 1.0)[0]
    assert np.isnan([row[k] for k in NATURALNESS_MEASURES if k not in NATURALNESS_SCORES]).all()
    assert np.isinf([row[k] for k in NATURALNESS_SCORES]).all()


def test_sec8_timing_with_a_fake_clock(walks, model):
    """Sec. 8 reports the mean over the timing runs (the paper: "on average"), not the best."""
    ticks = iter([0.0, 0.5, 10.0, 11.0])  # the first run takes 0.5 s, the second 1 s
    settings = TOY.replace(sec8__seconds=2.0, sec8__repeats=2)
    result = sec8_timing(walks, model, settings, clock=lambda: float(next(ticks)))
    row = result.table.iloc[0]
    lo, hi = row["min_seconds_per_second"], row["max_seconds_per_second"]
    assert hi > 1.5 * lo
    assert row["seconds_per_second"] == pytest.approx((lo + hi) / 2)
    assert lo == pytest.approx(0.5 / row["motion_seconds"], rel=0.2)
    assert row["example_cycles"] == walks.clips.n_clips and row["subjects"] == 4 and row["runs"] == 2
    (claim,) = result.claims
    assert claim.value == row["seconds_per_second"] and (claim.bound, claim.unit) == (0.15, "s per s")
    assert "mean of 2 runs" in claim.measured and f"{os.cpu_count()} logical cores" in claim.measured
    assert result.measurements["cpu"] == row["cpu"] == cpu_model()
    check(result, figures.draw_sec8, "sec8")


def test_sec8_names_the_cpu(tmp_path):
    info = tmp_path / "cpuinfo"
    info.write_text("processor\t: 0\nmodel name\t: Test  CPU @ 2.00GHz\nflags\t: fpu\n")
    assert cpu_model(str(info)) == "Test CPU @ 2.00GHz"
    assert cpu_model(str(tmp_path / "none"))  # no cpuinfo: what the platform module says
