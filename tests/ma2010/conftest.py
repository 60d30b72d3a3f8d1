"""Fixtures shared by the Ma 2010 tests (one instance per test process): toy walks as walking
cycles and the model fitted to them, and toy clips of the model tests."""

import numpy as np
import pytest
from ma2010_toy import JM, KEYFRAMES, LINEAR, TOY, toy_dataset
from ma2010_toywalk import toy_walk

from motionvar.ma2010 import build_clipset, cut, extract_cycles
from motionvar.ma2010.correspondence import standard_skeleton
from motionvar.ma2010.examples import WalkCycles, walk_cycles


@pytest.fixture(scope="session")
def walks(tmp_path_factory):
    data = toy_dataset(tmp_path_factory.mktemp("data"), ["neutral"] * 4)
    clips, table = walk_cycles(data, JM, TOY)
    return WalkCycles(clips, table["subject"].tolist(), JM, source="toy walks", root_group="legs")


@pytest.fixture(scope="session")
def model(walks):
    return walks.fit_model(LINEAR)


@pytest.fixture(scope="session")
def toy_clips():
    """Cycles of 8 toy walkers with different stride (hip amplitude) and arm swing."""
    rng = np.random.default_rng(0)
    cycles, keys, ids = [], [], []
    for s in range(8):
        m = toy_walk(
            hip_amp=rng.uniform(0.28, 0.42),
            arm_amp=rng.uniform(0.1, 0.5),
            period_s=rng.uniform(1.0, 1.2),
            height=rng.uniform(0.92, 1.08),
            twist=rng.uniform(0, 0.1),
            n_cycles=3,
        )
        for k, c in enumerate(extract_cycles(m, JM, *KEYFRAMES).cycles):
            cycles.append(cut(m, c))
            keys.append(c.key_frames)
            ids.append(f"s{s}_c{k}")
    sk = standard_skeleton([c.skeleton for c in cycles])
    return build_clipset(cycles, keys, sk, JM, n_frames=48, clip_ids=ids)
