"""Skeleton: joint names, parent indices, rest offsets (cm), and BVH channel layout.

The default is the CMU 31-joint hierarchy of the cgspeed BVH conversion of the CMU
Graphics Lab Motion Capture Database, with offsets of subject 02 converted to cm
(CMU BVH units are 1/0.45 inch = 5.644 cm).
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np

CMU_UNIT_CM = 2.54 / 0.45
"""Centimetres per CMU BVH length unit (the ASF ``length 0.45`` convention)."""

# (name, parent name, offset in CMU units) for the 31 joints of the cgspeed conversion.
_CMU_JOINTS: tuple[tuple[str, str | None, tuple[float, float, float]], ...] = (
    ("Hips", None, (0.0, 0.0, 0.0)),
    ("LHipJoint", "Hips", (0.0, 0.0, 0.0)),
    ("LeftUpLeg", "LHipJoint", (1.65674, -1.80282, 0.62477)),
    ("LeftLeg", "LeftUpLeg", (2.59720, -7.13576, 0.0)),
    ("LeftFoot", "LeftLeg", (2.49236, -6.84770, 0.0)),
    ("LeftToeBase", "LeftFoot", (0.19704, -0.54136, 2.14581)),
    ("RHipJoint", "Hips", (0.0, 0.0, 0.0)),
    ("RightUpLeg", "RHipJoint", (-1.61070, -1.80282, 0.62476)),
    ("RightLeg", "RightUpLeg", (-2.59502, -7.12977, 0.0)),
    ("RightFoot", "RightLeg", (-2.46780, -6.78024, 0.0)),
    ("RightToeBase", "RightFoot", (-0.23024, -0.63258, 2.13368)),
    ("LowerBack", "Hips", (0.0, 0.0, 0.0)),
    ("Spine", "LowerBack", (0.01961, 2.05450, -0.14112)),
    ("Spine1", "Spine", (0.01021, 2.06436, -0.05921)),
    ("Neck", "Spine1", (0.0, 0.0, 0.0)),
    ("Neck1", "Neck", (0.00713, 1.56711, 0.14968)),
    ("Head", "Neck1", (0.03429, 1.56041, -0.10006)),
    ("LeftShoulder", "Spine1", (0.0, 0.0, 0.0)),
    ("LeftArm", "LeftShoulder", (3.54205, 0.90436, -0.17364)),
    ("LeftForeArm", "LeftArm", (4.86513, 0.0, 0.0)),
    ("LeftHand", "LeftForeArm", (3.35554, 0.0, 0.0)),
    ("LeftFingerBase", "LeftHand", (0.0, 0.0, 0.0)),
    ("LeftHandIndex1", "LeftFingerBase", (0.66117, 0.0, 0.0)),
    ("LThumb", "LeftFingerBase", (0.0, 0.0, 0.0)),
    ("RightShoulder", "Spine1", (0.0, 0.0, 0.0)),
    ("RightArm", "RightShoulder", (-3.49802, 0.75994, -0.32616)),
    ("RightForeArm", "RightArm", (-5.02649, 0.0, 0.0)),
    ("RightHand", "RightForeArm", (-3.36431, 0.0, 0.0)),
    ("RightFingerBase", "RightHand", (0.0, 0.0, 0.0)),
    ("RightHandIndex1", "RightFingerBase", (-0.73041, 0.0, 0.0)),
    ("RThumb", "RightFingerBase", (0.0, 0.0, 0.0)),
)
_CMU_END_SITES: dict[str, tuple[float, float, float]] = {
    "LeftToeBase": (0.0, 0.0, 1.11249),
    "RightToeBase": (0.0, 0.0, 1.11569),
    "Head": (0.01305, 1.62560, -0.05265),
    "LeftHandIndex1": (0.53306, 0.0, 0.0),
    "LThumb": (0.54120, 0.0, 0.54120),
    "RightHandIndex1": (-0.58887, 0.0, 0.0),
    "RThumb": (-0.59786, 0.0, 0.59786),
}


@dataclass(frozen=True)
class Skeleton:
    """A joint hierarchy in rest pose.

    Attributes:
        names: joint names, parents before children.
        parents: (J,) parent index per joint, -1 for the root.
        offsets: (J, 3) rest offset of each joint from its parent, in cm.
        end_sites: joint index -> (3,) offset of its BVH End Site, in cm.
        rotation_orders: per joint, the BVH rotation channel order, e.g. "ZYX"
            (intrinsic, as scipy reads uppercase axes).
        position_channels: per joint, whether its BVH channels include positions.
    """

    names: tuple[str, ...]
    parents: np.ndarray
    offsets: np.ndarray
    end_sites: dict[int, np.ndarray] = field(default_factory=dict)
    rotation_orders: tuple[str, ...] | None = None
    position_channels: tuple[bool, ...] | None = None

    def __post_init__(self) -> None:
        parents = np.asarray(self.parents, dtype=np.int64)
        offsets = np.asarray(self.offsets, dtype=float)
        n = len(self.names)
        if parents.shape != (n,) or offsets.shape != (n, 3):
            raise ValueError(
                f"Skeleton: {n} names need parents of shape ({n},) and offsets ({n}, 3); "
                f"got {parents.shape} and {offsets.shape}"
            )
        if n == 0 or parents[0] != -1 or np.any(parents[1:] >= np.arange(1, n)) or np.any(parents[1:] < 0):
            raise ValueError("Skeleton: joint 0 must be the root and every parent must precede its child")
        object.__setattr__(self, "parents", parents)
        object.__setattr__(self, "offsets", offsets)
        if self.rotation_orders is None:
            object.__setattr__(self, "rotation_orders", ("ZYX",) * n)
        if self.position_channels is None:
            object.__setattr__(self, "position_channels", (True,) + (False,) * (n - 1))

    @property
    def n_joints(self) -> int:
        return len(self.names)

    def index(self, name: str) -> int:
        """Index of joint ``name``; KeyError naming the known joints otherwise."""
        try:
            return self.names.index(name)
        except ValueError:
            raise KeyError(f"joint {name!r} not in skeleton ({', '.join(self.names)})") from None

    def indices(self, names: list[str] | tuple[str, ...]) -> np.ndarray:
        return np.array([self.index(n) for n in names], dtype=np.int64)

    def children(self, j: int) -> list[int]:
        return [int(c) for c in np.flatnonzero(self.parents == j)]

    def bone_lengths(self) -> np.ndarray:
        """(J,) length of the offset of each joint from its parent (cm)."""
        return np.linalg.norm(self.offsets, axis=-1)

    def scaled(self, scale: np.ndarray | float) -> "Skeleton":
        """Copy with offsets (and end sites) multiplied by a scalar or a per-joint (J,) or
        (J, 3) factor: the per-subject bone scaling of the synthetic subjects."""
        scale = np.asarray(scale, dtype=float)
        per_joint = scale if scale.ndim == 0 else (scale[:, None] if scale.ndim == 1 else scale)
        end = {j: o * (per_joint if per_joint.ndim == 0 else per_joint[j]) for j, o in self.end_sites.items()}
        return replace(self, offsets=self.offsets * per_joint, end_sites=end)

    def with_offsets(self, offsets: np.ndarray) -> "Skeleton":
        """Same topology and channel layout, other rest offsets."""
        return replace(self, offsets=np.asarray(offsets, dtype=float))

    def same_topology(self, other: "Skeleton") -> bool:
        return self.names == other.names and np.array_equal(self.parents, other.parents)


def cmu_skeleton(straight_legs: bool = True) -> Skeleton:
    """The CMU 31-joint skeleton (subject 02 proportions) in cm, channel order ZYX.

    The body faces +z, its left side is +x, y is up. The cgspeed conversion's rest pose
    splays thigh and shin 20 degrees outwards; with ``straight_legs`` (the default, used
    by the synthetic generator) those two bones point straight down with the same
    lengths, so that zero rotations are an anatomically neutral standing pose.
    ``straight_legs=False`` gives the offsets exactly as in the CMU BVH files.
    """
    names = tuple(j[0] for j in _CMU_JOINTS)
    parents = np.array([-1 if p is None else names.index(p) for _, p, _ in _CMU_JOINTS])
    offsets = np.array([o for _, _, o in _CMU_JOINTS]) * CMU_UNIT_CM
    if straight_legs:
        for name in ("LeftLeg", "LeftFoot", "RightLeg", "RightFoot"):
            j = names.index(name)
            offsets[j] = [0.0, -np.linalg.norm(offsets[j]), 0.0]
    end_sites = {names.index(k): np.array(v) * CMU_UNIT_CM for k, v in _CMU_END_SITES.items()}
    return Skeleton(names=names, parents=parents, offsets=offsets, end_sites=end_sites)
