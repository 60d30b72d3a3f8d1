"""Post-processing (Ma et al. 2010, Sec. 6.3): transitions by displacement mapping
(Eq. 14-15) and footskate cleanup, which computes the root motion.

Poses here are local rotations (T, J, 4) plus, optionally, a root height curve (T,);
the root position is set by :func:`reconstruct_root` at the end.
"""

from __future__ import annotations

import numpy as np

from ..core.kinematics import fk
from ..core.quaternions import qdistance_sinusoidal, qexp, qinv, qlog, qmul, qrot, quat_about_axis
from ..core.skeleton import Skeleton


def pose_distance(pose: np.ndarray, poses: np.ndarray) -> np.ndarray:
    """Distance of one pose (J, 4) to each of poses (T, J, 4): the sum over joints of the
    sinusoidal rotational distance (Sec. 4, [PSS02])."""
    return qdistance_sinusoidal(pose[None], poses).sum(axis=-1)


def landing_frame(last_pose: np.ndarray, clip: np.ndarray) -> int:
    """Landing frame t of a transition into ``clip`` (T, J, 4), 1-based (Sec. 6.3): the
    frame that reaches the first local maximum of the pose distance to ``last_pose``,
    the last frame of the preceding clip. At least 2; the clip's length if no maximum."""
    d = pose_distance(last_pose, clip)
    interior = np.flatnonzero((d[1:-1] >= d[:-2]) & (d[1:-1] > d[2:])) + 1
    t = int(interior[0]) + 1 if len(interior) else len(d)
    return max(t, 2)


def blend_weights(t: int) -> np.ndarray:
    """Eq. 15: rho_i = 2 u^3 - 3 u^2 + 1 with u = (i - 1) / (t - 1), i = 1..t; rho_1 = 1, rho_t = 0."""
    u = np.arange(t) / max(t - 1, 1)
    return 2 * u**3 - 3 * u**2 + 1


def heading_angle(q: np.ndarray, forward: np.ndarray) -> np.ndarray:
    """Yaw (radians about +y) of the direction ``forward`` rotated by root rotations q (..., 4)."""
    f = qrot(q, np.broadcast_to(forward, q.shape[:-1] + (3,)))
    return np.arctan2(-f[..., 2], f[..., 0])


def land(
    last_pose: np.ndarray,
    second: np.ndarray,
    last_extra: np.ndarray | None = None,
    second_extra: np.ndarray | None = None,
    landing: int | None = None,
    align_heading: bool = True,
    forward: np.ndarray = np.array([1.0, 0.0, 0.0]),
) -> tuple[np.ndarray, np.ndarray | None]:
    """M2 edited for a transition from a clip ending in ``last_pose`` (Eq. 14-15):
    {q_1..q_t, p^2_(t+1)..p^2_T} with q_i = p^2_i exp(rho_i log((p^2_1)^-1 p^1_T)) per
    joint, so that q_1 = p^1_T; per-frame channels ``second_extra`` get
    q_i = p^2_i + rho_i (p^1_T - p^2_1). See :func:`transition`."""
    second = second.copy()
    if align_heading:
        yaw = heading_angle(last_pose[0], forward) - heading_angle(second[0, 0], forward)
        second[:, 0] = qmul(quat_about_axis([0.0, 1.0, 0.0], yaw), second[:, 0])
    t = landing_frame(last_pose, second) if landing is None else int(np.clip(landing, 2, len(second)))
    rho = blend_weights(t)
    delta = qlog(qmul(qinv(second[0]), last_pose))  # (J, 3)
    second[:t] = qmul(second[:t], qexp(rho[:, None, None] * delta[None]))
    extra = None
    if last_extra is not None and second_extra is not None:
        extra = np.array(second_extra, dtype=float, copy=True)
        extra[:t] += rho.reshape((-1,) + (1,) * (extra.ndim - 1)) * (last_extra - extra[0])
    return second, extra


