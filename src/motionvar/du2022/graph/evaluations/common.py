"""Shared by the Du 2022 ch. 4 evaluations: semantic joints of a primitive's skeleton."""

from __future__ import annotations

from ....core.joint_map import JointMap
from ....core.skeleton import Skeleton


def semantic_index(joint_map: JointMap, skeleton: Skeleton, semantic: str, key: str) -> int:
    """Index in ``skeleton`` of the semantic joint ``semantic``; KeyError naming ``key``
    (the config key the name came from) and the joint map's semantic joints when the
    joint map has no such joint."""
    if semantic not in joint_map.joints:
        raise KeyError(
            f"config {key}: {semantic!r} is not a semantic joint of the joint map "
            f"({', '.join(sorted(joint_map.joints))})"
        )
    return joint_map.index(skeleton, semantic)
