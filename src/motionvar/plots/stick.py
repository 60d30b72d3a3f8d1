"""Stick figures: one skeleton pose, or key frames side by side, for any rig.

A rig is given by its ``parents`` (and optionally joint ``names`` to colour the left
side blue and the right side red); positions are global joint positions (..., J, 3) in
cm with y up, as :meth:`motionvar.core.Motion.positions` returns them.

The view is an orthographic camera: ``screen_x`` is the horizontal world direction that
points to the right of the picture (a side view of a walk uses the walking direction,
a front view of a standing person the person's left-right axis; :func:`view_axis`
picks one of the two), ``azimuth_deg`` turns the camera about the vertical axis and
``elevation_deg`` lifts it, so that left and right limbs separate.

Typical use::

    fig, ax = plt.subplots()
    plot_key_frames(ax, motion.positions(), motion.skeleton.parents, frames=[0, 20, 40],
                    names=motion.skeleton.names, fps=motion.fps)
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.axes import Axes
from matplotlib.collections import LineCollection
from matplotlib.figure import Figure

SIDE_COLOURS = {"left": "#1f77b4", "right": "#d62728", "centre": "#333333"}
"""Bone colours by body side: left blue, right red, spine and head dark grey."""


def joint_sides(names: Sequence[str] | None, n_joints: int) -> list[str]:
    """'left', 'right' or 'centre' per joint, from its name ("LeftArm", "LThumb",
    "lShldr", "l_hip", "Hand.R", "upperarm_r"...); all 'centre' when ``names`` is None."""
    if names is None:
        return ["centre"] * n_joints
    if len(names) != n_joints:
        raise ValueError(f"joint_sides: {len(names)} names for {n_joints} joints")
    sides = []
    for name in names:
        # case-sensitive single-letter prefixes ("LHipJoint") must be followed by an
        # upper-case letter, so "Leg" or "Root" are not taken for a side
        single = re.match(r"^([LRlr])(?=[A-Z_.])", name)
        if single:
            sides.append("left" if single.group(1) in "Ll" else "right")
        elif re.search(r"left|[_.]l$|^l_", name, re.IGNORECASE):
            sides.append("left")
        elif re.search(r"right|[_.]r$|^r_", name, re.IGNORECASE):
            sides.append("right")
        else:
            sides.append("centre")
    return sides


def bone_colours(parents: np.ndarray, names: Sequence[str] | None = None) -> list[str]:
    """Colour of the bone ending at each non-root joint (index j-1 for joint j)."""
    sides = joint_sides(names, len(parents))
    return [SIDE_COLOURS[sides[j]] for j in range(1, len(parents))]


def view_axis(positions: np.ndarray, min_travel_cm: float = 50.0) -> np.ndarray:
    """A horizontal unit vector (3,) for ``screen_x``.

    The root's net horizontal travel direction when it moves at least ``min_travel_cm``
    (a side view of locomotion); otherwise the direction of the body's widest horizontal
    spread in the first frame, which for a standing person is the left-right axis
    (a front view, where weight shifts show).
    """
    positions = np.asarray(positions, dtype=float)
    root = positions[..., 0, :].reshape(-1, 3)
    travel = root[-1] - root[0]
    travel[1] = 0.0
    if np.linalg.norm(travel) >= min_travel_cm:
        return travel / np.linalg.norm(travel)
    first = positions.reshape(-1, *positions.shape[-2:])[0]
    horiz = first[:, [0, 2]] - first[:, [0, 2]].mean(axis=0)
    _, _, vt = np.linalg.svd(horiz, full_matrices=False)
    axis = np.array([vt[0, 0], 0.0, vt[0, 1]])
    return axis / np.linalg.norm(axis)


def project(
    positions: np.ndarray,
    screen_x: np.ndarray | Sequence[float] = (1.0, 0.0, 0.0),
    elevation_deg: float = 0.0,
    azimuth_deg: float = 0.0,
) -> np.ndarray:
    """Orthographic projection of points (..., 3) to screen coordinates (..., 2) in cm.

    Screen x runs along ``screen_x`` turned by ``azimuth_deg`` about the vertical; screen
    y is the height, tilted by ``elevation_deg`` (camera above: nearer points lower).
    """
    sx = np.asarray(screen_x, dtype=float).copy()
    sx[1] = 0.0
    norm = np.linalg.norm(sx)
    if norm == 0:
        raise ValueError("project: screen_x must have a horizontal component")
    sx /= norm
    a = np.deg2rad(azimuth_deg)
    # rotate about y: x' = x cos a + z sin a, z' = -x sin a + z cos a
    right = np.array([sx[0] * np.cos(a) + sx[2] * np.sin(a), 0.0, -sx[0] * np.sin(a) + sx[2] * np.cos(a)])
    toward_viewer = np.cross(right, [0.0, 1.0, 0.0])
    e = np.deg2rad(elevation_deg)
    p = np.asarray(positions, dtype=float)
    x = p @ right
    y = p[..., 1] * np.cos(e) - (p @ toward_viewer) * np.sin(e)
    return np.stack([x, y], axis=-1)


def bone_segments(xy: np.ndarray, parents: np.ndarray) -> np.ndarray:
    """(..., J-1, 2, 2) line segments parent -> child from projected joints (..., J, 2)."""
    parents = np.asarray(parents)
    return np.stack([xy[..., parents[1:], :], xy[..., 1:, :]], axis=-2)


def draw_pose(
    ax: Axes,
    xy: np.ndarray,
    parents: np.ndarray,
    names: Sequence[str] | None = None,
    linewidth: float = 2.0,
    alpha: float = 1.0,
) -> LineCollection:
    """Draw one projected pose (J, 2) as bones coloured by side; returns the collection
    (update it with ``collection.set_segments(bone_segments(new_xy, parents))``)."""
    lines = LineCollection(
        bone_segments(np.asarray(xy), parents),
        colors=bone_colours(np.asarray(parents), names),
        linewidths=linewidth,
        alpha=alpha,
        capstyle="round",
        joinstyle="round",
    )
    ax.add_collection(lines)
    return lines


def check_positions(positions: np.ndarray, parents: np.ndarray) -> np.ndarray:
    """``positions`` as a float (T, J, 3) array; ValueError on a wrong shape or NaN."""
    positions = np.asarray(positions, dtype=float)
    if positions.ndim != 3 or positions.shape[-1] != 3 or positions.shape[1] != len(parents):
        raise ValueError(f"positions must be (T, {len(parents)}, 3) for {len(parents)} joints; got {positions.shape}")
    if not np.all(np.isfinite(positions)):
        raise ValueError("positions contain NaN or infinite values")
    return positions


def key_frame_spacing(positions: np.ndarray) -> float:
    """Horizontal distance between neighbouring key-frame poses: 0.7 x the body's height
    (a pose's full vertical extent over the clip), at least 40 cm."""
    y = np.asarray(positions)[..., 1]
    return max(0.7 * float(y.max() - y.min()), 40.0)


def plot_key_frames(
    ax: Axes,
    positions: np.ndarray,
    parents: np.ndarray,
    frames: Sequence[int],
    names: Sequence[str] | None = None,
    fps: float | None = None,
    screen_x: np.ndarray | Sequence[float] | None = None,
    spacing: float | None = None,
    elevation_deg: float = 0.0,
    azimuth_deg: float = 0.0,
    title: str | None = None,
    linewidth: float = 2.0,
) -> None:
    """Draw the poses of ``frames`` of one clip side by side on ``ax``.

    Each pose is shifted horizontally so that its root sits at ``k * spacing`` (the
    clip's own travel is removed, so the poses never overlap); heights are true, with
    the ground (the lowest point of the clip) drawn as a grey line. The x tick under a
    pose gives its time in seconds (``fps`` given) or its frame index. Equal aspect.

    Args:
        positions: (T, J, 3) global joint positions in cm, y up.
        parents: (J,) parent indices, -1 for the root.
        frames: frame indices to draw, left to right.
        names: joint names, to colour left (blue) and right (red) limbs.
        screen_x: horizontal world direction to the right of the picture
            (default :func:`view_axis`).
        spacing: cm between poses (default :func:`key_frame_spacing`).
    """
    parents = np.asarray(parents)
    positions = check_positions(positions, parents)
    frames = [int(f) for f in frames]
    if not frames or min(frames) < 0 or max(frames) >= len(positions):
        raise ValueError(f"frames {frames} out of range for a clip of {len(positions)} frames")
    if screen_x is None:
        screen_x = view_axis(positions)
    if spacing is None:
        spacing = key_frame_spacing(positions)
    xy = project(positions, screen_x, elevation_deg, azimuth_deg)
    ground = float(xy[..., 1].min())
    poses = xy[frames].copy()
    poses[..., 0] += (np.arange(len(frames)) * spacing - poses[:, 0, 0])[:, None]
    for pose in poses:
        draw_pose(ax, pose, parents, names, linewidth=linewidth)
    ax.axhline(ground, color="0.6", linewidth=1.0, zorder=0)
    ax.set_xticks([k * spacing for k in range(len(frames))])
    ax.set_xticklabels([f"{f / fps:.2f} s" if fps else f"frame {f}" for f in frames])
    ax.set_aspect("equal")
    # half a spacing either side, wider where a pose reaches further (a long stride)
    pad = 0.02 * spacing
    ax.set_xlim(
        min(-0.5 * spacing, poses[..., 0].min() - pad), max((len(frames) - 0.5) * spacing, poses[..., 0].max() + pad)
    )
    if title:
        ax.set_title(title, fontsize=10)


def evenly_spaced_frames(n_frames: int, n_keys: int) -> list[int]:
    """``n_keys`` frame indices spread evenly from the first to the last frame."""
    if n_frames < 1 or n_keys < 1:
        raise ValueError(f"need at least one frame and one key (got {n_frames} frames, {n_keys} keys)")
    return sorted(set(np.linspace(0, n_frames - 1, n_keys).round().astype(int).tolist()))


@dataclass
class KeyFrameRow:
    """One row of a :func:`key_frame_grid`: a clip's positions and how to label it."""

    label: str
    positions: np.ndarray
    parents: np.ndarray
    names: Sequence[str] | None = None
    fps: float | None = None
    frames: Sequence[int] | None = None

    def __post_init__(self) -> None:
        self.parents = np.asarray(self.parents)
        self.positions = check_positions(self.positions, self.parents)


def key_frame_grid(
    rows: Sequence[KeyFrameRow | None],
    n_keys: int = 5,
    columns: int = 1,
    title: str | None = None,
    row_height_in: float = 1.8,
    azimuth_deg: float = 25.0,
) -> Figure:
    """A figure of key frames, one clip per row (``columns`` blocks of rows side by side,
    filled column by column; a None row leaves its panel empty).

    All panels share one scale: the same pose spacing and the same height range, so
    body sizes and step lengths compare across rows. Frames default to ``n_keys``
    evenly spaced over each clip. The figure is as wide as the panels' equal aspect
    needs at ``row_height_in`` inches per row. The camera is turned ``azimuth_deg`` from
    :func:`view_axis` (no elevation: heights stay true) so left and right limbs separate.
    """
    drawn = [r for r in rows if r is not None]
    if not drawn:
        raise ValueError("key_frame_grid: no rows to draw")
    spacing = max(key_frame_spacing(r.positions) for r in drawn)
    low = min(float(np.min(r.positions[..., 1])) for r in drawn)
    high = max(float(np.max(r.positions[..., 1])) for r in drawn)
    pad = 0.05 * (high - low)
    ylim = (low - pad, high + pad)
    xlim = (-0.5 * spacing, (n_keys - 0.5) * spacing)
    n_rows = -(-len(rows) // columns)
    plot_h = row_height_in - 0.55  # title above, tick labels below
    plot_w = plot_h * (xlim[1] - xlim[0]) / (ylim[1] - ylim[0])
    fig, axes = plt.subplots(
        n_rows,
        columns,
        squeeze=False,
        figsize=(columns * (plot_w + 0.75), n_rows * row_height_in + (0.4 if title else 0.1)),
    )
    drawn_axes = []
    for i, row in enumerate(rows):
        ax = axes[i % n_rows, i // n_rows]
        if row is None:
            ax.set_visible(False)
            continue
        frames = row.frames if row.frames is not None else evenly_spaced_frames(len(row.positions), n_keys)
        plot_key_frames(
            ax,
            row.positions,
            row.parents,
            frames,
            names=row.names,
            fps=row.fps,
            spacing=spacing,
            azimuth_deg=azimuth_deg,
        )
        ax.set_title(row.label, fontsize=9, loc="left")
        ax.tick_params(labelsize=7)
        ax.set_ylim(*ylim)
        ax.set_ylabel("height (cm)", fontsize=7)
        xlim = (min(xlim[0], ax.get_xlim()[0]), max(xlim[1], ax.get_xlim()[1]))
        drawn_axes.append(ax)
    for ax in drawn_axes:  # one scale for all panels, wide enough for every pose
        ax.set_xlim(*xlim)
    for j in range(len(rows), n_rows * columns):
        axes[j % n_rows, j // n_rows].set_visible(False)
    if title:
        fig.suptitle(title, fontsize=11)
    fig.tight_layout()
    return fig
