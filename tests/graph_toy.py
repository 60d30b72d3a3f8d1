"""Small procedural clips for the Morphable Graph tests: a CMU body facing +x that swings
its legs and arms with per-clip amplitudes and moves forward, clips of 40-60 frames."""

from __future__ import annotations

import numpy as np

from motionvar.core.motion import Motion
from motionvar.core.quaternions import qidentity, quat_about_axis
from motionvar.core.skeleton import cmu_skeleton
from motionvar.du2022.graph import PrimitiveOptions

#: the options of the tests' small primitives: 8 B-splines, 5 components, no SFPCA iterations
OPT = PrimitiveOptions(n_basis=8, n_components=5, gmm_components=(1, 3), sfpca_max_iter=0)


def toy_clips(n: int = 16, seed: int = 0) -> list[Motion]:
    rng = np.random.default_rng(seed)
    sk = cmu_skeleton()
    J = sk.n_joints
    out = []
    for _ in range(n):
        T = int(rng.integers(40, 60))
        t = np.linspace(0.0, 1.0, T)
        a, b = rng.uniform(0.3, 0.8), rng.uniform(-0.3, 0.3)
        rot = qidentity((T, J))
        rot[:, 0] = quat_about_axis(np.array([0.0, 1.0, 0.0]), np.pi / 2)  # face +x (aligned)
        for name, amp, ax in (
            ("LeftUpLeg", a, (1, 0, 0)),
            ("RightUpLeg", -a, (1, 0, 0)),
            ("LeftArm", b, (0, 0, 1)),
            ("RightForeArm", a * b, (0, 1, 0)),
            ("Spine", 0.2 * b, (1, 0, 0)),
        ):
            rot[:, sk.index(name)] = quat_about_axis(np.array(ax, float), amp * np.sin(np.pi * t**1.3))
        root = np.stack([100 * a * t, 90 + 2 * np.sin(2 * np.pi * t), np.zeros(T)], -1)
        out.append(Motion(skeleton=sk, root_pos=root, rotations=rot, fps=120.0))
    return out
