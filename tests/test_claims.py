"""The claims contract (motionvar.claims): the number a verdict comes from travels with the
claim (value, bound, unit, direction), and claims written before those fields still read."""

from __future__ import annotations

import json
import math

import numpy as np
import pandas as pd
import pytest

from motionvar.claims import CLAIM_COLUMNS, TEXT_COLUMNS, Claim, merge_claims, read_claims, write_claims
from motionvar.report.summary import read_claims_table


def claim(**kw) -> Claim:
    base = dict(
        claim_id="ma2010.x",
        paper="ma2010",
        source="Fig. 6",
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


def test_claims_written_before_value_and_bound_still_read(tmp_path):
    old = {k: "s" for k in TEXT_COLUMNS} | {"claim_id": "du2022.a", "paper": "du2022", "verdict": "reproduced"}
    (tmp_path / "old.json").write_text(json.dumps([old]))
    c = read_claims(tmp_path / "old.json")[0]
    assert c.value is None and c.bound is None and c.unit == "" and c.direction == ""
    pd.DataFrame([old]).to_csv(tmp_path / "old.csv", index=False)
    table = read_claims_table(tmp_path / "old.csv")
    assert list(table.columns) == list(CLAIM_COLUMNS) and table.loc[0, "value"] == ""
