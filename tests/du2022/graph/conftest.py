"""Fixtures shared by the Morphable Graph tests (one instance per test process): the toy clips,
two primitives fitted to them, the clips as a packed dataset and the joints the constraints name."""

from __future__ import annotations

import pandas as pd
import pytest
from graph_toy import OPT, toy_clips

from motionvar.core import cmu_joint_map
from motionvar.du2022.graph import MotionPrimitive
from motionvar.io import load_dataset, save_dataset


@pytest.fixture(scope="session")
def clips():
    return toy_clips(16)


@pytest.fixture(scope="session")
def prim(clips):
    return MotionPrimitive("walk_leftStance", OPT).fit(clips)


@pytest.fixture(scope="session")
def right(clips):
    return MotionPrimitive("walk_rightStance", OPT).fit(clips[::-1])


@pytest.fixture(scope="session")
def dataset(clips, tmp_path_factory):
    """The toy clips as a packed dataset: clips 0-7 are walks of two source clips
    alternating left and right stance, clips 8-15 pick reaches."""
    d = tmp_path_factory.mktemp("prep")
    walk = ["walk_leftStance", "walk_rightStance"] * 4
    meta = pd.DataFrame(
        dict(
            clip_id=[f"c{i}" for i in range(16)],
            source_clip=[f"w{i // 4}" for i in range(8)] + [f"p{i}" for i in range(8)],
            primitive=walk + ["pick_reach"] * 8,
            start_frame=[100 * (i % 4) for i in range(16)],
            stop_frame=[100 * (i % 4) + c.n_frames for i, c in enumerate(clips)],
        )
    )
    save_dataset(d, clips, meta)
    return load_dataset(d)


@pytest.fixture(scope="session")
def joints(prim):
    jm, sk = cmu_joint_map(), prim.skeleton
    return {
        k: jm.index(sk, k)
        for k in (
            "hips",
            "right_hand",
            "left_hand",
            "left_ankle",
            "right_ankle",
            "left_shoulder",
            "right_shoulder",
            "left_hip",
            "right_hip",
        )
    }
