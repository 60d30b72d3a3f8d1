"""Ma 2010 evaluations on toy walks: Fig. 7b's reliability and Fig. 8a's variation at one style."""

import numpy as np
import pandas as pd
import pytest
from ma2010_toy import JM, LINEAR, TOY, check

from motionvar.claim_catalog import spec
from motionvar.ma2010 import figures
from motionvar.ma2010.evaluations.fig7b import fig7b_reliability, reliability_correlation
from motionvar.ma2010.evaluations.fig8 import GROUPS, fig8_fixed_style
from motionvar.ma2010.examples import WalkCycles


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
