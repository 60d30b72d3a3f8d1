"""Ma 2010 evaluations on toy walks: Sec. 7.4's comparison of six methods, its settings and claims, and Sec. 8's timing."""

import os

import numpy as np
import pytest
from claim_checks import check_value_bound
from ma2010_toy import JM, LINEAR, TOY, check

from motionvar.claim_catalog import spec
from motionvar.claims import NotApplicable
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
from motionvar.ma2010.evaluations.sec7_4 import sec7_4_comparison, sequence_rows
from motionvar.ma2010.evaluations.sec8 import cpu_model, sec8_timing
from motionvar.ma2010.examples import WalkCycles
from motionvar.ma2010.settings import Ma2010Settings


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
