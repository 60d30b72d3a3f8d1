"""Foot skating: horizontal sliding of a foot while it is on the ground (e.g. Kovar et al.
2002, "Footskate cleanup").

:func:`foot_skating` measures it where a foot really touches the ground: over the frames of
its contacts (given: the generator's ground truth, or the project's contact detection,
:func:`motionvar.prep.contacts.detect_foot_contacts`), the horizontal speed of the foot's
contact point, the joint of the foot nearest its planted height (the ankle while the heel
is down, the toe while the foot rolls over it at toe-off). A planted foot rolls: its
ankle rises and moves forward at heel-off while the toe stays put, and the heel lands
before the toe; only the contact point must not move. The generator's walks, whose planted
feet never slide, score 0 (tests/metrics/test_metrics_motion.py).

:func:`low_joint_speed` is the earlier measure: the horizontal speed of every foot joint
while it is below a height threshold. It counts the heel and toe roll of a planted foot
and a foot skimming the floor at heel strike as sliding (13-47 cm/s on the generator's
walks) and is kept for comparison only.
"""

from __future__ import annotations

import numpy as np


def contact_point_speeds(
    foot_positions: np.ndarray, contacts: np.ndarray, fps: float, floor: np.ndarray | None = None, up_axis: int = 1
) -> np.ndarray:
    """Horizontal speed (T-1, S) of each foot's contact point between consecutive frames,
    NaN where the foot is not in contact in both frames.

    The contact point of a frame pair is the foot's joint whose higher position of the two
    frames is nearest its planted height (``floor``); a foot that stands still on its heel,
    its sole or its toe scores 0 whichever joint the foot has down.

    Args:
        foot_positions: (T, S, F, 3) global positions of F joints (e.g. ankle and toe) of
            S feet, cm.
        contacts: (T, S) boolean contact mask of each foot.
        fps: frames per second.
        floor: (S, F) height of each joint when its foot is planted (e.g. its rest height
            above the sole); default: the joint's lowest height over its foot's contacts.
        up_axis: index of the vertical axis.
    """
    p = np.asarray(foot_positions, dtype=float)
    c = np.asarray(contacts, dtype=bool)
    if p.ndim != 4 or p.shape[-1] != 3 or p.shape[0] < 2:
        raise ValueError(f"foot skating: foot_positions must be (T>=2, S, F, 3); got {p.shape}")
    if c.shape != p.shape[:2]:
        raise ValueError(f"foot skating: contacts must be (T, S) = {p.shape[:2]}; got {c.shape}")
    if not np.isfinite(fps) or fps <= 0:
        raise ValueError(f"foot skating: fps must be positive; got {fps}")
    height = p[..., up_axis]  # (T, S, F)
    if floor is None:
        floor = np.where(c[..., None], height, np.inf).min(axis=0)  # (S, F)
        floor = np.where(np.isfinite(floor), floor, 0.0)
    floor = np.asarray(floor, dtype=float)
    if floor.shape != p.shape[1:3]:
        raise ValueError(f"foot skating: floor must be (S, F) = {p.shape[1:3]}; got {floor.shape}")
    above = np.maximum(height[1:], height[:-1]) - floor  # (T-1, S, F): the pair's higher position
    point = np.argmin(above, axis=2)  # (T-1, S)
    horizontal = [a for a in range(3) if a != up_axis]
    step = np.diff(p[..., horizontal], axis=0)  # (T-1, S, F, 2)
    moved = np.take_along_axis(step, point[..., None, None], axis=2)[:, :, 0]  # (T-1, S, 2)
    speed = np.linalg.norm(moved, axis=-1) * fps
    return np.where(c[1:] & c[:-1], speed, np.nan)


def foot_skating(
    foot_positions: np.ndarray, contacts: np.ndarray, fps: float, floor: np.ndarray | None = None, up_axis: int = 1
) -> float:
    """Mean horizontal speed (cm/s) of the feet's contact points over the frame pairs in
    which the foot is in contact (:func:`contact_point_speeds`, same arguments); 0.0 when
    no foot is ever in contact."""
    speed = contact_point_speeds(foot_positions, contacts, fps, floor, up_axis)
    valid = np.isfinite(speed)
    return float(speed[valid].mean()) if valid.any() else 0.0


def low_joint_speed(foot_positions: np.ndarray, fps: float, contact_height: float, up_axis: int = 1) -> float:
    """Mean horizontal speed (cm/s) of foot joints while below a height threshold (the
    earlier "foot skating": it also counts a planted foot's heel and toe roll, see the
    module docstring).

    Args:
        foot_positions: (T, F, 3) global positions of F foot joints (e.g. ankles and toes), cm.
        fps: frames per second.
        contact_height: a joint counts in a frame pair when its height is below this in
            both frames (cm above the ground plane y = 0).
        up_axis: index of the vertical axis.

    Returns 0.0 when no joint is ever that low.
    """
    p = np.asarray(foot_positions, dtype=float)
    if p.ndim != 3 or p.shape[-1] != 3 or p.shape[0] < 2:
        raise ValueError(f"low_joint_speed: foot_positions must be (T>=2, F, 3); got {p.shape}")
    horizontal = [a for a in range(3) if a != up_axis]
    low = p[..., up_axis] < contact_height
    contact = low[1:] & low[:-1]
    speed = np.linalg.norm(np.diff(p[..., horizontal], axis=0), axis=-1) * fps
    if not contact.any():
        return 0.0
    return float(speed[contact].mean())
