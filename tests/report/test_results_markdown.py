"""docs/results.md and README's counts from merged claims tables (tools/readme_results.py)."""

import pandas as pd

from motionvar.claims import Claim
from motionvar.report.results_markdown import results_markdown, verdict_counts
from motionvar.report.stability import claims_stability


def _table(claims):
    return pd.DataFrame([c.__dict__ for c in claims])


def _claim(cid, kind, verdict, statement="s", measured="m", **kw):
    return Claim(cid, cid.split(".")[0], "Fig. 6", kind, statement, "<1.2", measured, verdict, **kw)


MAIN = _table(
    [
        _claim("ma2010.a", "replication", "reproduced", "stride | error", "0.9 cm", value=0.9, bound=1.2, unit="cm"),
        _claim("ma2010.b", "stand-in", "partial"),
        _claim("ma2010.c", "consistency", "reproduced"),
        _claim("du2022.b", "replication", "partial"),
    ]
)


def test_results_count_by_paper_and_kind_and_list_claims():
    xia = _table(
        [
            _claim("ma2010.a", "replication", "not reproduced"),
            _claim("egges2004.s", "consistency", "not applicable", note="no idle clips"),
        ]
    )
    md = results_markdown(MAIN, "synthetic", {"xia": xia}, "config/config.yaml")
    assert "| Ma et al. 2010 | replication | 1 | 1 reproduced, 0 partial, 0 not reproduced |" in md
    assert "| Ma et al. 2010 | stand-in | 1 | 0 reproduced, 1 partial, 0 not reproduced |" in md
    assert "| Ma et al. 2010 | consistency | 1 | 1 checks: 1 hold, 0 fail |" in md
    assert "| Fig. 6 | replication | stride \\| error | reproduced | - | - | 0.9 cm |" in md
    assert "- `xia`: 2 claims: replication 0 reproduced, 0 partial, 1 not reproduced; consistency 1 checks: " in md
    assert "### Egges et al. 2004" in md and "*(no claims)*" in md


def test_a_verdict_that_fewer_than_four_of_five_seeds_give_is_unstable():
    seeds = {}
    for i in range(5):
        t = MAIN.copy()
        t.loc[t.claim_id == "ma2010.a", "verdict"] = "reproduced" if i < 3 else "partial"
        t.loc[t.claim_id == "ma2010.a", "value"] = 0.9 + i / 10
        seeds[f"s{i}"] = t.astype(str)
    stability = claims_stability(seeds)
    md = results_markdown(MAIN, "s0", None, "", stability)
    assert "| Ma et al. 2010 | replication | 1 | 0 reproduced, 0 partial, 0 not reproduced, 1 unstable |" in md
    assert "| unstable (reproduced) | 3/5 | 1.1 [0.904, 1.3] cm |" in md
    assert "Unstable claims (1 of 4), per seed: value and verdict." in md
    assert (
        "| `ma2010.a` | replication | 1.2 cm | 0.9 reproduced | 1 reproduced | 1.1 reproduced | 1.2 partial | 1.3 partial |"
        in md
    )
    assert "| Ma et al. 2010 | stand-in | 1 | 0 reproduced, 1 partial, 0 not reproduced |" in md


def test_verdict_counts_leaves_out_absent_undecided_verdicts():
    assert verdict_counts(pd.Series(["reproduced", "reproduced"])) == "2 reproduced, 0 partial, 0 not reproduced"


def test_seeds_of_another_configuration_are_counted_apart():
    seeds = {f"ci_s{i}": MAIN.astype(str) for i in range(5)}
    seeds["ci_s4"] = seeds["ci_s4"].assign(verdict=lambda t: t["verdict"].where(t.claim_id != "ma2010.b", "reproduced"))
    seeds["ci_s3"] = seeds["ci_s4"]
    md = results_markdown(MAIN, "synthetic", None, "", claims_stability(seeds))
    assert "Across the 5 seeds (ci_s0, ci_s1, ci_s2, ci_s3, ci_s4)" in md
    assert "| Ma et al. 2010 | stand-in | 1 | 0 reproduced, 0 partial, 0 not reproduced, 1 unstable |" in md
    assert "| partial | partial 3/5 |" in md and "seeds: verdict, agreeing" in md
    assert "Unstable claims (1 of 4), per seed: value and verdict." in md and "| `ma2010.b` | stand-in |" in md


def test_a_run_whose_verdict_the_other_seeds_do_not_give_is_listed_unstable():
    """Four seeds agree with one another, not with this run: its verdict is unstable (1 of 5)."""
    seeds = {f"s{i}": MAIN.astype(str) for i in range(5)}
    seeds["s0"] = seeds["s0"].assign(verdict=lambda t: t["verdict"].where(t.claim_id != "du2022.b", "not reproduced"))
    main = MAIN.assign(verdict=lambda t: t["verdict"].where(t.claim_id != "du2022.b", "not reproduced"))
    md = results_markdown(main, "s0", None, "", claims_stability(seeds))
    assert "| Du 2022 | replication | 1 | 0 reproduced, 0 partial, 0 not reproduced, 1 unstable |" in md
    assert "Unstable claims (1 of 4)" in md and "| `du2022.b` | replication |" in md
