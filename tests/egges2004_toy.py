"""Small idle-like recordings for the Egges 2004 tests: weight shifts between resting on
the left foot, the right foot and both, with breathing-like small variations; and a
packed dataset of them with the true resting postures."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd

from motionvar.core import Motion, cmu_skeleton
from motionvar.core.quaternions import qidentity, quat_about_axis
from motionvar.io import save_dataset

SHIFT_CM = {"left": 4.0, "both": 0.0, "right": -4.0}  # the pelvis moves over the loaded foot (+x is left)


def toy_recording(
    sequence: list[str],
    rest_s: list[float],
    seed: int = 0,
    fps: float = 30.0,
    shift_s: float = 1.0,
    lean: float = 0.0,
) -> tuple[Motion, list[tuple[str, int, int]]]:
    """A clip resting in each category of ``sequence`` for the given times, joined by
    minimum-jerk shifts of ``shift_s`` seconds; returns the motion and the true rests."""
    rng = np.random.default_rng(seed)
    sk = cmu_skeleton()
    xs, truth, t0 = [], [], 0
    for k, (name, rest) in enumerate(zip(sequence, rest_s)):
        n = int(round(rest * fps))
        xs.append(np.full(n, SHIFT_CM[name]))
        truth.append((name, t0, t0 + n))
        t0 += n
        if k + 1 < len(sequence):
            m = int(round(shift_s * fps))
            tau = np.arange(1, m + 1) / (m + 1)
            s = 10 * tau**3 - 15 * tau**4 + 6 * tau**5
            xs.append(SHIFT_CM[name] + (SHIFT_CM[sequence[k + 1]] - SHIFT_CM[name]) * s)
            t0 += m
    x = np.concatenate(xs)
    T = len(x)
    t = np.arange(T) / fps
    breath = 0.01 * np.sin(2 * np.pi * 0.25 * t + rng.uniform(0, 6)) + 0.003 * rng.standard_normal(
        T
    ).cumsum() / np.sqrt(T)
    sway = 0.3 * np.sin(2 * np.pi * 0.4 * t + rng.uniform(0, 6))
    x = x + sway
    rot = qidentity((T, sk.n_joints))
    leg = 2 * abs(sk.offsets[sk.index("LeftLeg"), 1]) + abs(sk.offsets[sk.index("LeftFoot"), 1])
    theta = -np.arcsin(x / leg)  # the legs lean so the feet stay planted
    for hip in ("LeftUpLeg", "RightUpLeg"):
        rot[:, sk.index(hip)] = quat_about_axis([0, 0, 1], theta)
    rot[:, sk.index("Spine")] = quat_about_axis([1, 0, 0], breath + lean)
    rot[:, sk.index("Neck1")] = quat_about_axis([1, 0, 0], 0.5 * breath)
    root = np.stack([x, np.full(T, 90.0), np.zeros(T)], axis=1)
    return Motion(skeleton=sk, root_pos=root, rotations=rot, fps=fps), truth


SEQUENCES = [
    ["left", "both", "right", "left", "both", "right"],
    ["right", "left", "both", "left", "right", "both"],
    ["both", "right", "left", "both", "left", "right"],
]


def toy_dataset(folder: Path, subjects: int = 3, clips: int = 3) -> Path:
    """A packed dataset of idle clips ``idle_<s>_<c>`` of subjects 01, 02, ..., each
    resting six times (3-5 s) with its true postures in ``idle_postures``."""
    motions, rows = [], []
    for s in range(subjects):
        for c in range(clips):
            rest = list(np.random.default_rng(10 * s + c).uniform(3.0, 5.0, 6))
            m, truth = toy_recording(SEQUENCES[(s + c) % 3], rest, seed=10 * s + c, lean=0.05 * s)
            motions.append(m)
            postures = ";".join(f"{n}:{a}:{b}" for n, a, b in truth)
            rows.append(
                {"clip_id": f"idle_{s}_{c}", "subject": f"{s + 1:02d}", "behaviour": "idle", "idle_postures": postures}
            )
    save_dataset(folder, motions, pd.DataFrame(rows))
    return folder


#: the toy recordings' sequence of stances and their rest lengths (s)
SEQ = ["left", "both", "right", "both", "left", "right", "left"]
RESTS = [4, 3, 5, 3, 6, 4, 3]
