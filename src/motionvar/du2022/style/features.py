"""Motion features of Du 2022 Sec. 5.2: per frame, the 3-D positions of 21 joints in the
body's local frame plus the ground velocity of the root and its rotation velocity about
the vertical axis (3 * 21 + 3 = 66 values a frame, "each frame is represented as a vector
of length 66").

The thesis' 21 joints belong to the Makehuman game-engine rig (pelvis, three spine
joints, neck, head, and per side clavicle, upper arm, forearm, hand, thigh, calf, foot,
ball). Through the :class:`~motionvar.core.JointMap` we take the 19 semantic joints
(hips, spine, chest, neck, head; per side shoulder, elbow, hand, hip, knee, ankle, toe)
plus the rig parent of each shoulder (the clavicle), which on the CMU rig gives
Hips, Spine, Spine1, Neck1, Head, LeftShoulder, LeftArm, LeftForeArm, LeftHand,
RightShoulder, RightArm, RightForeArm, RightHand, LeftUpLeg, LeftLeg, LeftFoot,
LeftToeBase, RightUpLeg, RightLeg, RightFoot, RightToeBase (:func:`style_joints`).

"All frames are normalized in the way that they have the same global position on the
2D ground and face the same direction": each frame's positions are taken relative to
the root's ground projection and turned about +y so that the body faces +x. The body's
facing is up x (left -> right), averaged over the hips and shoulders (so that the
pelvis' counter-rotation in walking cancels). Velocities are forward differences per
frame, expressed in the frame's local coordinates; the last frame repeats the one
before. :func:`features_to_positions` integrates them back to global positions (the
inverse used to look at and measure generated motions).

Layout of the C = 3J + 3 channels: joint j's x, y, z at 3j..3j+2, then the ground
velocity (local x, local z, cm per frame) and the yaw rate (rad per frame).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from ...core.joint_map import JointMap
from ...core.motion import Motion
from ...core.skeleton import Skeleton

# The joint map's semantic joints in the order of the feature channels; the clavicles
# (rig parents of the shoulders) are inserted before each shoulder.
_ORDER = (
    "hips",
    "spine",
    "chest",
    "neck",
    "head",
    "left_clavicle",
    "left_shoulder",
    "left_elbow",
    "left_hand",
    "right_clavicle",
    "right_shoulder",
    "right_elbow",
    "right_hand",
    "left_hip",
    "left_knee",
    "left_ankle",
    "left_toe",
    "right_hip",
    "right_knee",
    "right_ankle",
    "right_toe",
)
#: the semantic joints the features need from a joint map (hands and toes among them)
FEATURE_JOINTS = tuple(s for s in _ORDER if not s.endswith("clavicle"))
N_ROOT_CHANNELS = 3


@dataclass(frozen=True)
class FeatureLayout:
    """Which rig joints the features hold and their tree, for drawing and measuring.

    Attributes:
        joints: (J,) rig joint indices, in channel order.
        names: (J,) rig joint names.
        parents: (J,) parent of each feature joint within the feature joints (-1: root);
            the nearest selected ancestor in the rig.
        left, right: indices (into ``joints``) of the left/right hip and shoulder, used
            for the facing direction.
    """

    joints: np.ndarray
    names: tuple[str, ...]
    parents: np.ndarray
    left: np.ndarray
    right: np.ndarray

    @property
    def n_joints(self) -> int:
        return len(self.joints)

    @property
    def n_channels(self) -> int:
        return 3 * self.n_joints + N_ROOT_CHANNELS


def style_joints(skeleton: Skeleton, joint_map: JointMap) -> FeatureLayout:
    """The feature joints of Sec. 5.2 (21 on the CMU rig; see the module docstring).

    A clavicle is the rig parent of the mapped shoulder; where that parent is already
    a selected joint (a rig without clavicles), it is not repeated, so such rigs get
    fewer than 21 joints. Raises ValueError naming missing semantic joints.
    """
    missing = [s for s in FEATURE_JOINTS if s not in joint_map.joints]
    if missing:
        raise ValueError(f"style features: the joint map lacks semantic joints {missing}")
    picked: list[int] = []
    for s in _ORDER:
        if s.endswith("clavicle"):
            j = int(skeleton.parents[joint_map.index(skeleton, s.replace("clavicle", "shoulder"))])
        else:
            j = joint_map.index(skeleton, s)
        if j >= 0 and j not in picked:
            picked.append(j)
    root = joint_map.index(skeleton, "hips")
    if picked[0] != root or skeleton.parents[root] != -1:
        raise ValueError("style features: the joint map's hips must be the rig's root joint")
    # parent within the selection: nearest selected ancestor
    sel = {j: k for k, j in enumerate(picked)}
    parents = np.full(len(picked), -1, dtype=np.int64)
    for k, j in enumerate(picked[1:], start=1):
        p = int(skeleton.parents[j])
        while p >= 0 and p not in sel:
            p = int(skeleton.parents[p])
        parents[k] = sel.get(p, 0)
    # the tree must list parents before children for drawing; the order above does
    if np.any(parents[1:] >= np.arange(1, len(picked))):
        raise ValueError("style features: the selected joints are not ordered parents first")
    left = np.array([sel[joint_map.index(skeleton, s)] for s in ("left_hip", "left_shoulder")])
    right = np.array([sel[joint_map.index(skeleton, s)] for s in ("right_hip", "right_shoulder")])
    return FeatureLayout(
        joints=np.array(picked, dtype=np.int64),
        names=tuple(skeleton.names[j] for j in picked),
        parents=parents,
        left=left,
        right=right,
    )


def _rotate_y(v: np.ndarray, angle: np.ndarray) -> np.ndarray:
    """Rotate vectors (..., 3) about +y by ``angle`` (...): x' = x cos + z sin,
    z' = -x sin + z cos (turns direction (cos a, 0, sin a) onto +x)."""
    c, s = np.cos(angle)[..., None], np.sin(angle)[..., None]
    x, y, z = v[..., 0:1], v[..., 1:2], v[..., 2:3]
    return np.concatenate([x * c + z * s, y, -x * s + z * c], axis=-1)


