"""Re-rooting a clip at another joint: for rigs whose BVH ROOT is not the pelvis.

Everything downstream (alignment, root paths, speeds) takes joint 0's position as the
body's root. Some rigs put a helper above the pelvis: the Bandai-Namco ROOT
``joint_Root`` is the pelvis projected onto the ground, the pelvis is its child ``Hips``.
:func:`reroot` makes a chosen joint (the joint map's ``hips``) joint 0: its world
position becomes ``root_pos``, its world rotation the root rotation, the joints above it
are removed, and every other joint keeps its local rotation (and local translation, for
rigs with position channels on every joint). Forward kinematics of the kept joints is
unchanged.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from .motion import Motion
from .quaternions import qfix
from .skeleton import Skeleton


class RerootError(ValueError):
    """The clip cannot be re-rooted without losing joints."""


def ancestors(skeleton: Skeleton, joint: int) -> list[int]:
    """Indices of the joints above ``joint``, root first."""
    out = []
    p = int(skeleton.parents[joint])
    while p >= 0:
        out.append(p)
        p = int(skeleton.parents[p])
    return out[::-1]


def subtree(skeleton: Skeleton, joint: int) -> np.ndarray:
    """Sorted indices of ``joint`` and all joints below it (parents precede children)."""
    inside = np.zeros(skeleton.n_joints, dtype=bool)
    inside[joint] = True
    for j in range(joint + 1, skeleton.n_joints):
        inside[j] = inside[skeleton.parents[j]]
    return np.flatnonzero(inside)


def reroot_skeleton(skeleton: Skeleton, joint: int) -> tuple[Skeleton, np.ndarray]:
    """The skeleton below (and including) ``joint``, with ``joint`` as its root, and the
    old indices of the kept joints (new joint k is old joint ``kept[k]``).

    The new root's rest offset is its rest position in the old skeleton (the sum of the
    offsets above it); it always has position channels (its position moves). Raises
    :class:`RerootError` if a joint above ``joint`` has other children (they would be lost).
    """
    up = ancestors(skeleton, joint)
    kept = subtree(skeleton, joint)
    lost = sorted(set(range(skeleton.n_joints)) - set(kept.tolist()) - set(up))
    if lost:
        names = [skeleton.names[j] for j in lost]
        above = ", ".join(skeleton.names[j] for j in up)
        raise RerootError(
            f"cannot make {skeleton.names[joint]} the root: the joints above it ({above}) have other "
            f"children, which would be lost: {names}"
        )
    new_index = np.full(skeleton.n_joints, -1, dtype=np.int64)
    new_index[kept] = np.arange(len(kept))
    parents = np.where(kept == joint, -1, new_index[skeleton.parents[kept]])
    offsets = skeleton.offsets[kept].copy()
    offsets[0] = skeleton.offsets[up + [joint]].sum(axis=0)
    orders = tuple(skeleton.rotation_orders[j] for j in kept)
    pos_ch = (True,) + tuple(skeleton.position_channels[j] for j in kept[1:])
    end_sites = {int(new_index[j]): o.copy() for j, o in skeleton.end_sites.items() if new_index[j] >= 0}
    new = Skeleton(
        names=tuple(skeleton.names[j] for j in kept),
        parents=parents,
        offsets=offsets,
        end_sites=end_sites,
        rotation_orders=orders,
        position_channels=pos_ch,
    )
    return new, kept


def reroot(motion: Motion, joint: int | str) -> Motion:
    """``motion`` with ``joint`` (index or name) as joint 0 (see the module docstring).
    Returns ``motion`` itself when ``joint`` is already the root."""
    sk = motion.skeleton
    j = sk.index(joint) if isinstance(joint, str) else int(joint)
    if j == 0:
        return motion
    skeleton, kept = reroot_skeleton(sk, j)
    pos, rot = motion.positions(), motion.global_rotations()
    rotations = motion.rotations[:, kept].copy()
    rotations[:, 0] = qfix(rot[:, j], axis=0)
    translations = None
    if motion.translations is not None:
        translations = motion.translations[:, kept].copy()
        translations[:, 0] = np.nan  # the root's position is root_pos
        if np.all(np.isnan(translations)):
            translations = None
    return replace(motion, skeleton=skeleton, root_pos=pos[:, j].copy(), rotations=rotations, translations=translations)
