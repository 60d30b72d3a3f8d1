"""Forward kinematics in numpy and in torch, vectorised over any leading axes
(clips, frames); the only loop is over joints, parents before children.

The torch path is differentiable (used by SFPCA's objective, Du 2022 Eq. 3.8, and by
constrained synthesis). Both compute the same thing: global joint rotations
R_j = R_parent(j) * q_j and positions p_j = p_parent(j) + R_parent(j) * o_j, with the root
placed at ``root_pos``.
"""

from __future__ import annotations

import numpy as np

from .quaternions import qmul, qrot


def fk(
    rotations: np.ndarray,
    root_pos: np.ndarray,
    offsets: np.ndarray,
    parents: np.ndarray,
    translations: np.ndarray | None = None,
    return_rotations: bool = False,
) -> np.ndarray | tuple[np.ndarray, np.ndarray]:
    """Global joint positions (..., J, 3) from local quaternions.

    Args:
        rotations: (..., J, 4) local unit quaternions, scalar first.
        root_pos: (..., 3) root position.
        offsets: (J, 3) or (..., J, 3) rest offsets (per-clip skeletons broadcast).
        parents: (J,) parent indices, -1 for the root, parents first.
        translations: optional (..., J, 3) per-frame local translations that replace
            ``offsets`` (BVH joints with position channels); NaN entries fall back to offsets.
        return_rotations: also return global rotations (..., J, 4).
    """
    J = rotations.shape[-2]
    local = np.broadcast_to(offsets, rotations.shape[:-1] + (3,))
    if translations is not None:
        local = np.where(np.isnan(translations), local, translations)
    gpos: list[np.ndarray] = [root_pos]
    grot: list[np.ndarray] = [rotations[..., 0, :]]
    for j in range(1, J):
        p = parents[j]
        grot.append(qmul(grot[p], rotations[..., j, :]))
        gpos.append(gpos[p] + qrot(grot[p], local[..., j, :]))
    pos = np.stack(gpos, axis=-2)
    if return_rotations:
        return pos, np.stack(grot, axis=-2)
    return pos


def _torch():
    import torch  # imported lazily: numpy users need not pay torch's import time

    return torch


def qmul_torch(a, b):
    """Hamilton product of torch quaternions (..., 4), scalar first."""
    torch = _torch()
    aw, ax, ay, az = a.unbind(-1)
    bw, bx, by, bz = b.unbind(-1)
    return torch.stack(
        (
            aw * bw - ax * bx - ay * by - az * bz,
            aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw,
        ),
        dim=-1,
    )


def qrot_torch(q, v):
    """Rotate torch vectors v (..., 3) by unit quaternions q (..., 4)."""
    torch = _torch()
    w = q[..., :1]
    u = q[..., 1:]
    t = 2.0 * torch.linalg.cross(u, v.expand_as(u), dim=-1)
    return v + w * t + torch.linalg.cross(u, t, dim=-1)


def fk_torch(rotations, root_pos, offsets, parents, translations=None):
    """Differentiable torch version of :func:`fk` (positions only).

    Joints are taken with ``unbind`` rather than slicing: slice backward was 4x slower
    (docs/stack.md, SFPCA measurements).
    """
    torch = _torch()
    offsets = torch.as_tensor(offsets, dtype=rotations.dtype)
    local = offsets.expand(*rotations.shape[:-1], 3)
    if translations is not None:
        translations = torch.as_tensor(translations, dtype=rotations.dtype)
        local = torch.where(torch.isnan(translations), local, translations)
    rots = rotations.unbind(-2)
    locs = local.unbind(-2)
    gpos = [root_pos]
    grot = [rots[0]]
    for j in range(1, len(rots)):
        p = int(parents[j])
        grot.append(qmul_torch(grot[p], rots[j]))
        gpos.append(gpos[p] + qrot_torch(grot[p], locs[j]))
    return torch.stack(gpos, dim=-2)
