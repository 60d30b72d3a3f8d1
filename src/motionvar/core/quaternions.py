"""Unit-quaternion utilities, scalar first (w, x, y, z), vectorised over leading axes.

Conversions to and from Euler angles, matrices and rotation vectors go through
:class:`scipy.spatial.transform.Rotation`; this module holds only what scipy does not
give over arbitrary batch shapes: products, log/exp maps, slerp, hemisphere continuity
and the sinusoidal rotational distance of Ma et al. 2010, Sec. 4.
"""

from __future__ import annotations

import numpy as np
from scipy.spatial.transform import Rotation

_EPS = 1e-12


def qnormalize(q: np.ndarray) -> np.ndarray:
    """Scale quaternions (..., 4) to unit length."""
    return q / np.linalg.norm(q, axis=-1, keepdims=True)


def qidentity(shape: tuple[int, ...] = ()) -> np.ndarray:
    """Identity quaternions of the given batch shape (..., 4)."""
    q = np.zeros((*shape, 4))
    q[..., 0] = 1.0
    return q


def qmul(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Hamilton product a * b of quaternions (..., 4), broadcasting over leading axes."""
    a, b = np.asarray(a), np.asarray(b)
    aw, ax, ay, az = a[..., 0], a[..., 1], a[..., 2], a[..., 3]
    bw, bx, by, bz = b[..., 0], b[..., 1], b[..., 2], b[..., 3]
    out = np.empty(np.broadcast_shapes(a.shape, b.shape), dtype=np.result_type(a, b))
    out[..., 0] = aw * bw - ax * bx - ay * by - az * bz
    out[..., 1] = aw * bx + ax * bw + ay * bz - az * by
    out[..., 2] = aw * by - ax * bz + ay * bw + az * bx
    out[..., 3] = aw * bz + ax * by - ay * bx + az * bw
    return out


def qinv(q: np.ndarray) -> np.ndarray:
    """Inverse (conjugate) of unit quaternions (..., 4)."""
    return q * np.array([1.0, -1.0, -1.0, -1.0])


def qrot(q: np.ndarray, v: np.ndarray) -> np.ndarray:
    """Rotate vectors v (..., 3) by unit quaternions q (..., 4), broadcasting.

    v' = v + w t + u × t with t = 2 u × v (u the vector part); the cross products are
    written out per component (about twice as fast as ``np.cross`` on short arrays).
    """
    q, v = np.asarray(q), np.asarray(v)
    w, x, y, z = q[..., 0], q[..., 1], q[..., 2], q[..., 3]
    vx, vy, vz = v[..., 0], v[..., 1], v[..., 2]
    tx, ty, tz = 2.0 * (y * vz - z * vy), 2.0 * (z * vx - x * vz), 2.0 * (x * vy - y * vx)
    out = np.empty(np.broadcast_shapes(q.shape[:-1] + (3,), v.shape), dtype=np.result_type(q, v, 2.0))
    out[..., 0] = vx + w * tx + (y * tz - z * ty)
    out[..., 1] = vy + w * ty + (z * tx - x * tz)
    out[..., 2] = vz + w * tz + (x * ty - y * tx)
    return out


def qlog(q: np.ndarray) -> np.ndarray:
    """Logarithm map of unit quaternions (..., 4) -> (..., 3): half the rotation vector.

    q = (cos θ, sin θ · n) maps to θ · n, with θ in [0, π] after choosing w >= 0.
    """
    q = np.where(q[..., :1] < 0, -q, q)
    v = q[..., 1:]
    s = np.linalg.norm(v, axis=-1, keepdims=True)
    theta = np.arctan2(s, q[..., :1])
    scale = np.where(s > _EPS, theta / np.maximum(s, _EPS), 1.0)
    return v * scale


def qexp(r: np.ndarray) -> np.ndarray:
    """Exponential map (..., 3) -> unit quaternions (..., 4); inverse of :func:`qlog`."""
    theta = np.linalg.norm(r, axis=-1, keepdims=True)
    scale = np.where(theta > _EPS, np.sin(theta) / np.maximum(theta, _EPS), 1.0)
    return np.concatenate([np.cos(theta), r * scale], axis=-1)


def qslerp(a: np.ndarray, b: np.ndarray, t: np.ndarray | float) -> np.ndarray:
    """Spherical linear interpolation from a to b (..., 4) at fraction t (broadcast to ...)."""
    t = np.asarray(t, dtype=float)[..., None] if np.ndim(t) else float(t)
    dot = np.sum(a * b, axis=-1, keepdims=True)
    b = np.where(dot < 0, -b, b)
    delta = qmul(qinv(a), b)
    return qnormalize(qmul(a, qexp(t * qlog(delta))))


def qfix(q: np.ndarray, axis: int = 0) -> np.ndarray:
    """Make consecutive quaternions along ``axis`` agree in sign (no hemisphere flips).

    q and -q are the same rotation; PCA, splines and interpolation need a continuous
    sign. Flips are accumulated so that each quaternion lies in the hemisphere of its
    predecessor.
    """
    q = np.moveaxis(np.array(q, dtype=float, copy=True), axis, 0)
    if q.shape[0] > 1:
        dots = np.sum(q[1:] * q[:-1], axis=-1)
        flips = np.cumsum(dots < 0, axis=0) % 2
        q[1:] *= np.where(flips[..., None] == 1, -1.0, 1.0)
    return np.moveaxis(q, 0, axis)


def qdistance_sinusoidal(q1: np.ndarray, q2: np.ndarray) -> np.ndarray:
    """Sinusoidal rotational distance ||q1 - q2||_s = sin(||log(q1^-1 q2)||) (Ma 2010, Sec. 4).

    Bounded in [0, 1] and equal for q and -q.
    """
    return np.sin(np.linalg.norm(qlog(qmul(qinv(q1), q2)), axis=-1))


def qangle(q1: np.ndarray, q2: np.ndarray) -> np.ndarray:
    """Geodesic angle in radians between two rotations (..., 4)."""
    return 2.0 * np.linalg.norm(qlog(qmul(qinv(q1), q2)), axis=-1)


def quat_from_scipy(r: Rotation, shape: tuple[int, ...]) -> np.ndarray:
    """Scalar-first quaternions from a flat scipy Rotation, reshaped to (*shape, 4)."""
    return r.as_quat(scalar_first=True).reshape(*shape, 4)


def quat_to_scipy(q: np.ndarray) -> Rotation:
    """Flat scipy Rotation from scalar-first quaternions (..., 4)."""
    return Rotation.from_quat(q.reshape(-1, 4), scalar_first=True)


def euler_to_quat(angles_deg: np.ndarray, order: str) -> np.ndarray:
    """Intrinsic Euler angles in degrees (..., 3), in BVH channel ``order`` (e.g. 'ZXY'),
    to scalar-first quaternions (..., 4)."""
    shape = angles_deg.shape[:-1]
    r = Rotation.from_euler(order.upper(), angles_deg.reshape(-1, 3), degrees=True)
    return quat_from_scipy(r, shape)


def quat_to_euler(q: np.ndarray, order: str) -> np.ndarray:
    """Scalar-first quaternions (..., 4) to intrinsic Euler angles in degrees (..., 3)."""
    shape = q.shape[:-1]
    return quat_to_scipy(q).as_euler(order.upper(), degrees=True).reshape(*shape, 3)


def quat_to_rotvec(q: np.ndarray) -> np.ndarray:
    """Rotation vectors (exponential map, Egges 2004 Sec. 3.2) of quaternions (..., 4)."""
    return 2.0 * qlog(q)


def rotvec_to_quat(r: np.ndarray) -> np.ndarray:
    """Quaternions (..., 4) of rotation vectors (..., 3)."""
    return qexp(0.5 * r)


def quat_about_axis(axis: np.ndarray | list[float], angle: np.ndarray | float) -> np.ndarray:
    """Quaternions of rotations by ``angle`` (radians, any shape) about a fixed unit ``axis``."""
    axis = np.asarray(axis, dtype=float)
    axis = axis / np.linalg.norm(axis)
    half = 0.5 * np.asarray(angle, dtype=float)[..., None]
    return np.concatenate([np.cos(half), np.sin(half) * axis], axis=-1)