def heading_angles(positions: np.ndarray, layout: FeatureLayout) -> np.ndarray:
    """(..., T) yaw angles that turn each frame's facing onto +x; positions (..., T, J, 3)
    of the feature joints."""
    across = (positions[..., layout.right, :] - positions[..., layout.left, :]).sum(axis=-2)
    facing_x, facing_z = across[..., 2], -across[..., 0]  # up x across, on the floor
    if np.any(np.hypot(facing_x, facing_z) < 1e-9):
        raise ValueError("style features: facing direction undefined (left and right joints coincide)")
    return np.arctan2(facing_z, facing_x)


def _wrap(a: np.ndarray) -> np.ndarray:
    return (a + np.pi) % (2 * np.pi) - np.pi


def positions_to_features(positions: np.ndarray, layout: FeatureLayout) -> np.ndarray:
    """Features (..., T, 3J + 3) of global feature-joint positions (..., T, J, 3), T >= 2."""
    positions = np.asarray(positions, dtype=float)
    if positions.ndim < 3 or positions.shape[-2:] != (layout.n_joints, 3):
        raise ValueError(f"style features: positions must be (..., T, {layout.n_joints}, 3); got {positions.shape}")
    if positions.shape[-3] < 2:
        raise ValueError(f"style features: need at least 2 frames; got {positions.shape[-3]}")
    theta = heading_angles(positions, layout)
    ground = positions[..., 0, :].copy()
    ground[..., 1] = 0.0
    local = _rotate_y(positions - ground[..., None, :], theta[..., None])
    step = np.diff(ground, axis=-2)
    vel = _rotate_y(step, theta[..., :-1])
    yaw = _wrap(np.diff(theta, axis=-1))
    vel = np.concatenate([vel, vel[..., -1:, :]], axis=-2)
    yaw = np.concatenate([yaw, yaw[..., -1:]], axis=-1)
    flat = local.reshape(*local.shape[:-2], -1)
    return np.concatenate([flat, vel[..., [0, 2]], yaw[..., None]], axis=-1)


def motion_features(motion: Motion, layout: FeatureLayout) -> np.ndarray:
    """(T, 3J + 3) features of one clip (one vectorised FK over its frames)."""
    return positions_to_features(motion.positions()[:, layout.joints], layout)


def motions_features(motions: Sequence[Motion], layout: FeatureLayout) -> np.ndarray:
    """(N, T, 3J + 3) features of clips that all have T frames (e.g. resampled to the
    canonical 60); ValueError naming the first clip of another length."""
    if len(motions) == 0:
        raise ValueError("style features: no clips given")
    T = motions[0].n_frames
    for i, m in enumerate(motions):
        if m.n_frames != T:
            raise ValueError(f"style features: clip {i} has {m.n_frames} frames, clip 0 has {T}; resample first")
    return np.stack([motion_features(m, layout) for m in motions])


