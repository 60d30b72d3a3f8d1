"""Ma et al. 2010 evaluations as library functions (motionvar.ma2010.evaluations) on toy
walkers: the walking cycles of a dataset, every evaluation's table, claims and figure, and
bad input named in the error."""

import matplotlib

matplotlib.use("Agg")  # noqa: E402  (tests draw figures to nowhere)

import matplotlib.pyplot as plt
import numpy as np
import pandas as pd
import pytest
from ma2010_toywalk import toy_walk

from motionvar.claims import VERDICTS, NotApplicable
from motionvar.core import cmu_joint_map
from motionvar.io import load_dataset, save_dataset
from motionvar.ma2010 import figures
from motionvar.ma2010.comparison import METHODS
from motionvar.ma2010.evaluations.common import PAPER
from motionvar.ma2010.evaluations.fig3 import circular_sd, fig3_keyframes, step_phases
from motionvar.ma2010.evaluations.fig6 import fig6_leave_one_out
from motionvar.ma2010.evaluations.fig7b import fig7b_reliability
from motionvar.ma2010.evaluations.fig8 import fig8_fixed_style
from motionvar.ma2010.evaluations.sec7_4 import sec7_4_comparison
from motionvar.ma2010.evaluations.sec8 import sec8_timing
from motionvar.ma2010.examples import WalkCycles, walk_cycles

JM = cmu_joint_map()


def toy_dataset(path, styles, n_cycles=3):
    motions = [toy_walk(hip_amp=0.3 + 0.03 * i, arm_amp=0.2 + 0.1 * i, n_cycles=n_cycles) for i in range(len(styles))]
    meta = pd.DataFrame({"clip_id": [f"w{i}" for i in range(len(styles))], "subject": [f"{i:02d}" for i in range(len(styles))],
                         "behaviour": "walk", "style": styles, "variant": "forward"})
    save_dataset(path, motions, meta)
    return load_dataset(path)


@pytest.fixture(scope="module")
def walks(tmp_path_factory):
    data = toy_dataset(tmp_path_factory.mktemp("data"), ["neutral"] * 4)
    clips, table = walk_cycles(data, JM, ["neutral"], ["forward"], n_frames=24)
    return WalkCycles(clips, table["subject"].tolist(), JM, source="toy walks")


@pytest.fixture(scope="module")
def model(walks):
    return walks.fit_model("auto", "linear")


def check(result, draw, claim_prefix):
    assert len(result.table) and result.claims
    for c in result.claims:
        assert c.claim_id.startswith(f"{PAPER}.{claim_prefix}") and c.verdict in VERDICTS
    fig = draw(result)
    assert fig.axes
    plt.close(fig)


def test_walk_cycles_cut_walks_into_cycles(tmp_path):
    data = toy_dataset(tmp_path, ["neutral"] * 3)
    clips, table = walk_cycles(data, JM, ["neutral"], ["forward"], n_frames=24)
    assert clips.rotations.shape[:2] == (len(table), 24) and table["clip_id"].tolist() == clips.clip_ids
    assert len(table) >= 3 and set(table["source_clip"]) == {"w0", "w1", "w2"}
    assert np.all(table["left_support_stride_cm"] > 50) and set(table["subject"]) == {"00", "01", "02"}


@pytest.mark.parametrize("styles, n_cycles, expected", [(["proud", "proud"], 3, "no clip with"),
                                                         (["neutral"], 1.2, "need at least 3")])
def test_walk_cycles_name_the_problem(tmp_path, styles, n_cycles, expected):
    data = toy_dataset(tmp_path, styles, n_cycles)
    with pytest.raises(ValueError, match=expected) as err:
        walk_cycles(data, JM, ["neutral"], ["forward"], n_frames=24, what="meta.csv (config ma2010.walk_styles)")
    assert str(err.value).startswith("meta.csv (config ma2010.walk_styles)")


def test_walk_cycles_need_one_subject_per_cycle(walks):
    with pytest.raises(ValueError, match="toy walks: 1 subjects"):
        WalkCycles(walks.clips, ["a"], JM, source="toy walks")


