"""Stride length per support phase (Ma et al. 2010, Sec. 7.1-7.2: "the stride lengths of
the left support phase and the right support phase are the two elements of a style
parameter for the walking behavior").

During a single-support phase the stance foot stays put and the swing foot travels from
behind the body to in front of it: its horizontal displacement is one stride (two steps,
docs/gait.md). The swing foot is the one that moves more between the phase's boundaries.
"""

from __future__ import annotations

import numpy as np


def stride_lengths(
    foot_positions: np.ndarray, boundaries: np.ndarray, up_axis: int = 1, footprint_window: int = 0
) -> np.ndarray:
    """Horizontal displacement of the swing foot in each phase, in the input's units.

    Args:
        foot_positions: (T, F, 3) global positions of one joint per foot (F >= 2, e.g. the
            two ankles).
        boundaries: (P + 1,) increasing frame indices; phase p runs from boundaries[p] to
            boundaries[p + 1].
        up_axis: index of the vertical axis.
        footprint_window: if > 0, each foot's position at a boundary is taken where that
            foot moves least horizontally within +- this many frames (its footprint), so
            that the measure does not depend on the exact boundary frame.

    Returns:
        (P,) stride length of each phase.
    """
    p = np.asarray(foot_positions, dtype=float)
    b = np.asarray(boundaries, dtype=np.int64)
    if p.ndim != 3 or p.shape[1] < 2 or p.shape[2] != 3:
        raise ValueError(f"stride_lengths: foot_positions must be (T, F>=2, 3); got {p.shape}")
    if b.ndim != 1 or len(b) < 2 or np.any(np.diff(b) <= 0) or b[0] < 0 or b[-1] >= len(p):
        raise ValueError(f"stride_lengths: boundaries must increase within [0, {len(p) - 1}]; got {b.tolist()}")
    horizontal = [a for a in range(3) if a != up_axis]
    h = p[:, :, horizontal]
    if footprint_window > 0:
        speed = np.linalg.norm(np.diff(h, axis=0, append=h[-1:]), axis=-1)  # (T, F)
        offsets = np.arange(-footprint_window, footprint_window + 1)
        frames = np.clip(b[:, None] + offsets[None, :], 0, len(p) - 1)  # (B, W)
        still = frames[np.arange(len(b))[:, None], np.argmin(speed[frames], axis=1)]  # (B, F)
        at = h[still, np.arange(h.shape[1])[None, :]]  # (B, F, 2)
    else:
        at = h[b]
    disp = np.linalg.norm(at[1:] - at[:-1], axis=-1)  # (P, F)
    return disp.max(axis=1)
