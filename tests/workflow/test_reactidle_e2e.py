"""End to end on captured standing idle motion, as a user runs it: config/real/reactidle_idle.yaml
(reduced by config/ci.yaml) on the files of two ReActIdle performers from ../shared/data/real
(skipped when absent). Every Egges 2004 claim ends decided, or undecided with its reason;
what the verdicts are is the data's to say. The walking and picking evaluations are not
applicable, and those that need the hands or toes this rig lacks say so."""

import pandas as pd
import pytest
from pipeline_runs import ROOT
from test_real_data_e2e import run_real_config

from motionvar.claims import CHECKED_VERDICTS

SOURCE = ROOT.parent / "shared" / "data" / "real" / "reactidle_idle"
DATASET = "reactidle_idle"
PERFORMERS = ("p002", "p008")  # a genuine and an acted recording each
UNDECIDED = ("not applicable", "not testable")

pytestmark = [pytest.mark.e2e, pytest.mark.skipif(not SOURCE.is_dir(), reason=f"{SOURCE} absent")]


@pytest.fixture(scope="module")
def idle_run(tmp_path_factory):
    base = tmp_path_factory.mktemp("reactidle")
    subset = base / "two_performers"
    subset.mkdir()
    labels = pd.read_csv(SOURCE / "labels.csv", dtype=str, keep_default_na=False)
    labels = labels[labels["subject"].isin(PERFORMERS)]
    for name in labels["file"]:
        (subset / name).symlink_to(SOURCE / name)
    labels.to_csv(subset / "labels.csv", index=False)
    work = base / "run"
    (work / "reports").mkdir(parents=True)
    (work / "config").symlink_to(ROOT / "config")
    run_real_config(work, DATASET, "--config", f"datasets={{{DATASET}: {{path: {subset}}}}}")
    return work


def test_every_egges_claim_is_decided_or_says_why_not(idle_run):
    results = idle_run / "results" / DATASET
    claims = pd.read_csv(results / "claims.csv", keep_default_na=False)
    assert (idle_run / "reports" / f"{DATASET}.html").is_file()
    egges = claims[claims["paper"] == "egges2004"]
    assert len(egges) >= 5
    for row in egges.itertuples():
        # undecided only with its reason (two people give an identification test little power)
        assert row.verdict in CHECKED_VERDICTS or (row.verdict in UNDECIDED and row.note.strip()), row
    model = pd.read_csv(results / "tables" / "egges2004_categories.csv", dtype={"subject": str})
    assert set(model["subject"]) == set(PERFORMERS)  # one database per performer


def test_what_needs_hands_or_toes_says_the_rig_lacks_them(idle_run):
    table = pd.read_csv(idle_run / "results" / DATASET / "applicability.csv", keep_default_na=False)
    table = table.set_index("evaluation")
    assert not table["applicable"][[e for e in table.index if not e.startswith("egges2004")]].any()
    assert "left_toe, right_toe, which the joint map" in table.loc["ma2010_fig6", "reason"]
    assert "left_hand, right_hand, left_toe, right_toe" in table.loc["du2022_table5_2", "reason"]
    realism = pd.read_csv(idle_run / "results" / DATASET / "tables" / "dataset_realism.csv")
    assert {"idle_sway_sd_cm", "idle_weight_shifts_per_min"} <= set(realism["statistic"])