def test_fig3_step_phases_and_key_frames(tmp_path):
    assert np.allclose(step_phases(np.array([5, 15, 40]), np.array([0, 10, 20])), [0.5, 0.5])
    assert circular_sd([0.2, 0.2, 0.2]) == pytest.approx(0.0, abs=1e-6) and circular_sd([0.0, 0.5]) > 0.3
    data = toy_dataset(tmp_path, ["neutral"] * 2)
    result = fig3_keyframes(data, JM, ["neutral"], ["forward"], max_clips=1)
    assert set(result.table["behaviour"]) == {"walk"} and set(result.figure["shown"]) == {"walk"}
    assert set(result.table["extremum"]) == {"max", "min"} and (result.table["part"] == "lower").all()
    check(result, figures.draw_fig3, "fig3.walk_keyframes")


def test_fig6_leave_one_out(walks):
    result = fig6_leave_one_out(walks, "auto", "linear", seed=0, max_clips=2)
    t = result.table
    assert len(t) == 2 and list(t.columns[:2]) == ["clip_id", "subject"]
    assert np.all(t["ours_stride_error_cm"] >= 0) and np.all(t["rbf_pose_error_cm"] >= 0)
    assert [c.claim_id for c in result.claims] == ["ma2010.fig6.loo_max_stride_error_below_1_2cm",
                                                   "ma2010.mk05.kriging_beats_rbf"]
    check(result, figures.draw_fig6, "")


def test_fig7b_reliability(walks, model):
    result = fig7b_reliability(walks, model, n_grid=3, margin=0.2)
    assert len(result.table) == 9 and np.all(result.table["nearest_example_cm"] >= 0)
    assert len(result.figure["failed"]) == 9
    check(result, figures.draw_fig7b, "fig7b")


def test_fig8_variants_vary_and_interpolations_do_not(walks, model):
    result = fig8_fixed_style(walks, model, n_variants=3, seed=1, spread_ratio_bounds=[0.1, 10.0])
    t = result.table
    assert (t["kind"] == "variant").sum() == 3 and (t["kind"] == "spread_cm").sum() == 4
    spreads = result.figure["spreads"]
    assert min(spreads["ours"].values()) > 0 and max(spreads["RBF"].values()) < 1e-6
    assert result.claims[1].verdict == "reproduced"  # RBF and Kriging give no variation
    assert len(result.figure["motions"]) == 3
    check(result, figures.draw_fig8, "")


def test_sec7_4_comparison(walks):
    result = sec7_4_comparison(walks, n_examples=3, seconds=2.0, n_sequences=2, gplvm_iterations=2,
                               gplvm_frame_step=4, dbn_max_parents=4)
    t = result.table
    assert set(t["method"]) == {*METHODS, "examples"} and (t["method"] != "examples").sum() == 2 * len(METHODS)
    assert list(result.figure["sequences"]) == list(METHODS)
    ours = t[t["method"] == "ours"]["variation_between_sequences_cm"]
    rbf = t[t["method"] == "rbf"]["variation_between_sequences_cm"]
    assert np.all(ours > 0) and np.allclose(rbf, 0.0)
    check(result, figures.draw_sec7_4, "sec7_4")
    with pytest.raises(NotApplicable, match="toy walks: 1 subject"):
        sec7_4_comparison(WalkCycles(walks.clips, ["one"] * walks.clips.n_clips, JM, "toy walks"))


def test_sec8_timing_with_a_fake_clock(walks, model):
    ticks = iter(np.arange(0.0, 100.0, 0.5))
    result = sec8_timing(walks, model, seconds=2.0, repeats=2, clock=lambda: float(next(ticks)))
    row = result.table.iloc[0]
    assert row["seconds_per_second"] == pytest.approx(0.5 / row["motion_seconds"])
    assert row["example_cycles"] == walks.clips.n_clips and row["subjects"] == 4
    check(result, figures.draw_sec8, "sec8")
