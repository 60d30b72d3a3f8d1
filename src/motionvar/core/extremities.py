"""Hands and toes where a rig lacks them (:data:`~.joint_map.OPTIONAL_JOINTS`).

A markerless rig may end its arms at the forearm and its legs at the foot; the BVH still
gives the End Site beyond each (the wrist, the toe tip). What needs a toe (foot contacts, the
floor) takes the foot's End Site in its place, and says so; what needs a hand joint declares
it in its requirements and is not applicable on such a rig.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from .joint_map import JointMap
from .kinematics import fk
from .motion import Motion
from .quaternions import qrot


def end_site_positions(motion: Motion, joints: Sequence[int]) -> np.ndarray:
    """(T, len(joints), 3) global positions of the End Sites of ``joints`` (indices; each
    must have one): the joint's position plus its End Site offset turned by its global
    rotation."""
    sk = motion.skeleton
    lacking = [sk.names[j] for j in joints if j not in sk.end_sites]
    if lacking:
        raise ValueError(f"joints {lacking} have no End Site")
    pos, rot = fk(
        motion.rotations,
        motion.root_pos,
        sk.offsets,
        sk.parents,
        motion.translations,
        return_rotations=True,
    )  # one forward kinematics for the positions and the rotations
    idx = np.asarray(joints, dtype=np.int64)
    return pos[:, idx] + qrot(rot[:, idx], np.stack([sk.end_sites[int(j)] for j in idx]))


def toe_stand_in(joint_map: JointMap, motion: Motion) -> str | None:
    """Why the toes come from End Sites ('the joint map has no toe joints: ...'), or None when
    the map names both toe joints. ValueError when neither the toes nor the ankles' End Sites
    exist."""
    if joint_map.has("left_toe", "right_toe"):
        return None
    ankles = [joint_map.joints[f"{s}_ankle"] for s in ("left", "right")]
    sk = motion.skeleton
    if not all(sk.index(a) in sk.end_sites for a in ankles):
        where = f" ({joint_map.origin})" if joint_map.origin else ""
        raise ValueError(
            f"the joint map{where} has no toe joints and the ankles {ankles} have no End Site to stand in for them"
        )
    return f"the joint map has no toe joints: the End Sites of {ankles[0]} and {ankles[1]} stand in for the toes"


def foot_points(motion: Motion, joint_map: JointMap, positions: np.ndarray | None = None) -> np.ndarray:
    """(T, 2 feet [left, right], 2 points [ankle, toe], 3) positions: the ankle joints and the
    toe joints, or, where the map has no toe joints, the ankles' End Sites (:func:`toe_stand_in`)."""
    sk = motion.skeleton
    pos = motion.positions() if positions is None else np.asarray(positions, dtype=float)
    ankles = joint_map.indices(sk, ["left_ankle", "right_ankle"])
    if toe_stand_in(joint_map, motion) is None:
        toes = pos[:, joint_map.indices(sk, ["left_toe", "right_toe"])]
    else:
        toes = end_site_positions(motion, ankles)
    return np.stack([pos[:, ankles], toes], axis=2)
