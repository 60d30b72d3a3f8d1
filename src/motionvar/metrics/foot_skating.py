"""Foot skating: horizontal sliding of a foot that touches the ground (e.g. Kovar et al.
2002, "Footskate cleanup"). A foot joint is in contact while its height is below
``contact_height``; its horizontal speed in those frames is skating."""

from __future__ import annotations

import numpy as np


def foot_skating(foot_positions: np.ndarray, fps: float, contact_height: float, up_axis: int = 1) -> float:
    """Mean horizontal speed (cm/s) of foot joints over the frames they are in contact.

    Args:
        foot_positions: (T, F, 3) global positions of F foot joints (e.g. ankles and toes), cm.
        fps: frames per second.
        contact_height: a joint is in contact in a frame pair when its height is below this
            in both frames (cm above the ground plane y = 0).
        up_axis: index of the vertical axis.

    Returns 0.0 when no joint is ever in contact.
    """
    p = np.asarray(foot_positions, dtype=float)
    if p.ndim != 3 or p.shape[-1] != 3 or p.shape[0] < 2:
        raise ValueError(f"foot_skating: foot_positions must be (T>=2, F, 3); got {p.shape}")
    horizontal = [a for a in range(3) if a != up_axis]
    low = p[..., up_axis] < contact_height
    contact = low[1:] & low[:-1]
    speed = np.linalg.norm(np.diff(p[..., horizontal], axis=0), axis=-1) * fps
    if not contact.any():
        return 0.0
    return float(speed[contact].mean())
