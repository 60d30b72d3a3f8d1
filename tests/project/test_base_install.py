"""The base install runs the replication: the project installed without extras
(`python -m pip install -c constraints.txt <project>`) into a fresh virtual environment, whose
python then builds a target of the real workflow and a Snakemake report of it (the
command rule dataset_report runs). The report checks its packages (Pygments, Jinja2,
docutils) only when it runs, and CI installs the `test` extra, which pulls some of them
in: a dry run or the development environment would not notice one missing from the base
dependencies. About 1.5 minutes on 2 cores with the wheels on the local disk."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
# the files a wheel of the project is built from
PROJECT_FILES = ("pyproject.toml", "README.md", "LICENSE")
# the smallest synthetic dataset whose overview figure (a report item) the workflow draws
TINY_CONFIG = """\
datasets:
  synthetic: {source: synthetic, subjects: 1, idle_clips: 1, idle_duration_s: 2.0, walks_per_style: 1,
              turning_walks: 0, runs: 0, sidesteps: 0, picks: 0, places: 0}
"""
TARGET = "results/synthetic/figures/dataset_overview.png"


def copy_project(dest: Path) -> Path:
    """The project's packaging files and src/ in ``dest`` (a build leaves the repository as it is)."""
    dest.mkdir()
    for name in PROJECT_FILES:
        shutil.copy(ROOT / name, dest / name)
    shutil.copytree(ROOT / "src", dest / "src", ignore=shutil.ignore_patterns("__pycache__", "*.egg-info"))
    return dest


def fresh_venv(folder: Path) -> tuple[Path, dict[str, str]]:
    """(its python, the environment of an activated shell) of a new virtual environment."""
    subprocess.run([sys.executable, "-m", "venv", str(folder)], check=True, timeout=300)
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PYTHONHOME", "SNAKEMAKE_PROFILE")}
    env["VIRTUAL_ENV"] = str(folder)
    env["PATH"] = f"{folder / 'bin'}{os.pathsep}{env.get('PATH', '')}"
    return folder / "bin" / "python", env


def run(argv: list[str], env: dict[str, str], cwd: Path, timeout: int) -> subprocess.CompletedProcess:
    result = subprocess.run(argv, env=env, cwd=cwd, capture_output=True, text=True, timeout=timeout)
    assert result.returncode == 0, (argv, result.stdout[-3000:], result.stderr[-6000:])
    return result


@pytest.mark.e2e
def test_base_install_builds_a_report(tmp_path):
    project = copy_project(tmp_path / "project")
    python, env = fresh_venv(tmp_path / "venv")
    install = [str(python), "-m", "pip", "install", "--quiet", "--no-compile", "-c", str(ROOT / "constraints.txt")]
    run([*install, str(project)], env, tmp_path, timeout=900)
    run([str(python), "-m", "pip", "check"], env, tmp_path, timeout=120)
    (tmp_path / "tiny.yaml").write_text(TINY_CONFIG)
    work = tmp_path / "work"
    snakemake = [str(python), "-m", "snakemake", "-s", str(ROOT / "Snakefile"), "-d", str(work)]
    snakemake += ["--configfile", str(tmp_path / "tiny.yaml"), "--workflow-profile", "none", "--cores", "2"]
    run([*snakemake, TARGET], env, tmp_path, timeout=600)
    report = tmp_path / "report.html"
    run([*snakemake, "--report", str(report), TARGET], env, tmp_path, timeout=300)
    assert "dataset_overview.png" in report.read_text(encoding="utf-8", errors="replace")
