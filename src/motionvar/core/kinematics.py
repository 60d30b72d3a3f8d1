"""Forward kinematics in numpy and in torch, vectorised over any leading axes
(clips, frames); the only loop is over joints, parents before children.

The torch path is differentiable (used by SFPCA's objective, Du 2022 Eq. 3.8, and by
constrained synthesis). Both compute the same thing: global joint rotations
R_j = R_parent(j) * q_j and positions p_j = p_parent(j) + R_parent(j) * o_j, with the root
placed at ``root_pos``.
"""

from __future__ import annotations

import numpy as np


def _qmul_rows(a: np.ndarray, b: np.ndarray, out: np.ndarray) -> None:
    """:func:`~.quaternions.qmul` on quaternions stored components first, (4, M) rows,
    written into ``out``."""
    aw, ax, ay, az = a
    bw, bx, by, bz = b
    out[0] = aw * bw - ax * bx - ay * by - az * bz
    out[1] = aw * bx + ax * bw + ay * bz - az * by
    out[2] = aw * by - ax * bz + ay * bw + az * bx
    out[3] = aw * bz + ax * by - ay * bx + az * bw


def _add_qrot_rows(p: np.ndarray, q: np.ndarray, v: np.ndarray, out: np.ndarray) -> None:
    """``out = p + qrot(q, v)`` (:func:`~.quaternions.qrot`) on (3, M) position rows,
    (4, M) quaternion rows and (3, M) or (3, 1) vector rows."""
    w, x, y, z = q
    vx, vy, vz = v
    tx, ty, tz = 2.0 * (y * vz - z * vy), 2.0 * (z * vx - x * vz), 2.0 * (x * vy - y * vx)
    out[0] = p[0] + (vx + w * tx + (y * tz - z * ty))
    out[1] = p[1] + (vy + w * ty + (z * tx - x * tz))
    out[2] = p[2] + (vz + w * tz + (x * ty - y * tx))


def fk(
    rotations: np.ndarray,
    root_pos: np.ndarray,
    offsets: np.ndarray,
    parents: np.ndarray,
    translations: np.ndarray | None = None,
    return_rotations: bool = False,
) -> np.ndarray | tuple[np.ndarray, np.ndarray]:
    """Global joint positions (..., J, 3) from local quaternions.

    Computed joint-major: every joint's quaternion components are contiguous rows over all
    (clip, frame) pairs, so the products run on contiguous memory instead of strided views
    of the (..., J, 4) array (the same operations in the same order as
    :func:`~.quaternions.qmul` and :func:`~.quaternions.qrot`: the same numbers bit for bit,
    about 3x faster on a walk primitive's 1,480 clips).

    Args:
        rotations: (..., J, 4) local unit quaternions, scalar first.
        root_pos: (..., 3) root position (broadcast to the rotations' leading axes).
        offsets: (J, 3) or (..., J, 3) rest offsets (per-clip skeletons broadcast).
        parents: (J,) parent indices, -1 for the root, parents first.
        translations: optional (..., J, 3) per-frame local translations that replace
            ``offsets`` (BVH joints with position channels); NaN entries fall back to offsets.
        return_rotations: also return global rotations (..., J, 4).
    """
    rotations = np.asarray(rotations)
    lead, J = rotations.shape[:-2], rotations.shape[-2]
    M = int(np.prod(lead, dtype=np.int64))
    offsets = np.asarray(offsets)
    rot = np.ascontiguousarray(np.moveaxis(rotations.reshape(M, J, 4), 0, -1))  # (J, 4, M) rows
    if translations is None and offsets.ndim == 2:
        local = offsets[:, :, None]  # (J, 3, 1): the same offsets for every (clip, frame)
    else:
        local = np.broadcast_to(offsets, lead + (J, 3))
        if translations is not None:
            local = np.where(np.isnan(translations), local, translations)
        local = np.ascontiguousarray(np.moveaxis(np.broadcast_to(local, lead + (J, 3)).reshape(M, J, 3), 0, -1))
    root = np.broadcast_to(np.asarray(root_pos), lead + (3,)).reshape(M, 3)
    dtype = np.result_type(rotations, root, local, 2.0)
    grot = np.empty((J, 4, M), dtype=np.result_type(rotations))
    gpos = np.empty((J, 3, M), dtype=dtype)
    grot[0], gpos[0] = rot[0], root.T
    for j in range(1, J):
        p = parents[j]
        _qmul_rows(grot[p], rot[j], grot[j])
        _add_qrot_rows(gpos[p], grot[p], local[j], gpos[j])
    pos = np.ascontiguousarray(np.moveaxis(gpos, -1, 0)).reshape(lead + (J, 3))
    if return_rotations:
        return pos, np.ascontiguousarray(np.moveaxis(grot, -1, 0)).reshape(lead + (J, 4))
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
