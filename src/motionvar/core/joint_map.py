"""Joint map: names the semantic joints and the joint groups of a rig, so that methods
never hard-code CMU joint names (docs/design.md, Conventions).

Joint groups follow Ma et al. 2010, Fig. 4: A legs, B left arm, C right arm,
D the rest of the upper body (spine, neck, head). The root joint (the pelvis, whose
rotation tilts and turns the hips that carry both legs) goes with the legs in every
shipped map: Fig. 4 names the groups but not where the root rotation goes; Sec. 8 keeps
the legs together because foot constraints matter, and Sec. 6.3 already treats the
root's height with the legs (A). Measured: with the root in D, a xi_D two SDs from its mean
tilts the pelvis ~1 degree, drops a swinging foot below the stance foot and breaks the
stride of a synthesized walk (Fig. 6). Ma 2010's evaluations can move it back
(``motionvar.ma2010.examples.joint_groups``, config ``ma2010.model.root_group``).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from .skeleton import Skeleton

SEMANTIC_JOINTS = (
    "hips",
    "spine",
    "chest",
    "neck",
    "head",
    "left_shoulder",
    "left_elbow",
    "left_hand",
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
#: the extremities a rig may lack (a markerless rig whose arms end at the forearm, whose legs end
#: at the foot): a joint map may leave them out, and what needs them says so
OPTIONAL_JOINTS = ("left_hand", "right_hand", "left_toe", "right_toe")
REQUIRED_JOINTS = tuple(s for s in SEMANTIC_JOINTS if s not in OPTIONAL_JOINTS)
JOINT_GROUPS = ("legs", "left_arm", "right_arm", "upper_body")


@dataclass(frozen=True)
class JointMap:
    """Semantic joint name -> rig joint name, and group name -> rig joint names.

    ``groups`` partitions the rig's joints; joints not listed in any group fall into
    ``upper_body`` (so finger and end joints of a detailed rig need not be listed).
    """

    joints: dict[str, str]
    groups: dict[str, tuple[str, ...]] = field(default_factory=dict)
    #: where the map was read from (a YAML file), named in errors; "" for built-in maps
    origin: str = field(default="", compare=False)

    @property
    def lacking(self) -> tuple[str, ...]:
        """The semantic joints (of :data:`OPTIONAL_JOINTS`) the rig does not have."""
        return tuple(s for s in SEMANTIC_JOINTS if s not in self.joints)

    def has(self, *semantics: str) -> bool:
        """Whether the rig has every one of ``semantics``."""
        return all(s in self.joints for s in semantics)

    def validate(self, skeleton: Skeleton, source: str = "joint map") -> None:
        """Raise ValueError naming every missing required semantic joint or unknown rig joint."""
        missing = [s for s in REQUIRED_JOINTS if s not in self.joints]
        unknown = [f"{s}={n}" for s, n in self.joints.items() if n not in skeleton.names]
        unknown += [f"{g}:{n}" for g, ns in self.groups.items() for n in ns if n not in skeleton.names]
        bad_groups = [g for g in self.groups if g not in JOINT_GROUPS]
        problems = []
        if missing:
            problems.append(f"missing semantic joints {missing}")
        if unknown:
            problems.append(f"joints not in the skeleton {unknown}")
        if bad_groups:
            problems.append(f"unknown groups {bad_groups} (expected {list(JOINT_GROUPS)})")
        if problems:
            where = f"{source} ({self.origin})" if self.origin else source
            raise ValueError(f"{where}: " + "; ".join(problems))

    def index(self, skeleton: Skeleton, semantic: str) -> int:
        if semantic not in self.joints:
            where = f" ({self.origin})" if self.origin else ""
            raise ValueError(f"the joint map{where} has no {semantic}: the rig lacks it")
        return skeleton.index(self.joints[semantic])

    def indices(self, skeleton: Skeleton, semantics: list[str] | tuple[str, ...]) -> np.ndarray:
        return np.array([self.index(skeleton, s) for s in semantics], dtype=np.int64)

    def group_indices(self, skeleton: Skeleton) -> dict[str, np.ndarray]:
        """Group name -> sorted joint indices; unlisted joints join ``upper_body``."""
        listed = {g: set(skeleton.indices(self.groups.get(g, ()))) for g in JOINT_GROUPS}
        taken = set().union(*listed.values())
        listed["upper_body"] |= set(range(skeleton.n_joints)) - taken
        return {g: np.array(sorted(v), dtype=np.int64) for g, v in listed.items()}

    @classmethod
    def from_dict(cls, d: dict, origin: str = "") -> "JointMap":
        return cls(
            joints=dict(d["joints"]), groups={k: tuple(v) for k, v in d.get("groups", {}).items()}, origin=origin
        )


def cmu_joint_map() -> JointMap:
    """The joint map of the CMU 31-joint rig (:func:`motionvar.core.skeleton.cmu_skeleton`)."""
    joints = {
        "hips": "Hips",
        "spine": "Spine",
        "chest": "Spine1",
        "neck": "Neck1",
        "head": "Head",
        "left_shoulder": "LeftArm",
        "left_elbow": "LeftForeArm",
        "left_hand": "LeftHand",
        "right_shoulder": "RightArm",
        "right_elbow": "RightForeArm",
        "right_hand": "RightHand",
        "left_hip": "LeftUpLeg",
        "left_knee": "LeftLeg",
        "left_ankle": "LeftFoot",
        "left_toe": "LeftToeBase",
        "right_hip": "RightUpLeg",
        "right_knee": "RightLeg",
        "right_ankle": "RightFoot",
        "right_toe": "RightToeBase",
    }
    groups = {
        "legs": (
            "Hips",
            "LHipJoint",
            "LeftUpLeg",
            "LeftLeg",
            "LeftFoot",
            "LeftToeBase",
            "RHipJoint",
            "RightUpLeg",
            "RightLeg",
            "RightFoot",
            "RightToeBase",
        ),
        "left_arm": (
            "LeftShoulder",
            "LeftArm",
            "LeftForeArm",
            "LeftHand",
            "LeftFingerBase",
            "LeftHandIndex1",
            "LThumb",
        ),
        "right_arm": (
            "RightShoulder",
            "RightArm",
            "RightForeArm",
            "RightHand",
            "RightFingerBase",
            "RightHandIndex1",
            "RThumb",
        ),
        "upper_body": ("LowerBack", "Spine", "Spine1", "Neck", "Neck1", "Head"),
    }
    return JointMap(joints=joints, groups=groups)