def features_to_positions(features: np.ndarray, layout: FeatureLayout, start_heading: float = 0.0) -> np.ndarray:
    """Global positions (..., T, J, 3) from features (..., T, 3J + 3): the root starts
    above the origin with heading ``start_heading`` (0: facing +x) and moves by the
    integrated ground velocity and yaw rate (the inverse of :func:`positions_to_features`
    up to the starting place and heading)."""
    features = np.asarray(features, dtype=float)
    J = layout.n_joints
    if features.shape[-1] != layout.n_channels:
        raise ValueError(f"style features: expected {layout.n_channels} channels; got {features.shape[-1]}")
    local = features[..., : 3 * J].reshape(*features.shape[:-1], J, 3)
    vel = np.zeros(features.shape[:-1] + (3,))
    vel[..., 0], vel[..., 2] = features[..., 3 * J], features[..., 3 * J + 1]
    yaw = features[..., 3 * J + 2]
    # theta_t = theta_0 + sum_{s<t} yaw_s ; root_t = sum_{s<t} R(theta_s)^-1 vel_s
    theta = start_heading + np.concatenate([np.zeros_like(yaw[..., :1]), np.cumsum(yaw[..., :-1], axis=-1)], axis=-1)
    world_step = _rotate_y(vel, -theta)
    root = np.concatenate([np.zeros_like(world_step[..., :1, :]), np.cumsum(world_step[..., :-1, :], axis=-2)], axis=-2)
    return _rotate_y(local, -theta[..., None]) + root[..., None, :]


def split_features(features: np.ndarray, n_joints: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(local positions (..., T, J, 3), ground velocity (..., T, 2), yaw rate (..., T))."""
    J = n_joints
    local = features[..., : 3 * J].reshape(*features.shape[:-1], J, 3)
    return local, features[..., 3 * J : 3 * J + 2], features[..., 3 * J + 2]


def sliding_windows(clips: Sequence[np.ndarray], size: int, stride: int) -> np.ndarray:
    """(W, size, C) overlapping windows of per-frame features (Sec. 5.4.1: windows of 60
    frames overlapping by half). Clips shorter than ``size`` give no window."""
    if size < 1 or stride < 1:
        raise ValueError(f"sliding_windows: size and stride must be >= 1; got {size}, {stride}")
    out = []
    for x in clips:
        if len(x) < size:
            continue
        starts = np.arange(0, len(x) - size + 1, stride)
        out.append(np.lib.stride_tricks.sliding_window_view(x, size, axis=0)[starts].transpose(0, 2, 1))
    if not out:
        raise ValueError(f"sliding_windows: no clip has the {size} frames of a window")
    return np.concatenate(out).astype(np.float32)


class FeatureScaler:
    """Per-channel mean and a pooled scale per channel group, a scikit-learn-style estimator:
    ``FeatureScaler(n_joints).fit(features)``, then ``transform`` and ``inverse`` (the thesis
    does not say how features were normalised; as Holden et al. 2016, positions share one standard
    deviation so that the pose's geometry is kept, the two ground-velocity channels another, the
    yaw rate a third).

    Parameters: ``n_joints`` (the features' 3 * n_joints position channels come first), ``floor``
    (the least scale). Learned by :meth:`fit`: ``mean_`` and ``std_``, (C,) float32."""

    def __init__(self, n_joints: int, floor: float = 1e-6) -> None:
        self.n_joints, self.floor = n_joints, floor

    def fit(self, features: np.ndarray) -> FeatureScaler:
        """From features (..., C) pooled over all leading axes."""
        x = np.asarray(features, dtype=float).reshape(-1, features.shape[-1])
        mean = x.mean(axis=0)
        dev = x - mean
        n = self.n_joints
        groups = [slice(0, 3 * n), slice(3 * n, 3 * n + 2), slice(3 * n + 2, None)]
        std = np.empty_like(mean)
        for g in groups:
            std[g] = max(float(np.sqrt((dev[:, g] ** 2).mean())), self.floor)
        return self.set_fitted(mean.astype(np.float32), std.astype(np.float32))

    def set_fitted(self, mean: np.ndarray, std: np.ndarray) -> FeatureScaler:
        """Set the learned mean and scale (:meth:`fit`, or a saved model's); returns self."""
        self.mean_, self.std_ = mean, std
        return self

    def transform(self, features: np.ndarray) -> np.ndarray:
        return ((features - self.mean_) / self.std_).astype(np.float32)

    def inverse(self, scaled: np.ndarray, out: np.ndarray | None = None) -> np.ndarray:
        """Features in the data's units (float64) of scaled ones: scaled * std + mean,
        written into ``out`` (float64, scaled's shape) when given, without temporaries."""
        out = np.multiply(scaled, self.std_, out=out, dtype=np.float64)
        return np.add(out, self.mean_, out=out)
