"""What the labelled-folder tests share: the shipped joint maps, a random CMU clip and a labels
CSV written into a folder."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from motionvar.core import Motion, cmu_skeleton
from motionvar.core import quaternions as Q

MAPS = Path(__file__).resolve().parents[2] / "config/joint_maps"


def cmu_motion(seed: int, frames: int = 12) -> Motion:
    rng = np.random.default_rng(seed)
    sk = cmu_skeleton(straight_legs=False)
    rot = Q.qnormalize(np.array([1.0, 0, 0, 0]) + 0.1 * rng.normal(size=(frames, sk.n_joints, 4)))
    return Motion(sk, rng.normal(size=(frames, 3)) * 10 + [0, 95, 0], rot, fps=120.0)


def labels_csv(folder: Path, text: str) -> Path:
    path = folder / "labels.csv"
    path.write_text(text)
    return path
