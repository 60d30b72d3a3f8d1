"""Capture-level motion: the small rotations captured data carries on channels the generator
holds constant (docs/gait.md, "Capture-level motion").

Skin-marker capture moves every channel its rig animates: soft-tissue artefact and joint
laxity give spurious off-axis rotations of several degrees at hinge joints (Cappozzo et al.
1996; Leardini et al. 2005; at the knee in walking, average rotational errors up to 4.4°,
Benoit et al. 2006). The generator instead holds about half its channels exactly constant.
:func:`add_capture_motion` adds to a clip a smooth zero-mean rotation per channel of
:data:`CAPTURE_CHANNELS`: Gaussian noise low-pass filtered at :data:`CORNER_HZ`, scaled to a
stated SD in degrees. STA has the frequency content of the movement itself (Leardini et al.
2005), hence low-pass, not white per frame.

Ground truth is kept exactly: the knee turns about its own bone to the ankle and the ankle
takes the inverse turn, so the ankle, the foot's global pose and everything below it stay as
generated; the toe base's children are end sites only; in :data:`GRIP_BEHAVIOURS` no joint
on the path to a hand (:data:`GRIP_JOINTS`) is touched, so the hands reach their grips.
The root, hip joints, collars and index fingers (held still by captured data,
:data:`motionvar.realism.bands.CMU_CAPTURED_CHANNELS`) are never touched.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from ..core.motion import Motion
from ..core.quaternions import qinv, qmul, quat_about_axis, rotvec_to_quat
from ..core.reroot import ancestors
from ..core.skeleton import Skeleton
from .signals import colored_noise

STREAM_TAG = 7
"""Last entry of a clip's capture stream ``[seed, subject, behaviour, clip, STREAM_TAG]``."""

CORNER_HZ = 2.0
"""Corner of the noise's low-pass (authors' choice: STA follows the movement, Leardini et al.
2005; a walking stride takes about 1 s)."""
FILTER_ORDER = 4
"""Order of the low-pass (:func:`~motionvar.synth.signals.colored_noise`); at 8 Hz the gain is
1/257, so nothing reaches the 8-14 Hz capture-noise band of the realism table."""

KNEE_TWIST_SD_DEG = 1.5
"""Knee axial (internal/external) rotation: authors' choice, below the average rotational
errors of skin markers at the knee in walking (up to 4.4°, Benoit et al. 2006; internal/external
errors 63 % of their range in running, Reinschmidt et al. 1997)."""
TOE_SD_DEG = 1.0
"""Toe base flexion and abduction: authors' choice (1° moves the toe's end site about 1 mm)."""
NECK_SD_DEG = 1.0
"""Neck and upper neck: authors' choice, below the 1.0-1.9° SD of the neck channels in CMU's
own captured walks 02_01, 02_03, 09_01 (which hold the real motion too)."""
FOREARM_SD_DEG = 1.5
"""Elbow's third (carrying-angle) channel: authors' choice, a laxity-sized off-axis rotation
of a hinge (Leardini et al. 2005)."""
HAND_SD_DEG = 1.0
"""Wrist's first channel, finger bases and thumbs: authors' choice, below the 1-3° SD that CMU's
own captured walks show on the finger bases and thumbs."""


@dataclass(frozen=True)
class CaptureChannels:
    """Joints given capture motion with SD ``sd_deg`` on each of ``axes``: local axes "x", "y",
    "z" (any of them), or "bone": about the bone to the joint's only child, undone at that child
    so that the child and everything below it keep their global pose."""

    joints: tuple[str, ...]
    axes: str
    sd_deg: float


