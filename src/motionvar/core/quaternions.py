"""Unit-quaternion utilities, scalar first (w, x, y, z), vectorised over leading axes.

Conversions to Euler angles and matrices go through
:class:`scipy.spatial.transform.Rotation`; Euler angles to quaternions are scipy's
composition written out (every BVH read starts there; the same bits, faster). The rest is
what scipy does not give over arbitrary batch shapes: products, log/exp maps, slerp,
hemisphere continuity and the sinusoidal rotational distance of Ma et al. 2010, Sec. 4.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from scipy.spatial.transform import Rotation

_EPS = 1e-12


def qnormalize(q: np.ndarray) -> np.ndarray:
    """Scale quaternions (..., 4) to unit length.

    The squares summed as written, ((w² + x²) + y²) + z²: ``np.linalg.norm``'s value bit
    for bit (tests/core/test_core.py) without its temporaries."""
    q = np.asarray(q)
    q = q.astype(np.result_type(q, 1.0), copy=False)
    w, x, y, z = np.moveaxis(q, -1, 0)
    return q / np.sqrt(w * w + x * x + y * y + z * z)[..., None]


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


def quat_to_scipy(q: np.ndarray) -> Rotation:
    """Flat scipy Rotation from scalar-first quaternions (..., 4)."""
    from scipy.spatial.transform import Rotation  # lazily: most callers never convert

    return Rotation.from_quat(q.reshape(-1, 4), scalar_first=True)


def euler_to_quat(angles_deg: np.ndarray, order: str) -> np.ndarray:
    """Intrinsic Euler angles in degrees (..., 3), in BVH channel ``order`` (e.g. 'ZXY'),
    to scalar-first quaternions (..., 4): q = q_a(θ1) q_b(θ2) q_c(θ3), the axis rotations
    of ``order`` composed left to right.

    scipy's ``Rotation.from_euler`` (its elementary-quaternion composition) with the terms
    that are zero for axis quaternions written out of the products; rows where a component
    comes out zero are composed in full, so that its sign is scipy's too. The same
    quaternions bit for bit (tests/core/test_core.py), about 8x faster on a BVH file's rotations.
    """
    axes = ["XYZ".index(c) for c in order.upper() if c in "XYZ"]
    if len(order) != 3 or len(set(axes)) != 3:
        raise ValueError(f"Euler order must be a permutation of XYZ; got {order!r}")
    angles_deg = np.asarray(angles_deg, dtype=float)
    shape = angles_deg.shape[:-1]
    half = np.deg2rad(angles_deg.reshape(-1, 3).T, out=np.empty((3, angles_deg.size // 3)))  # (3, N) rows
    half /= 2
    s, c = np.sin(half), np.cos(half)
    a, b, k = axes
    n = half.shape[1]
    mul, tmp = np.multiply, np.empty(n)  # products written in place: few large temporaries
    # q_a q_b = (c_b s_a e_a + c_a s_b e_b + s_a s_b (e_a x e_b), c_a c_b); e_a x e_b = ±e_third
    ab = np.empty((4, n))  # x, y, z, w rows
    mul(c[1], s[0], out=ab[a]), mul(c[0], s[1], out=ab[b]), mul(c[0], c[1], out=ab[3])
    mul(s[0], s[1], out=ab[3 - a - b])
    if (b - a) % 3 != 1:
        np.negative(ab[3 - a - b], out=ab[3 - a - b])
    # (q_a q_b) q_k with q_k = (s_k e_k, c_k); i, j the axes after k in cyclic order
    i, j = (k + 1) % 3, (k + 2) % 3
    xyzw = np.empty((4, n))
    mul(ab[3], c[2], out=xyzw[3]), mul(ab[k], s[2], out=tmp), np.subtract(xyzw[3], tmp, out=xyzw[3])
    mul(ab[3], s[2], out=xyzw[k]), mul(c[2], ab[k], out=tmp), np.add(xyzw[k], tmp, out=xyzw[k])
    mul(c[2], ab[i], out=xyzw[i]), mul(ab[j], s[2], out=tmp), np.add(xyzw[i], tmp, out=xyzw[i])
    mul(c[2], ab[j], out=xyzw[j]), mul(ab[i], s[2], out=tmp), np.subtract(xyzw[j], tmp, out=xyzw[j])
    zero = np.flatnonzero((xyzw == 0).any(axis=0))
    if zero.size:  # the dropped zero terms decide the sign of a zero component
        elementary = [_axis_quat(axis, s[m, zero], c[m, zero]) for m, axis in enumerate(axes)]
        xyzw[:, zero] = _compose_xyzw(_compose_xyzw(elementary[0], elementary[1]), elementary[2])
    out = np.empty((n, 4))
    out[:, 0], out[:, 1:] = xyzw[3], xyzw[:3].T
    return out.reshape(*shape, 4)


def _axis_quat(axis: int, sin_half: np.ndarray, cos_half: np.ndarray) -> np.ndarray:
    """(4, N) scalar-last rows of the rotations about basis ``axis`` (0-2)."""
    q = np.zeros((4, sin_half.size))
    q[axis], q[3] = sin_half, cos_half
    return q


def _compose_xyzw(p: np.ndarray, q: np.ndarray) -> np.ndarray:
    """Product p q of (4, N) scalar-last quaternion rows, term by term as scipy composes."""
    px, py, pz, pw = p
    qx, qy, qz, qw = q
    cx, cy, cz = py * qz - pz * qy, pz * qx - px * qz, px * qy - py * qx
    return np.stack(
        [
            pw * qx + qw * px + cx,
            pw * qy + qw * py + cy,
            pw * qz + qw * pz + cz,
            pw * qw - (px * qx + py * qy + pz * qz),
        ]
    )


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
