"""End to end on real motion capture, as a user runs it: config/real/dfki_markerless.yaml
(reduced by config/ci.yaml) on ../shared/data/real (skipped when absent). The run ends
clean with a claims table, its summary and the report; evaluations the data cannot
support are `not applicable` with their reason, the others get checked verdicts."""

import shutil

import pandas as pd
import pytest
from pipeline_runs import CI_CONFIG, ROOT, run_snakemake

from motionvar.claims import CHECKED_VERDICTS

REAL = ROOT.parent / "shared" / "data" / "real"
DATASET = "dfki_markerless"

pytestmark = [
    pytest.mark.e2e,
    pytest.mark.skipif(not (REAL / DATASET).is_dir(), reason=f"{REAL / DATASET} absent"),
]


def run_real_config(work, dataset: str, *more: str) -> None:
    """Run config/real/<dataset>.yaml, reduced by config/ci.yaml, in ``work`` (which has a
    reports/ folder), with ``more`` arguments; assert it ends clean."""
    result = run_snakemake(
        "-d",
        str(work),
        "--configfile",
        CI_CONFIG,
        str(ROOT / "config" / "real" / f"{dataset}.yaml"),
        *more,
        "--cores",
        "2",
        cwd=work,
    )
    assert result.returncode == 0, result.stdout[-4000:] + result.stderr[-8000:]


@pytest.fixture(scope="module")
def real_run(tmp_path_factory):
    base = tmp_path_factory.mktemp("real")
    work = base / "run"
    (work / "reports").mkdir(parents=True)
    # the config's paths are relative to the working directory, as from the repository root
    (base / "shared").symlink_to(ROOT.parent / "shared")
    shutil.copytree(ROOT / "config" / "joint_maps", work / "config" / "joint_maps")
    run_real_config(work, DATASET)
    return work


def test_real_set_gets_claims_summary_and_report(real_run):
    results = real_run / "results" / DATASET
    claims = pd.read_csv(results / "claims.csv", keep_default_na=False)
    assert (results / "claims_summary.html").is_file() and (real_run / "reports" / f"{DATASET}.html").is_file()
    checked = claims[claims["verdict"].isin(CHECKED_VERDICTS)]
    na = claims[claims["verdict"] == "not applicable"]
    assert len(checked) >= 3, claims[["claim_id", "verdict"]]
    # no idle recordings: every Egges 2004 evaluation is not applicable, and says why
    egges = claims[claims["paper"] == "egges2004"]
    assert len(egges) and set(egges["verdict"]) == {"not applicable"}
    assert all("idle" in note for note in egges["note"])
    assert all(note.strip() for note in na["note"])


def test_real_set_primitives_come_from_the_labels(real_run):
    prep = pd.read_csv(real_run / "results" / DATASET / "prep" / "metadata.csv", keep_default_na=False)
    assert set(prep["primitive"]) == {"walk_start", "walk_leftStance", "walk_rightStance", "walk_end"}
    assert len(prep) > 300  # every labelled single-step clip is one primitive
