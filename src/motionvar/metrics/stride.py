"""Stride length per support phase (Ma et al. 2010, Sec. 7.1-7.2: "the stride lengths of
the left support phase and the right support phase are the two elements of a style
parameter for the walking behavior").

During a single-support phase the stance foot stays put and the swing foot travels from
behind the body to in front of it: its horizontal displacement is one stride (two steps,
docs/gait.md). The swing foot is the one that moves more between the phase's boundaries.

Two ways to find where a foot stands at a boundary:

- :func:`footfall_strides` (what the Ma 2010 evaluations use): the footprint of the foot's
  last footfall (contact) at or before the boundary, from contact masks. A phase's stride is
  then the distance between two footfalls of the swing foot, as the generator defines it
  (tests/test_synth_locomotion.py), wherever those footfalls lie: the motion must reach
  back to the footfall before the phase (measure on the uncut motion, not the cut cycle).
- :func:`stride_lengths`: the foot's stillest frame within a window around the boundary.
  At the key frames of a walking cycle (legs farthest apart) the trailing foot is already
  rolling off its toes, and a cycle cut at that key frame has no frames before it: this
  measure then comes out 2-7 % short (left support 130.6 cm on a cut generator cycle, 137.0
  on the uncut walk, generator 140.7 cm). Kept for comparison.
"""

from __future__ import annotations

import numpy as np


def _feet_and_boundaries(
    foot_positions: np.ndarray, boundaries: np.ndarray, name: str
) -> tuple[np.ndarray, np.ndarray]:
    """(T, F, 3) float feet and (P + 1,) int boundaries, checked; ValueError naming ``name``."""
    p = np.asarray(foot_positions, dtype=float)
    b = np.asarray(boundaries, dtype=np.int64)
    if p.ndim != 3 or p.shape[1] < 2 or p.shape[2] != 3:
        raise ValueError(f"{name}: foot_positions must be (T, F>=2, 3); got {p.shape}")
    if b.ndim != 1 or len(b) < 2 or np.any(np.diff(b) <= 0) or b[0] < 0 or b[-1] >= len(p):
        raise ValueError(f"{name}: boundaries must increase within [0, {len(p) - 1}]; got {b.tolist()}")
    return p, b


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
    p, b = _feet_and_boundaries(foot_positions, boundaries, "stride_lengths")
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


def footprints(
    foot_positions: np.ndarray, contacts: np.ndarray, up_axis: int = 1
) -> list[tuple[np.ndarray, np.ndarray]]:
    """Each foot's footfalls: per foot, its contacts (K, 2) as [start, stop) frames and
    their footprints (K, 2): the horizontal position of the foot's joint in the contact's
    frame where that joint is lowest (a planted heel: the ankle stands still from heel
    strike to heel-off, while at toe-off it rises and moves).

    Args:
        foot_positions: (T, F, 3) one joint per foot (e.g. the ankles).
        contacts: (T, F) boolean contact masks.
    """
    p = np.asarray(foot_positions, dtype=float)
    c = np.asarray(contacts, dtype=bool)
    if p.ndim != 3 or p.shape[2] != 3 or c.shape != p.shape[:2]:
        raise ValueError(f"footprints: need foot_positions (T, F, 3) and contacts (T, F); got {p.shape} and {c.shape}")
    horizontal = [a for a in range(3) if a != up_axis]
    out = []
    for f in range(p.shape[1]):  # loop over feet
        d = np.diff(np.concatenate([[0], c[:, f].astype(np.int8), [0]]))
        runs = np.stack([np.flatnonzero(d == 1), np.flatnonzero(d == -1)], axis=1)
        frames = np.flatnonzero(c[:, f])
        run = np.searchsorted(runs[:, 0], frames, side="right") - 1  # contact of each contact frame
        order = np.lexsort((p[frames, f, up_axis], run))  # by contact, then by height
        first = order[np.r_[True, run[order][1:] != run[order][:-1]]] if len(order) else order
        out.append((runs, p[frames[first], f][:, horizontal]))
    return out


def footfall_strides(
    foot_positions: np.ndarray, contacts: np.ndarray, boundaries: np.ndarray, min_contact: int = 1, up_axis: int = 1
) -> np.ndarray:
    """Stride of each phase between the footfalls of the swing foot (:func:`footprints`).

    At each boundary a foot stands on the footprint of its contact nearest to the boundary
    (the one holding it, else the one with the fewest frames between them: at a walk's
    key frames, legs farthest apart, the trailing foot has just left or is leaving the
    ground and the leading foot has just landed or is about to); a phase's stride is the
    larger displacement of the two feet between its boundaries (the stance foot's is ~0).
    Contacts shorter than ``min_contact`` frames are no footfalls (a swing foot grazing
    the floor). NaN for a phase where a foot has no footfall at all.

    Args:
        foot_positions: (T, F, 3) one joint per foot (F >= 2, e.g. the two ankles).
        contacts: (T, F) boolean contact masks of the feet.
        boundaries: (P + 1,) increasing frame indices of the phases' boundaries.
        min_contact: shortest contact (frames) that counts as a footfall.

    Returns:
        (P,) stride length of each phase, in the input's units.
    """
    p, b = _feet_and_boundaries(foot_positions, boundaries, "footfall_strides")
    at = np.full((len(b), p.shape[1], 2), np.nan)
    for f, (runs, prints) in enumerate(footprints(p, contacts, up_axis)):  # loop over feet
        long = (runs[:, 1] - runs[:, 0]) >= min_contact
        runs, prints = runs[long], prints[long]
        if len(runs):
            gap = np.maximum(
                np.maximum(runs[None, :, 0] - b[:, None], b[:, None] - (runs[None, :, 1] - 1)), 0
            )  # (B, K)
            at[:, f] = prints[np.argmin(gap, axis=1)]
    disp = np.linalg.norm(at[1:] - at[:-1], axis=-1)  # (P, F)
    return disp.max(axis=1)