def transition(
    first: np.ndarray,
    second: np.ndarray,
    first_extra: np.ndarray | None = None,
    second_extra: np.ndarray | None = None,
    landing: int | None = None,
    align_heading: bool = True,
    forward: np.ndarray = np.array([1.0, 0.0, 0.0]),
) -> tuple[np.ndarray, np.ndarray | None]:
    """M = M1 (+) M2 (Eq. 14): {p^1_1..p^1_(T-1), q_1..q_t, p^2_(t+1)..p^2_T} with
    q_i = p^2_i + rho_i dp, dp = p^1_T - p^2_1. Only M2 is edited (:func:`land`).

    For rotations the displacement is taken in the tangent space of each joint:
    q_i = p^2_i exp(rho_i log((p^2_1)^-1 p^1_T)), so q_1 = p^1_T exactly. With
    ``align_heading`` M2's root is first turned about the vertical so that its first
    frame heads where M1's last frame heads (our addition: it lets turns accumulate over a
    sequence instead of being blended back; a no-op for clips that already agree).

    Args:
        first, second: (T1, J, 4) and (T2, J, 4) local rotations.
        first_extra, second_extra: optional per-frame channels (T, ...) displaced alike
            (e.g. the root height curve).
        landing: landing frame t (1-based); default :func:`landing_frame`.
        forward: the root's forward axis after space warping (+x).
    """
    last_extra = None if first_extra is None else first_extra[-1]
    edited, extra = land(first[-1], second, last_extra, second_extra, landing, align_heading, forward)
    rotations = np.concatenate([first[:-1], edited], axis=0)
    if extra is not None:
        extra = np.concatenate([first_extra[:-1], extra], axis=0)
    return rotations, extra


def reconstruct_root(
    rotations: np.ndarray,
    skeleton: Skeleton,
    feet: np.ndarray,
    planted: np.ndarray,
    root_height: np.ndarray | None = None,
    flight_threshold: float | None = None,
) -> np.ndarray:
    """Footskate cleanup (Sec. 6.3): the root trajectory (T, 3) that keeps the lower foot
    planted ("fixing this foot on the ground and treating it as the root", [TLP07]).

    A foot's height is that of its lowest joint above the joint's planted height (ankle
    and toe: a foot rolling over its toes stands on the toe, a foot landing on its heel
    on the ankle). In every frame the lower foot supports the body and its lowest joint is
    pinned: horizontally the root moves opposite to that joint's motion relative to the
    root, vertically the root sits so that the joint is at its planted height.

    Behaviours with flight phases (running): pass the predicted root height curve
    ``root_height`` (T,) and ``flight_threshold`` (cm). A frame is in flight when both
    feet, placed with the predicted root height, are higher than ``flight_threshold``;
    there the predicted curve sets the root height and the root moves horizontally at
    constant speed (the velocity of the last supported frame).

    Args:
        rotations: (T, J, 4) local rotations.
        feet: (2, F) joint indices of the left and the right foot (e.g. ankle and toe).
        planted: (2, F) height (cm) of each of those joints when its foot is planted.
    """
    T = len(rotations)
    feet = np.asarray(feet, dtype=np.int64).reshape(2, -1)
    planted = np.asarray(planted, dtype=float).reshape(feet.shape)
    local = fk(rotations, np.zeros((T, 3)), skeleton.offsets, skeleton.parents)  # root at the origin
    p = local[:, feet]  # (T, 2, F, 3)
    above = p[..., 1] - planted  # (T, 2, F): height above planted, root at height 0
    joint = np.argmin(above, axis=2)  # lowest joint of each foot
    foot_low = np.take_along_axis(above, joint[..., None], axis=2)[..., 0]  # (T, 2)
    support = np.argmin(foot_low, axis=1)
    t = np.arange(T)
    pin = joint[t, support]
    now = p[t, support, pin]
    prev = p[np.maximum(t - 1, 0), support, pin]
    step = np.zeros((T, 3))
    step[1:, [0, 2]] = -(now[1:, [0, 2]] - prev[1:, [0, 2]])
    height = -foot_low[t, support]
    if root_height is not None and flight_threshold is not None:
        root_height = np.asarray(root_height, dtype=float)
        flight = np.all(root_height[:, None] + foot_low > flight_threshold, axis=1)
        flight[0] = False
        last_supported = np.maximum.accumulate(np.where(flight, 0, t))
        step[flight] = step[last_supported[flight]]
        height = np.where(flight, root_height, height)
    root = np.cumsum(step, axis=0)
    root[:, 1] = height
    return root
