"""Fixtures shared by the labelled-folder tests: three CMU-unit clips and their labels CSV."""

from __future__ import annotations

from pathlib import Path

import pytest
from bvh_dataset_toy import cmu_motion

from motionvar.core import CMU_UNIT_CM
from motionvar.io import write_bvh


@pytest.fixture
def folder(tmp_path) -> Path:
    """Three CMU-unit clips in a folder (one in a subfolder) and a labels CSV."""
    d = tmp_path / "bvh"
    (d / "sub").mkdir(parents=True)
    for seed, rel in enumerate(["a.bvh", "b.bvh", "sub/c.bvh"]):
        write_bvh(d / rel, cmu_motion(seed), scale=CMU_UNIT_CM)
    (d / "labels.csv").write_text(
        "file,subject,behaviour,style,variant,take\n"
        "a.bvh,02,walk,neutral,v1,1\n"
        "b.bvh,02,walk,proud,,2\n"
        "sub/c.bvh,07,run,,,3\n"
    )
    return d
