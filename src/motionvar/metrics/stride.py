"""Stride length per support phase (Ma et al. 2010, Sec. 7.1-7.2: "the stride lengths of
the left support phase and the right support phase are the two elements of a style
parameter for the walking behavior").

During a single-support phase the stance foot stays put and the swing foot travels from
behind the body to in front of it: its horizontal displacement is one stride (two steps,
docs/gait.md). The swing foot is the one that moves more between the phase's boundaries.

Two ways to find where a foot stands at a boundary:

- :func:`footfall_strides` (what the Ma 2010 evaluations use): the footprint of the foot's
  contact nearest to the boundary, from contact masks; a phase's stride is then the
  distance between two footfalls of the swing foot, as the generator defines it
  (tests/synth/test_synth_locomotion.py). With two joints per foot (ankle and toe) each footfall
  is located by the joint that is down at both of the phase's ends: a walking cycle cut at
  its key frames (legs farthest apart) starts with the trailing foot rolling off its toe,
  its heel already up, and ends with the leading foot on its heel, its toe not yet down.
- :func:`stride_lengths`: the foot's stillest frame within a window around the boundary.
  At the key frames of a walking cycle the trailing foot is already rolling off its toes,
  and a cycle cut at that key frame has no frames before it: this measure of the ankle then
  comes out 2-7 % short (left support 130.6 cm on a cut generator cycle, 137.0 on the uncut
  walk, generator 140.7 cm). Kept for comparison.
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


def _contact_runs(contacts: np.ndarray, min_contact: int) -> np.ndarray:
    """(K, 2) [start, stop) runs of a (T,) contact mask at least ``min_contact`` frames long."""
    d = np.diff(np.concatenate([[0], np.asarray(contacts, dtype=np.int8), [0]]))
    runs = np.stack([np.flatnonzero(d == 1), np.flatnonzero(d == -1)], axis=1)
    return runs[(runs[:, 1] - runs[:, 0]) >= min_contact]


def footfall_strides(
    foot_positions: np.ndarray,
    contacts: np.ndarray,
    boundaries: np.ndarray,
    min_contact: int = 1,
    up_axis: int = 1,
    planted: np.ndarray | None = None,
    joint_tolerance: float = 0.0,
) -> np.ndarray:
    """Stride of each phase between the footfalls of the swing foot.

    At each boundary a foot stands on its contact nearest to the boundary (the one holding
    it, else the one with the fewest frames between them: at a walk's key frames, legs
    farthest apart, the trailing foot has just left or is leaving the ground and the leading
    foot has just landed or is about to). Within that contact each joint of the foot has a
    footprint, its horizontal position in the contact's frame where the joint is lowest (a
    planted heel: the ankle stands still from heel strike to heel-off). A foot's displacement
    over a phase is that of its first joint (the ankle), unless another joint is down at both
    ends of the phase and the first is not: the joint whose higher footprint of the two (height
    above ``planted``) is the lowest, the first one while it is within ``joint_tolerance`` of
    that (a walking cycle cut at its first key frame starts with the trailing foot on its toe,
    its heel already up). A phase's stride is the larger displacement of the feet (the stance
    foot's is ~0). Contacts shorter than ``min_contact`` frames are no footfalls (a swing foot
    grazing the floor). NaN where a foot has no footfall at all.

    Args:
        foot_positions: (T, F, 3) one joint per foot (F >= 2, e.g. the two ankles), or
            (T, F, K, 3) K joints per foot (e.g. ankle and toe).
        contacts: (T, F) boolean contact masks of the feet.
        boundaries: (P + 1,) increasing frame indices of the phases' boundaries.
        min_contact: shortest contact (frames) that counts as a footfall.
        up_axis: index of the vertical axis.
        planted: (F, K) height of each joint when its foot stands flat (default 0).
        joint_tolerance: how much lower (input units) another joint must stand than the first
            for its footprints to be used.

    Returns:
        (P,) stride length of each phase, in the input's units.
    """
    p = np.asarray(foot_positions, dtype=float)
    p = p[:, :, None] if p.ndim == 3 else p
    if p.ndim != 4:
        raise ValueError(f"footfall_strides: foot_positions must be (T, F, 3) or (T, F, K, 3); got {p.shape}")
    _, b = _feet_and_boundaries(p[:, :, 0], boundaries, "footfall_strides")
    T, F, K = p.shape[:3]
    c = np.asarray(contacts, dtype=bool)
    if c.shape != (T, F):
        raise ValueError(f"footfall_strides: contacts must be (T, F) = {(T, F)}; got {c.shape}")
    rest = np.zeros((F, K)) if planted is None else np.broadcast_to(np.asarray(planted, dtype=float), (F, K))
    height = p[..., up_axis] - rest[None]  # (T, F, K)
    horizontal = p[..., [a for a in range(3) if a != up_axis]]  # (T, F, K, 2)
    disp = np.full((len(b) - 1, F), np.nan)
    for f in range(F):  # loop over feet
        runs = _contact_runs(c[:, f], min_contact)
        if not len(runs):
            continue
        gap = np.maximum(np.maximum(runs[None, :, 0] - b[:, None], b[:, None] - (runs[None, :, 1] - 1)), 0)
        near = runs[np.argmin(gap, axis=1)]  # (B, 2): the contact each boundary stands on
        low = np.stack([s + np.argmin(height[s:e, f], axis=0) for s, e in near])  # (B, K), loop over boundaries
        h = np.take_along_axis(height[:, f], low, axis=0)  # (B, K)
        prints = horizontal[low, f, np.arange(K)[None, :]]  # (B, K, 2)
        worst = np.maximum(h[:-1], h[1:])  # (P, K): the higher footprint of each joint
        joint = np.argmax(worst <= worst.min(axis=1, keepdims=True) + joint_tolerance, axis=1)
        phase = np.arange(len(joint))
        disp[:, f] = np.linalg.norm(prints[phase + 1, joint] - prints[phase, joint], axis=-1)
    return disp.max(axis=1)