CAPTURE_CHANNELS: tuple[CaptureChannels, ...] = (
    CaptureChannels(("LeftLeg", "RightLeg"), "bone", KNEE_TWIST_SD_DEG),
    CaptureChannels(("LeftToeBase", "RightToeBase"), "xy", TOE_SD_DEG),
    CaptureChannels(("Neck",), "xyz", NECK_SD_DEG),
    CaptureChannels(("Neck1",), "z", NECK_SD_DEG),
    CaptureChannels(("LeftForeArm", "RightForeArm"), "z", FOREARM_SD_DEG),
    CaptureChannels(("LeftHand", "RightHand"), "x", HAND_SD_DEG),
    CaptureChannels(("LeftFingerBase", "RightFingerBase", "LThumb", "RThumb"), "xyz", HAND_SD_DEG),
)
GRIP_BEHAVIOURS = ("pick", "place")
"""Behaviours whose hands must reach their grips exactly (``synth.reach``)."""
GRIP_JOINTS = ("LeftHand", "RightHand")


def capture_rng(seed: int, subject: int, behaviour: int, clip: int) -> np.random.Generator:
    """The capture stream of one clip, apart from every draw of the generator itself."""
    return np.random.default_rng([seed, subject, behaviour, clip, STREAM_TAG])


def _n_channels(group: CaptureChannels) -> int:
    return len(group.joints) * (1 if group.axes == "bone" else len(group.axes))


def _grip_path(skeleton: Skeleton) -> set[int]:
    """Joints whose rotation moves a grip joint (its proper ancestors)."""
    return {a for name in GRIP_JOINTS for a in ancestors(skeleton, skeleton.index(name))}


def _axis_turn(axes: str, angles: np.ndarray) -> np.ndarray:
    """(T, 4) rotations with rotation vector ``angles`` (T, len(axes)) on the named local axes."""
    rotvec = np.zeros((len(angles), 3))
    rotvec[:, ["xyz".index(a) for a in axes]] = angles
    return rotvec_to_quat(rotvec)


def _bone_child(skeleton: Skeleton, j: int) -> int:
    children = skeleton.children(j)
    if len(children) != 1:
        raise ValueError(f"capture: a bone twist needs one child of {skeleton.names[j]}; got {len(children)}")
    return children[0]


def capture_offsets(motion: Motion, behaviour: str, rng: np.random.Generator) -> dict[str, np.ndarray]:
    """Joint name -> (T, 4) local rotation to multiply on the right of that joint's rotation
    (the inverse twists of the bone children on the left; see :func:`add_capture_motion`).

    Every channel's noise is drawn, in :data:`CAPTURE_CHANNELS` order, whatever the behaviour."""
    sk, n = motion.skeleton, motion.n_frames
    total = sum(_n_channels(g) for g in CAPTURE_CHANNELS)
    noise = colored_noise(n, motion.fps, CORNER_HZ, rng, channels=total, order=FILTER_ORDER)
    skip = _grip_path(sk) if behaviour in GRIP_BEHAVIOURS else set()
    out: dict[str, np.ndarray] = {}
    col = 0
    for group in CAPTURE_CHANNELS:
        width = 1 if group.axes == "bone" else len(group.axes)
        for name in group.joints:
            angles = np.radians(group.sd_deg) * noise[:, col : col + width]
            col += width
            j = sk.index(name)
            if j in skip:
                continue
            if group.axes == "bone":
                out[name] = quat_about_axis(sk.offsets[_bone_child(sk, j)], angles[:, 0])
            else:
                out[name] = _axis_turn(group.axes, angles)
    return out


def add_capture_motion(motion: Motion, behaviour: str, rng: np.random.Generator) -> Motion:
    """Copy of ``motion`` with capture-level motion on :data:`CAPTURE_CHANNELS` (module docstring).

    A joint's local rotation L becomes L·C (C from :func:`capture_offsets`); for a "bone" group
    C turns about the bone to the child, which fixes the child's position, and the child's
    rotation becomes C⁻¹·L_child, which keeps its global rotation."""
    if motion.n_frames < 2:
        return motion.copy()
    sk = motion.skeleton
    bones = {n for g in CAPTURE_CHANNELS if g.axes == "bone" for n in g.joints}
    rot = motion.rotations.copy()
    for name, turn in capture_offsets(motion, behaviour, rng).items():
        j = sk.index(name)
        rot[:, j] = qmul(rot[:, j], turn)
        if name in bones:
            c = _bone_child(sk, j)
            rot[:, c] = qmul(qinv(turn), rot[:, c])
    return replace(motion.copy(), rotations=rot)
