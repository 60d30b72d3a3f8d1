"""docs/results.md from merged claims tables (tools/readme_results.py)."""

import pandas as pd

from motionvar.claims import Claim, not_applicable_result
from motionvar.report.results_markdown import results_markdown, verdict_counts


def _table(claims):
    return pd.DataFrame([c.__dict__ for c in claims])


def test_results_markdown_counts_and_lists_claims():
    main = _table(
        [
            Claim("ma2010.a", "ma2010", "Fig. 6", "stride | error", "<1.2", "0.9 cm", "reproduced"),
            Claim("du2022.b", "du2022", "Fig. 3.9", "rmse falls", "-", "5/5", "partial"),
        ]
    )
    xia = _table(
        [
            Claim("ma2010.a", "ma2010", "Fig. 6", "s", "p", "m", "not reproduced"),
            not_applicable_result("egges2004_speed", "no idle clips", source="Sec. 8").claims[0],
        ]
    )
    md = results_markdown(main, "synthetic", {"xia": xia}, "config/config.yaml")
    assert "1 reproduced, 1 partial, 0 not reproduced" in md
    assert "| Fig. 6 | stride \\| error | reproduced | 0.9 cm |" in md
    assert (
        "- `xia`: 2 claims: 0 reproduced, 0 partial, 1 not reproduced, 1 not applicable; not applicable: "
        "Sec. 8 (egges2004)." in md
    )
    assert "### Egges et al. 2004" in md and "*(no claims)*" in md


def test_verdict_counts_leaves_out_absent_undecided_verdicts():
    assert verdict_counts(pd.Series(["reproduced", "reproduced"])) == "2 reproduced, 0 partial, 0 not reproduced"
