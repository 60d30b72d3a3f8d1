"""Forward kinematics restricted to the joints a constraint needs (Du 2022 Eq. 4.2's f_k).

Evaluating the objective of Eq. 4.2 for thousands of latent samples needs the global
position (and rotation) of a few joints at a few key frames only: :func:`chain_fk` walks
just the ancestors of those joints, vectorised over any leading axes (samples, frames).
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np


def _qmul(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Hamilton product (..., 4), scalar first (as core.quaternions.qmul, fewer temporaries)."""
    aw, ax, ay, az = a[..., 0], a[..., 1], a[..., 2], a[..., 3]
    bw, bx, by, bz = b[..., 0], b[..., 1], b[..., 2], b[..., 3]
    out = np.empty(np.broadcast_shapes(a.shape, b.shape))
    out[..., 0] = aw * bw - ax * bx - ay * by - az * bz
    out[..., 1] = aw * bx + ax * bw + ay * bz - az * by
    out[..., 2] = aw * by - ax * bz + ay * bw + az * bx
    out[..., 3] = aw * bz + ax * by - ay * bx + az * bw
    return out


def _qrot(q: np.ndarray, v: np.ndarray) -> np.ndarray:
    """Rotate a fixed vector v (3,) by unit quaternions q (..., 4): v + 2w (u x v) + 2 u x (u x v)."""
    w, x, y, z = q[..., 0], q[..., 1], q[..., 2], q[..., 3]
    vx, vy, vz = float(v[0]), float(v[1]), float(v[2])
    tx, ty, tz = 2.0 * (y * vz - z * vy), 2.0 * (z * vx - x * vz), 2.0 * (x * vy - y * vx)
    out = np.empty(q.shape[:-1] + (3,))
    out[..., 0] = vx + w * tx + (y * tz - z * ty)
    out[..., 1] = vy + w * ty + (z * tx - x * tz)
    out[..., 2] = vz + w * tz + (x * ty - y * tx)
    return out


def ancestors(parents: np.ndarray, joints: Sequence[int]) -> np.ndarray:
    """Sorted indices of ``joints`` and all their ancestors (parents precede children)."""
    parents = np.asarray(parents)
    need: set[int] = set()
    for j in joints:
        j = int(j)
        if not 0 <= j < len(parents):
            raise ValueError(f"joint index {j} out of range for a skeleton of {len(parents)} joints")
        while j >= 0 and j not in need:
            need.add(j)
            j = int(parents[j])
    return np.array(sorted(need), dtype=np.int64)


def chain_fk(
    rotations: np.ndarray, root_pos: np.ndarray, offsets: np.ndarray, parents: np.ndarray, joints: Sequence[int]
) -> tuple[np.ndarray, np.ndarray]:
    """Global positions (..., len(joints), 3) and rotations (..., len(joints), 4) of
    ``joints`` from local unit quaternions (..., J, 4), root positions (..., 3) and bone
    offsets (J, 3); only the kinematic chains of ``joints`` are evaluated."""
    chain = ancestors(parents, joints)
    gpos: dict[int, np.ndarray] = {0: root_pos}
    grot: dict[int, np.ndarray] = {0: rotations[..., 0, :]}
    for j in chain[1:]:
        p = int(parents[j])
        grot[int(j)] = _qmul(grot[p], rotations[..., j, :])
        gpos[int(j)] = gpos[p] + _qrot(grot[p], offsets[j])
    return (np.stack([gpos[int(j)] for j in joints], axis=-2), np.stack([grot[int(j)] for j in joints], axis=-2))
