"""A tiny procedural walker for the Ma 2010 unit tests (not the project's generator):
sinusoidal hip swing (amplitude sets the stride), knee flexion in swing, arms hanging and
swinging (amplitude is the per-subject "variation"), root from footskate cleanup."""

from __future__ import annotations

import numpy as np
import pandas as pd
from rule_scripts import FakeSnakemake, Named

from motionvar.core import Motion, cmu_joint_map, cmu_skeleton  # noqa: F401
from motionvar.core.quaternions import qmul, quat_about_axis
from motionvar.io import save_dataset
from motionvar.ma2010.examples import root_solver


def toy_walk(
    hip_amp: float = 0.35,
    arm_amp: float = 0.3,
    period_s: float = 1.1,
    n_cycles: float = 4.0,
    height: float = 1.0,
    fps: float = 120.0,
    knee_amp: float = 1.2,
    twist: float = 0.05,
    hip_growth: float = 0.0,
) -> Motion:
    """A straight walk along +z (the rest pose faces +z). ``hip_growth``: relative growth
    of the hip swing per second (0: a steady walker, whose left- and right-support strides
    are equal, both being the distance walked per cycle; > 0: a walker lengthening its
    strides, whose right-support stride, later in the cycle, is the longer)."""
    sk = cmu_skeleton().scaled(height)
    n = int(round(n_cycles * period_s * fps)) + 1
    phi = 2 * np.pi * np.arange(n) / (period_s * fps)
    rot = np.zeros((n, sk.n_joints, 4))
    rot[..., 0] = 1.0
    x = [1.0, 0.0, 0.0]
    ix = sk.index
    swing_l, swing_r = np.maximum(np.cos(phi), 0), np.maximum(-np.cos(phi), 0)
    hip = hip_amp * (1.0 + hip_growth * np.arange(n) / fps)
    rot[:, ix("LeftUpLeg")] = quat_about_axis(x, -hip * np.sin(phi) - 0.5 * knee_amp * swing_l)
    rot[:, ix("RightUpLeg")] = quat_about_axis(x, hip * np.sin(phi) - 0.5 * knee_amp * swing_r)
    rot[:, ix("LeftLeg")] = quat_about_axis(x, knee_amp * swing_l)
    rot[:, ix("RightLeg")] = quat_about_axis(x, knee_amp * swing_r)
    down_l = quat_about_axis([0, 0, 1], np.full(n, -1.3))
    down_r = quat_about_axis([0, 0, 1], np.full(n, 1.3))
    rot[:, ix("LeftArm")] = qmul(quat_about_axis(x, arm_amp * np.sin(phi)), down_l)
    rot[:, ix("RightArm")] = qmul(quat_about_axis(x, -arm_amp * np.sin(phi)), down_r)
    rot[:, ix("LeftForeArm")] = quat_about_axis([0, 1, 0], np.full(n, 0.3 + 0.5 * arm_amp))
    rot[:, ix("RightForeArm")] = quat_about_axis([0, 1, 0], np.full(n, -0.3 - 0.5 * arm_amp))
    rot[:, ix("Spine")] = quat_about_axis([0, 1, 0], twist * np.sin(phi))
    return root_solver(sk, cmu_joint_map()).motion(rot, fps)


SETTINGS = {
    "clips": {"walk_styles": ["neutral"], "walk_variants": ["forward"], "n_frames": 24}
}  # config section ma2010


def walks_folder(folder, styles, n_cycles=3, hip_growth=0.0):
    """``folder`` holding a packed dataset of toy walkers of growing stride, one per style in
    ``styles``; with ``hip_growth``, walkers 1 and 2 of every three lengthen their strides as they
    walk by that much and twice that (a steady walker's two support strides are equal)."""
    motions = [
        toy_walk(hip_amp=0.3 + 0.03 * i, arm_amp=0.2 + 0.1 * i, n_cycles=n_cycles, hip_growth=hip_growth * (i % 3))
        for i in range(len(styles))
    ]
    meta = pd.DataFrame(
        {
            "clip_id": [f"w{i}" for i in range(len(styles))],
            "subject": [f"{i:02d}" for i in range(len(styles))],
            "behaviour": "walk",
            "style": styles,
            "variant": "forward",
        }
    )
    save_dataset(folder, motions, meta)
    return folder


def clips_fake(tmp_path, data):
    """(output folder, FakeSnakemake) of rule ma2010_clips on the packed dataset ``data``."""
    out = tmp_path / "models"
    fake = FakeSnakemake(
        tmp_path,
        "ma2010_clips",
        input=Named(clips=str(data / "clips.npz"), metadata=str(data / "metadata.csv")),
        output=Named(
            clips=str(out / "walk_clips.npz"),
            clips_settings=str(out / "walk_clips.json"),
            table=str(out / "walk_cycles.csv"),
        ),
        params=Named(settings=SETTINGS, joint_map=None),
    )
    out.mkdir()
    return out, fake
