"""Rule data on a labelled BVH folder, through Snakemake: its inputs are the files the
import may read (the folder's BVH files, `.bvh` in any case), so that editing one reruns
it; a labels row naming a file outside the folder stops it with one line."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import yaml

from motionvar.core import CMU_UNIT_CM, Motion, cmu_skeleton
from motionvar.core import quaternions as Q
from motionvar.io.bvh import write_bvh
from motionvar.io.bvh_dataset import bvh_files

ROOT = Path(__file__).resolve().parents[2]
TARGET = "results/mine/data/metadata.csv"
pytestmark = pytest.mark.e2e  # Snakemake subprocesses


def motion(frames: int = 6) -> Motion:
    sk = cmu_skeleton()
    return Motion(sk, np.tile([0.0, 95.0, 0.0], (frames, 1)), Q.qidentity((frames, sk.n_joints)), fps=120.0)


def bvh_folder(folder: Path, rows: list[str]) -> Path:
    """Clips 1.BVH, 2.BVH and sub/3.Bvh, a text file, and a labels CSV of ``rows``."""
    (folder / "sub").mkdir(parents=True)
    for rel in ("1.BVH", "2.BVH", "sub/3.Bvh"):
        write_bvh(folder / rel, motion(), scale=CMU_UNIT_CM)
    (folder / "notes.txt").write_text("not motion\n")
    (folder / "labels.csv").write_text("file,subject,behaviour,style\n" + "".join(f"{r}\n" for r in rows))
    return folder


def snakemake(work: Path, folder: Path, *args: str) -> subprocess.CompletedProcess:
    """The workflow on dataset `mine` (``folder``, sanity gates off: the clips stand still) in ``work``."""
    entry = {"source": "bvh", "path": str(folder), "unit_cm": CMU_UNIT_CM, "plausibility_check": False}
    config = work / "mine.yaml"
    config.write_text(yaml.safe_dump({"datasets": {"mine": entry}, "run_datasets": ["mine"]}))
    argv = [sys.executable, "-m", "snakemake", "-s", str(ROOT / "Snakefile"), "-d", str(work)]
    argv += ["--configfile", str(config), "--workflow-profile", "none", "--cores", "1", *args, TARGET]
    return subprocess.run(argv, cwd=work, capture_output=True, text=True, timeout=300)


def test_through_the_default_profile_a_failed_rule_prints_its_line_once(tmp_path):
    """Run as a user runs it (the default profile): the bad input's one line reaches the terminal
    once, with no traceback; the traceback stays in the rule's log, which Snakemake names."""
    write_bvh(tmp_path / "x.bvh", motion(), scale=CMU_UNIT_CM)
    folder = bvh_folder(tmp_path / "caps", ["1.BVH,a,walk,x", "../x.bvh,a,walk,x"])
    work = tmp_path / "work"
    work.mkdir()
    entry = {"source": "bvh", "path": str(folder), "unit_cm": CMU_UNIT_CM, "plausibility_check": False}
    config = work / "mine.yaml"
    config.write_text(yaml.safe_dump({"datasets": {"mine": entry}, "run_datasets": ["mine"]}))
    argv = [sys.executable, "-m", "snakemake", "-s", str(ROOT / "Snakefile"), "-d", str(work), "--configfile"]
    argv += [str(config), "--workflow-profile", str(ROOT / "profiles" / "default"), TARGET]
    result = subprocess.run(argv, cwd=work, capture_output=True, text=True, timeout=300)
    out = result.stdout + result.stderr
    assert result.returncode == 1
    assert sum("lies outside the dataset folder" in line for line in out.splitlines()) == 1, out[-3000:]
    assert "Traceback" not in out and "results/mine/logs/data.log" in out
    assert "Traceback" in (work / "results" / "mine" / "logs" / "data.log").read_text()


def job_inputs(dry_run_output: str) -> set[str]:
    """The input files of the one job of a dry run's output."""
    lines = [line.strip() for line in dry_run_output.splitlines() if line.strip().startswith("input: ")]
    assert len(lines) == 1, dry_run_output[-2000:]
    return set(lines[0].removeprefix("input: ").split(", "))


def test_an_edited_bvh_file_in_any_case_reruns_the_import(tmp_path):
    folder = bvh_folder(tmp_path / "caps", ["1.BVH,a,walk,x", "2.BVH,a,walk,x", "sub/3.Bvh,b,walk,x"])
    work = tmp_path / "work"
    work.mkdir()
    dry = snakemake(work, folder, "-n")
    assert job_inputs(dry.stdout) == {str(p) for p in [folder / "labels.csv", *bvh_files(folder)]}
    built = snakemake(work, folder)
    assert built.returncode == 0, built.stderr[-4000:]
    assert snakemake(work, folder, "-n").stdout.count("Nothing to be done") == 1
    write_bvh(folder / "sub" / "3.Bvh", motion(frames=8), scale=CMU_UNIT_CM)  # an edit
    dry = snakemake(work, folder, "-n")
    assert "Nothing to be done" not in dry.stdout and "rule data:" in dry.stdout, dry.stdout[-2000:]


def test_a_label_row_outside_the_folder_stops_the_rule_with_one_line(tmp_path):
    write_bvh(tmp_path / "x.bvh", motion(), scale=CMU_UNIT_CM)
    folder = bvh_folder(tmp_path / "caps", ["1.BVH,a,walk,x", "../x.bvh,a,walk,x"])
    work = tmp_path / "work"
    work.mkdir()
    result = snakemake(work, folder)
    assert result.returncode == 1
    errors = [line for line in (result.stdout + result.stderr).splitlines() if line.startswith("ERROR rule data:")]
    assert errors == [
        f"ERROR rule data: datasets.mine: {folder / 'labels.csv'}:3: labelled file '../x.bvh' lies outside the "
        f"dataset folder {folder}: move it into the folder (the run tracks only the folder's files)"
    ]
    assert not (work / TARGET).exists()
