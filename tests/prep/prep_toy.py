"""Toy motions of the preprocessing tests: a CMU body standing, stepping on given intervals,
turned, and on a renamed rig."""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from motionvar.core import JointMap, Motion, Skeleton, cmu_joint_map, cmu_skeleton
from motionvar.core import quaternions as Q
from motionvar.prep import facing_directions

FPS = 120.0
JM = cmu_joint_map()


def standing(n_frames: int, fps: float = FPS, skeleton: Skeleton | None = None) -> Motion:
    """A CMU body standing still with zero rotations, its lowest foot joint on the floor."""
    sk = skeleton or cmu_skeleton()
    m = Motion(sk, np.zeros((n_frames, 3)), Q.qidentity((n_frames, sk.n_joints)), fps)
    pos = m.positions()[:1]
    feet = JM.indices(cmu_skeleton(), ["left_ankle", "left_toe", "right_ankle", "right_toe"])
    m.root_pos[:, 1] = -pos[0, feet, 1].min()
    return m


def bump(t: np.ndarray, a: float, b: float) -> np.ndarray:
    """sin^2 bump rising from 0 at time a to 1 and back to 0 at time b (seconds)."""
    u = np.clip((t - a) / (b - a), 0.0, 1.0)
    return np.sin(np.pi * u) ** 2


def stepping(steps: list[tuple[str, float, float]], duration: float, fps: float = FPS, deg: float = 35.0) -> Motion:
    """Stepping in place: each (side, a, b) lifts that leg by hip flexion from a to b seconds
    (the foot leaves the floor after a and lands again at b), the root stays put."""
    n = int(round(duration * fps)) + 1
    m = standing(n, fps)
    t = np.arange(n) / fps
    for side, a, b in steps:
        j = JM.index(m.skeleton, f"{side}_hip")
        angle = np.radians(deg) * bump(t, a, b)
        m.rotations[:, j] = Q.qmul(m.rotations[:, j], Q.quat_about_axis([1.0, 0.0, 0.0], -angle))
    return m


def turned(m: Motion, yaw: float, shift: tuple[float, float]) -> Motion:
    """``m`` rotated by ``yaw`` about +y and moved by ``shift`` (x, z) on the floor."""
    q = Q.quat_about_axis([0.0, 1.0, 0.0], yaw)
    rot = m.rotations.copy()
    rot[:, 0] = Q.qmul(q, rot[:, 0])
    root = Q.qrot(q, m.root_pos) + np.array([shift[0], 0.0, shift[1]])
    return replace(m, root_pos=root, rotations=rot)


def renamed_rig(m: Motion) -> tuple[Motion, JointMap]:
    """The same clip on a rig whose joints have other names, and that rig's joint map."""
    names = tuple(f"j{k}_{n.lower()}" for k, n in enumerate(m.skeleton.names))
    rename = dict(zip(m.skeleton.names, names))
    sk = replace(m.skeleton, names=names)
    jm = JointMap(
        joints={s: rename[n] for s, n in JM.joints.items()},
        groups={g: tuple(rename[n] for n in ns) for g, ns in JM.groups.items()},
    )
    return replace(m, skeleton=sk), jm


WALK_STEPS = [("right", 0.2, 0.6), ("left", 0.7, 1.1), ("right", 1.2, 1.6), ("left", 1.7, 2.1)]


def facing_heading(m: Motion) -> np.ndarray:
    lh, rh = JM.indices(m.skeleton, ["left_hip", "right_hip"])
    f = facing_directions(m.positions()[0], lh, rh)
    return f / np.linalg.norm(f)
