"""Toy data of the functional data analysis tests (Du 2022 ch. 3): a joint chain, clips of a
few classes on it, and a stand-in for a packed dataset."""

import numpy as np

from motionvar.core import Motion, Skeleton
from motionvar.core.quaternions import quat_about_axis


def chain_skeleton(n_joints=5, scale=1.0):
    """A small branching rig: root, spine, head, and two arms of one joint each."""
    names = tuple(f"j{i}" for i in range(n_joints))
    parents = np.array([-1, 0, 1, 1, 1][:n_joints])
    offsets = np.array([[0, 0, 0], [0, 20, 0], [0, 25, 0], [15, 20, 0], [-15, 20, 0]][:n_joints], float) * scale
    return Skeleton(names=names, parents=parents, offsets=offsets)


def make_clips(n=60, seed=0, n_joints=5, classes=3, lengths=(30, 45)):
    """Smooth clips whose joint angles depend on a class (pose offset) and random phases."""
    rng = np.random.default_rng(seed)
    axes = rng.normal(size=(n_joints, 3))
    clips, labels = [], []
    for i in range(n):
        c = i % classes
        T = int(rng.integers(*lengths))
        t = np.linspace(0, 1, T)
        phase = rng.uniform(0, 2 * np.pi)
        angles = 0.5 * np.sin(2 * np.pi * t[:, None] + phase + np.arange(n_joints)) * rng.uniform(0.5, 1.0)
        angles += 0.6 * c * (np.arange(n_joints) % 2)[None] + 0.05 * rng.normal(size=(1, n_joints))
        q = np.stack([quat_about_axis(axes[j], angles[:, j]) for j in range(n_joints)], axis=1)
        root = np.stack([t * rng.uniform(80, 120), 90 + 2 * np.sin(4 * np.pi * t), t * 10 * rng.normal()], -1)
        sk = chain_skeleton(n_joints, rng.uniform(0.9, 1.1))
        clips.append(Motion(skeleton=sk, root_pos=root, rotations=q, fps=120.0))
        labels.append(c)
    return clips, np.array(labels)


class StandInDataset:
    """What the evaluations use of motionvar.io.MotionDataset: ``metadata`` and ``motion(i)``."""

    def __init__(self, motions, metadata):
        self.motions, self.metadata = list(motions), metadata.reset_index(drop=True)

    def motion(self, i):
        return self.motions[i]
