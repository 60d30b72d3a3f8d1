"""Motion core: skeletons, motions, quaternions, forward kinematics, joint maps."""

from .joint_map import JOINT_GROUPS, SEMANTIC_JOINTS, JointMap, cmu_joint_map
from .kinematics import fk, fk_torch
from .motion import Motion
from .skeleton import CMU_UNIT_CM, Skeleton, cmu_skeleton

__all__ = [
    "CMU_UNIT_CM", "JOINT_GROUPS", "SEMANTIC_JOINTS", "JointMap", "Motion", "Skeleton",
    "cmu_joint_map", "cmu_skeleton", "fk", "fk_torch",
]
