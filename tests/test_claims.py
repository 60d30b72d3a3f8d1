"""The claims contract (motionvar.claims): every claim says what kind of evidence it is, the number a
verdict comes from travels with the claim (value, bound, unit, direction), a claim is judged by its
declaration (ClaimSpec), and a claims table without the kind column is refused with its file named."""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest

from motionvar.claims import (
    CLAIM_COLUMNS,
    TEXT_COLUMNS,
    Claim,
    ClaimSpec,
    Judgement,
    judge_claims,
    merge_claims,
    read_claims,
    verdict_threshold,
    write_claims,
)
from motionvar.report.summary import read_claims_table


def claim(**kw) -> Claim:
    base = dict(
        claim_id="ma2010.x",
        paper="ma2010",
        source="Fig. 6",
        kind="replication",
        statement="s",
        published="p",
        measured="m",
        verdict="partial",
    )
    return Claim(**{**base, **kw})


def test_value_and_bound_round_trip_as_floats(tmp_path):
    c = claim(value=np.float32(1.88), bound=np.int64(1), unit="cm", direction="<=")
    assert isinstance(c.value, float) and c.bound == 1.0
    nan = claim(claim_id="ma2010.y", value=float("nan"), bound=1.2, direction="<=")
    write_claims(tmp_path / "c.json", [c, nan])
    back = read_claims(tmp_path / "c.json")
    assert back[0] == c and math.isnan(back[1].value)
    table = merge_claims([tmp_path / "c.json"])
    assert list(table.columns) == list(CLAIM_COLUMNS) and table.loc[0, "unit"] == "cm"


@pytest.mark.parametrize("bad", [dict(value="1.2"), dict(bound=True), dict(direction="=="), dict(value=[1.0])])
def test_bad_values_are_refused(bad):
    with pytest.raises(ValueError, match="ma2010.x"):
        claim(**bad)


def test_a_claim_without_a_known_kind_is_refused():
    with pytest.raises(ValueError, match="kind 'proxy'"):
        claim(kind="proxy")


def test_a_claims_table_without_the_kind_column_names_its_file(tmp_path):
    old = {k: "s" for k in TEXT_COLUMNS if k != "kind"} | {"claim_id": "du2022.a", "paper": "du2022"}
    pd.DataFrame([old | {"verdict": "reproduced"}]).to_csv(tmp_path / "old.csv", index=False)
    with pytest.raises(ValueError, match="old.csv: columns"):
        read_claims_table(tmp_path / "old.csv")


def _judge(m):
    return Judgement(verdict_threshold(m["error"], 1.2, "<="), f"{m['error']:.2f} cm", "", m["error"], 1.2, "cm", "<=")


SPEC = ClaimSpec(
    "ma2010.fig6.x", "ma2010_fig6", "Fig. 6", "replication", "below 1.2 cm", "< 1.2 cm", "<= 1.2 cm", _judge
)


def test_a_declared_claim_is_judged_from_measurements():
    (c,) = judge_claims([SPEC], "ma2010_fig6", {"error": 0.9})
    assert (c.verdict, c.kind, c.value, c.bound, c.measured) == ("reproduced", "replication", 0.9, 1.2, "0.90 cm")
    assert SPEC.claim({"error": 1.5}).verdict == "not reproduced"
    assert SPEC.undecided("not testable", "one cycle").note == "one cycle"
    with pytest.raises(ValueError, match="no claim declared"):
        judge_claims([SPEC], "ma2010_fig8", {})
    with pytest.raises(ValueError, match="kind"):
        ClaimSpec("ma2010.y", "ma2010_fig6", "Fig. 6", "proof", "s", "p", "b", _judge)
    with pytest.raises(ValueError, match="one paper"):
        ClaimSpec("ma2010.y", "du2022_fig3_9", "Fig. 6", "stand-in", "s", "p", "b", _judge)
