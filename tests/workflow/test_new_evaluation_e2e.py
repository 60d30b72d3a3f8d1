"""A new evaluation is one declaration plus its caption: in a copy of the project, a toy
evaluation of Ma 2010 (the method: a module with its measuring and drawing functions) is
declared in ``ma2010/catalog.py`` with one claim in ``ma2010/claims.py`` and a caption
``workflow/report/ma2010_toy.rst``; nothing else is edited. On a copy of the CI run, the
workflow then has its rule, the dataset's claims table its claim and the report its entry."""

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pandas as pd
import pytest

ROOT = Path(__file__).resolve().parents[2]
CI_CONFIG = str(ROOT / "config" / "ci.yaml")

#: the method: measures the walking cycles of input set ``ma2010_walks`` and draws their count
TOY_METHOD = """
import matplotlib.pyplot as plt
import pandas as pd

from ..claims import EvaluationResult, judge_claims
from .claims import CLAIMS


def count_cycles(walks, settings):
    measurements = {"cycles": walks.clips.n_clips}
    table = pd.DataFrame([measurements])
    return EvaluationResult(table, judge_claims(CLAIMS, "ma2010_toy", measurements), {}, measurements)


def draw_count(result):
    fig, ax = plt.subplots()
    ax.bar(["cycles"], [result.measurements["cycles"]])
    return fig
"""

#: the declaration (appended to ma2010/catalog.py)
TOY_DECLARATION = """
EVALUATIONS += (
    Evaluation(
        "ma2010_toy",
        "Toy",
        "The examples hold at least two walking cycles.",
        "ma2010",
        inputs="ma2010_walks",
        measure="motionvar.ma2010.toy:count_cycles",
        draw="motionvar.ma2010.toy:draw_count",
    ),
)
"""

#: its claim (appended to ma2010/claims.py)
TOY_CLAIM = """
CLAIMS += (
    ClaimSpec(
        claim_id="ma2010.toy.two_cycles",
        evaluation="ma2010_toy",
        source="Toy",
        kind="consistency",
        statement="The examples hold at least two walking cycles.",
        published="2",
        bound="cycles >= 2",
        judge=lambda m: Judgement(
            verdict=verdict_threshold(m["cycles"], 2, ">="), measured=f"{m['cycles']} cycles", value=m["cycles"]
        ),
    ),
)
"""

TOY_CAPTION = "Toy evaluation: the number of walking cycles the examples hold.\n"


def _project_with_toy(folder: Path) -> Path:
    """A copy of the project (Snakefile, workflow, config, src) with the toy declared."""
    for name in ("workflow", "config", "src"):
        shutil.copytree(ROOT / name, folder / name, ignore=shutil.ignore_patterns("__pycache__", "*.egg-info"))
    shutil.copy2(ROOT / "Snakefile", folder / "Snakefile")
    package = folder / "src" / "motionvar" / "ma2010"
    (package / "toy.py").write_text(TOY_METHOD)
    with open(package / "catalog.py", "a") as f:
        f.write(TOY_DECLARATION)
    with open(package / "claims.py", "a") as f:
        f.write(TOY_CLAIM)
    (folder / "workflow" / "report" / "ma2010_toy.rst").write_text(TOY_CAPTION)
    return folder


@pytest.mark.e2e
def test_a_new_evaluation_is_one_declaration_and_its_caption(ci_run, tmp_path):
    project = _project_with_toy(tmp_path / "project")
    work = tmp_path / "work"
    shutil.copytree(ci_run.work, work, symlinks=True, ignore=shutil.ignore_patterns(".snakemake"))
    env = {**os.environ, "PYTHONPATH": str(project / "src")}
    result = subprocess.run(
        [sys.executable, "-m", "snakemake", "-s", str(project / "Snakefile"), "-d", str(work)]
        + ["--configfile", CI_CONFIG, "--cores", "2", "--rerun-triggers", "mtime", "--forcerun", "applicability"],
        cwd=work,
        env=env,
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert result.returncode == 0, result.stdout[-2000:] + result.stderr[-4000:]
    ran = set(re.findall(r"^(?:local)?rule (\w+):", result.stdout + result.stderr, flags=re.M))
    assert "ma2010_toy" in ran and not ran & {"ma2010_fig6", "ma2010_clips", "du2022_table5_2"}, ran
    claims = pd.read_csv(work / "results" / "synthetic" / "claims.csv")
    toy = claims[claims["claim_id"] == "ma2010.toy.two_cycles"]
    assert len(toy) == 1 and toy["verdict"].iloc[0] == "reproduced", toy.to_dict("records")
    assert (work / "results" / "synthetic" / "figures" / "ma2010_toy.png").stat().st_size > 0
    report = (work / "reports" / "synthetic.html").read_text(encoding="utf-8", errors="replace")
    assert "ma2010_toy.png" in report and "Toy evaluation: the number of walking cycles" in report
