"""Toy data and tiny settings of the Du 2022 ch. 5 tests: a curving walk on the CMU rig and
the settings of the tiny training runs."""

import numpy as np

from motionvar.core import Motion, cmu_skeleton
from motionvar.core import quaternions as Q
from motionvar.du2022.style import AutoencoderSettings, CvaeSettings, StyleSettings, VaeSettings


def toy_walk(n_frames=60, seed=0, turn=0.4, speed=2.0, swing=0.5, arm=0.3):
    """A clip on the CMU rig: the root moves along a curving path while turning to
    face along it, legs and arms swing sinusoidally."""
    rng = np.random.default_rng(seed)
    sk = cmu_skeleton()
    t = np.linspace(0, 1, n_frames)
    heading = turn * t + rng.normal(0, 0.05)  # world yaw of the +z facing body
    step = speed * np.stack([np.sin(heading), np.zeros_like(t), np.cos(heading)], -1)
    root = np.cumsum(step, axis=0) + np.array([3.0, 95.0, -2.0])
    rot = np.tile(np.array([1.0, 0, 0, 0]), (n_frames, sk.n_joints, 1))
    rot[:, 0] = Q.quat_about_axis([0, 1, 0], heading)
    phase = 2 * np.pi * t + rng.uniform(0, 0.3)
    for name, amp in [("LeftUpLeg", swing), ("RightUpLeg", -swing), ("LeftArm", -arm), ("RightArm", arm)]:
        rot[:, sk.index(name)] = Q.quat_about_axis([1, 0, 0], amp * np.sin(phase))
    rot[:, sk.index("LeftLeg")] = Q.quat_about_axis([1, 0, 0], 0.3 + 0.3 * np.sin(phase))
    return Motion(skeleton=sk, root_pos=root, rotations=rot, fps=120.0)


TINY_HIDDEN = (32, 16, 8)  # the VAEs' hidden layers in the tiny runs


def tiny_settings(ae_epochs=3, vae_epochs=3, cvae_epochs=2):
    """The settings of the tiny runs: 8 windows every 5 frames, 16 kernels, 4 latent
    dimensions, L = 2, Adam, alpha 1."""
    return StyleSettings(
        autoencoder=AutoencoderSettings(
            kernels=16, window_stride=5, max_windows=8, epochs=ae_epochs, lr=3e-3, batch_size=8
        ),
        vae=VaeSettings(latent=4, samples_per_input=2, epochs=vae_epochs, lr=1e-3, batch_size=4, optimizer="adam"),
        cvae=CvaeSettings(alpha=1.0, epochs=cvae_epochs, lr=1e-3, batch_size=4, optimizer="adam"),
    )
