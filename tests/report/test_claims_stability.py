"""Claims stability across seeds (motionvar.report.stability): agreement counts, the stable
rule (4 of 5), the interval of the values, claims missing from a seed, and the figure/page."""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest
from scipy import stats

from motionvar.claims import CLAIM_COLUMNS
from motionvar.plots.stability import stability_figure
from motionvar.report.stability import claims_stability, stability_html


def table(rows: list[tuple]) -> pd.DataFrame:
    """Claims tables as the rule `claims` writes them (strings; empty value = none)."""
    out = []
    for cid, verdict, value in rows:
        out.append(
            dict(
                zip(
                    CLAIM_COLUMNS,
                    [
                        cid,
                        cid.split(".")[0],
                        "Fig. 1",
                        "replication",
                        "s",
                        "p",
                        "m",
                        verdict,
                        "",
                        "" if value is None else str(value),
                        "1.2",
                        "cm",
                        "<=",
                    ],
                )
            )
        )
    return pd.DataFrame(out, columns=list(CLAIM_COLUMNS))


@pytest.fixture
def five():
    v = [1.0, 1.1, 1.3, 0.9, 1.25]
    verdict = ["reproduced", "reproduced", "partial", "reproduced", "partial"]
    return {
        f"s{k}": table(
            [
                ("ma2010.a", "reproduced", 0.5 + 0.01 * k),
                ("ma2010.b", verdict[k], v[k]),
                ("du2022.c", "not testable", None),
            ]
            + ([("du2022.d", "reproduced", 2.0)] if k < 4 else [])
        )
        for k in range(5)
    }


def test_agreement_counts_and_the_stable_rule(five):
    t = claims_stability(five).set_index("claim_id")
    assert t.loc["ma2010.a", "n_agree"] == 5 and t.loc["ma2010.a", "stable"]
    assert t.loc["ma2010.b", "verdict"] == "reproduced" and t.loc["ma2010.b", "n_agree"] == 3
    assert not t.loc["ma2010.b", "stable"]  # 3 of 5 < 4 of 5
    assert t.loc["du2022.c", "stable"] and math.isnan(t.loc["du2022.c", "value_mean"])
    # missing from one seed: a verdict of its own, 4 of 5 still stable
    assert t.loc["du2022.d", "verdict_s4"] == "missing" and t.loc["du2022.d", "n_agree"] == 4
    assert t.loc["du2022.d", "stable"]
    assert list(t.reset_index().columns[:4]) == ["claim_id", "paper", "source", "kind"]


def test_interval_is_the_student_t_interval_of_the_mean(five):
    t = claims_stability(five).set_index("claim_id")
    v = np.array([1.0, 1.1, 1.3, 0.9, 1.25])
    half = stats.t.ppf(0.975, 4) * v.std(ddof=1) / np.sqrt(5)
    assert t.loc["ma2010.b", "value_mean"] == pytest.approx(v.mean())
    assert t.loc["ma2010.b", "value_sd"] == pytest.approx(v.std(ddof=1))
    assert (t.loc["ma2010.b", "value_ci_low"], t.loc["ma2010.b", "value_ci_high"]) == pytest.approx(
        (v.mean() - half, v.mean() + half)
    )
    assert t.loc["ma2010.b", "bound"] == 1.2
    # a claim measured by only four seeds: interval over those four
    assert t.loc["du2022.d", "value_sd"] == pytest.approx(0.0)


def test_bad_input_is_refused(five):
    with pytest.raises(ValueError, match="no claims tables"):
        claims_stability({})
    dup = {"s0": pd.concat([five["s0"], five["s0"].iloc[:1]])}
    with pytest.raises(ValueError, match="lists a claim twice"):
        claims_stability(dup)


def test_page_and_figure(five):
    t = claims_stability(five)
    page = stability_html(t)
    assert page.index("ma2010.b") < page.index("ma2010.a")  # not stable first
    assert "not stable" in page and "3/5" in page
    fig = stability_figure(t)
    assert len(fig.axes) == 3  # the claims that carry a value


def test_a_bound_measured_per_seed_is_kept_per_seed(five):
    """A bound measured on each seed's data (a recorded reference) is kept per seed; the figure
    draws each seed's bound beside its dot instead of one line, and the unstable claims' table
    gives it in each seed's cell."""
    from motionvar.report.counts import seed_bounds
    from motionvar.report.results_markdown import unstable_markdown

    for k, t in five.items():
        t.loc[t["claim_id"] == "ma2010.b", "bound"] = str(1.0 + 0.1 * int(k[1:]))
    st = claims_stability(five)
    rows = st.set_index("claim_id")
    assert [rows.loc["ma2010.b", f"bound_s{k}"] for k in range(5)] == pytest.approx([1.0, 1.1, 1.2, 1.3, 1.4])
    assert rows.loc["ma2010.b", "bound"] == 1.0  # the first seed's
    seeds = [f"s{k}" for k in range(5)]
    assert seed_bounds(rows.loc["ma2010.b"], seeds) == pytest.approx([1.0, 1.1, 1.2, 1.3, 1.4])
    assert seed_bounds(rows.loc["ma2010.a"], seeds) is None  # one bound for all
    fig = stability_figure(st)
    b_axis = fig.axes[[i for i, r in enumerate(st.dropna(subset=["value_mean"]).claim_id) if r == "ma2010.b"][0]]
    ticks = [ln for ln in b_axis.lines if ln.get_color() == "tab:red"]
    assert sorted(ln.get_xdata()[0] for ln in ticks) == pytest.approx([1.0, 1.1, 1.2, 1.3, 1.4])
    assert "&lt;= measured per seed" in stability_html(st) and "1.1 (&lt;= 1.1)" in stability_html(st)
    md = unstable_markdown(st, ["ma2010.b"])
    assert (
        "| `ma2010.b` | replication | <= measured per seed cm | 1 reproduced (<= 1) | 1.1 reproduced (<= 1.1) |" in md
    )
