"""Animated GIFs of stick figures: one or more clips side by side.

Positions come from one vectorised forward-kinematics call per clip (all frames at
once); frames are resampled to ``out_fps`` (20 by default, whatever each clip's own
frame rate), each panel's camera follows its clip's root over a floor grid, and the
GIF is written atomically: a failure, or a file over ``max_bytes``, leaves no file.

Typical use::

    animate_motions("walks.gif", [m1, m2], labels=["neutral", "proud"])
"""

from __future__ import annotations

import os
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path

import imageio.v3 as iio
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.axes import Axes
from matplotlib.collections import LineCollection
from matplotlib.text import Text
from PIL import Image

from ..core.motion import Motion
from ..io.atomic import atomic_write
from .stick import bone_segments, check_positions, draw_pose, project, view_axis

MAX_GIF_BYTES = 3_000_000


def _floor_grid(xz_min: np.ndarray, xz_max: np.ndarray, ground: float, step: float) -> np.ndarray:
    """(L, 2, 3) floor lines every ``step`` cm covering the box [xz_min, xz_max]."""
    lo = np.floor(xz_min / step) * step - step
    hi = np.ceil(xz_max / step) * step + step
    lines = [[[x, ground, lo[1]], [x, ground, hi[1]]] for x in np.arange(lo[0], hi[0] + 1e-6, step)]
    lines += [[[lo[0], ground, z], [hi[0], ground, z]] for z in np.arange(lo[1], hi[1] + 1e-6, step)]
    return np.array(lines, dtype=float)


def _per_clip_lists(
    positions: Sequence[np.ndarray],
    parents: Sequence[np.ndarray],
    clip_fps: Sequence[float],
    names: Sequence[Sequence[str] | None] | None,
    labels: Sequence[str] | None,
    out_fps: float,
    max_seconds: float,
) -> tuple[list, list[str]]:
    """The joint-name lists and labels of :func:`render_frames`, one per clip (None and ""
    when not given); ValueError naming any count that does not match the clips, or a
    non-positive ``out_fps`` / ``max_seconds``."""
    n = len(positions)
    if n == 0:
        raise ValueError("render_frames: no clips")
    if not (len(parents) == len(clip_fps) == n):
        raise ValueError(f"render_frames: {n} clips but {len(parents)} parents and {len(clip_fps)} fps values")
    names = list(names) if names is not None else [None] * n
    labels = list(labels) if labels is not None else [""] * n
    if len(names) != n or len(labels) != n:
        raise ValueError(f"render_frames: {n} clips but {len(names)} name lists and {len(labels)} labels")
    if not out_fps > 0 or not max_seconds > 0:
        raise ValueError(f"render_frames: out_fps and max_seconds must be positive (got {out_fps}, {max_seconds})")
    return names, labels


def _output_times(
    positions: Sequence[np.ndarray], clip_fps: Sequence[float], out_fps: float, max_seconds: float
) -> np.ndarray:
    """Times (s) of the output frames, ``out_fps`` per second until the longest clip (or
    ``max_seconds``) ends."""
    durations = [(len(p) - 1) / f for p, f in zip(positions, clip_fps)]
    n_out = int(np.floor(min(max(durations), max_seconds) * out_fps + 1e-9)) + 1
    return np.arange(n_out) / out_fps


@dataclass
class _Panel:
    """One clip's panel: its positions (T, J, 3) and parents, the root's floor offset
    ``follow`` (T, 1, 3) the camera follows, the clip frame ``idx`` shown at each output
    frame, the projection ``view``, and the artists updated per frame."""

    pos: np.ndarray
    parents: np.ndarray
    follow: np.ndarray
    idx: np.ndarray
    view: Callable[[np.ndarray], np.ndarray]
    lines: LineCollection
    floor: LineCollection
    grid: np.ndarray
    text: Text

    def show(self, k: int, t: float) -> None:
        """Set the artists to output frame ``k`` at time ``t`` (s)."""
        f = self.idx[k]
        self.lines.set_segments(bone_segments(self.view(self.pos[f] - self.follow[f]), self.parents))
        self.floor.set_segments(self.view(self.grid - self.follow[f]))
        self.text.set_text(f"{t:4.2f} s")


def _setup_panel(
    ax: Axes,
    pos: np.ndarray,
    par: np.ndarray,
    nm: Sequence[str] | None,
    label: str,
    fps: float,
    times: np.ndarray,
    elevation_deg: float,
    azimuth_deg: float,
) -> _Panel:
    """Draw a clip's first output frame on ``ax`` (floor grid, stick figure, time stamp,
    title) with the view framed on the body, and return its :class:`_Panel`."""
    idx = np.minimum(np.round(times * fps).astype(int), len(pos) - 1)
    ground = float(pos[..., 1].min())
    height = float(pos[..., 1].max() - ground)
    root_xz = pos[:, 0, [0, 2]]
    grid = _floor_grid(root_xz.min(axis=0) - height, root_xz.max(axis=0) + height, ground, 50.0)
    # the camera follows the root over the floor: every frame is projected relative to
    # the root's horizontal position, so the body stays centred at any distance
    follow = np.zeros((len(pos), 1, 3))
    follow[:, 0, [0, 2]] = root_xz

    def view(points, axis=view_axis(pos)):
        return project(points, axis, elevation_deg, azimuth_deg)

    floor = LineCollection(view(grid - follow[idx[0]]), colors="0.85", linewidths=0.8, zorder=0)
    ax.add_collection(floor)
    lines = draw_pose(ax, view(pos[idx[0]] - follow[idx[0]]), par, nm, linewidth=2.2)
    text = ax.text(0.02, 0.02, "", transform=ax.transAxes, fontsize=7, color="0.3")
    ax.set_title(label, fontsize=8)
    ax.set_aspect("equal")
    ax.set_xticks([])
    ax.set_yticks([])
    for spine in ax.spines.values():
        spine.set_visible(False)
    half = 0.6 * height + 10.0
    bottom = view(np.array([0.0, ground, 0.0]))[1] - 0.15 * height - 5.0
    ax.set_xlim(-half, half)
    ax.set_ylim(bottom, bottom + 2 * half)
    return _Panel(pos, par, follow, idx, view, lines, floor, grid, text)


def render_frames(
    positions: Sequence[np.ndarray],
    parents: Sequence[np.ndarray],
    clip_fps: Sequence[float],
    names: Sequence[Sequence[str] | None] | None = None,
    labels: Sequence[str] | None = None,
    out_fps: float = 20.0,
    max_seconds: float = 8.0,
    panel_px: int = 260,
    elevation_deg: float = 12.0,
    azimuth_deg: float = 25.0,
) -> np.ndarray:
    """RGB frames (N, H, W, 3) of the clips side by side, ``out_fps`` frames per second.

    Args:
        positions: per clip, (T_i, J_i, 3) global joint positions in cm, y up.
        parents: per clip, (J_i,) parent indices.
        clip_fps: per clip, its frame rate.
        names: per clip, joint names (left limbs blue, right red) or None.
        labels: per clip, a panel title.
        max_seconds: the animation stops after this long; shorter clips hold their
            last pose until the longest (or ``max_seconds``) ends.
        panel_px: width and height of one panel in pixels.
    """
    names, labels = _per_clip_lists(positions, parents, clip_fps, names, labels, out_fps, max_seconds)
    n = len(positions)
    positions = [check_positions(p, np.asarray(par)) for p, par in zip(positions, parents)]
    times = _output_times(positions, clip_fps, out_fps, max_seconds)

    dpi = 100
    fig, axes = plt.subplots(1, n, squeeze=False, figsize=(n * panel_px / dpi, panel_px / dpi), dpi=dpi)
    panels = [
        _setup_panel(ax, pos, np.asarray(par), nm, label, fps, times, elevation_deg, azimuth_deg)
        for ax, pos, par, nm, label, fps in zip(axes[0], positions, parents, names, labels, clip_fps)
    ]
    fig.subplots_adjust(left=0.01, right=0.99, bottom=0.01, top=0.9, wspace=0.04)

    frames = []
    for k, t in enumerate(times):
        for panel in panels:
            panel.show(k, t)
        fig.canvas.draw()
        frames.append(np.asarray(fig.canvas.buffer_rgba())[..., :3].copy())
    plt.close(fig)
    return np.stack(frames)


def quantize_frames(frames: np.ndarray, colors: int = 32) -> np.ndarray:
    """RGB frames mapped onto one shared palette of ``colors`` colours, without dithering.

    Stick figures on white need few colours; one palette for all frames (instead of one
    per frame, with dithered anti-aliasing) halves the GIF's size and avoids flicker.
    """
    sample = np.concatenate(frames[:: max(1, len(frames) // 10)], axis=0)
    palette = Image.fromarray(sample).quantize(colors=colors, method=Image.Quantize.MEDIANCUT)
    return np.stack(
        [
            np.asarray(Image.fromarray(f).quantize(palette=palette, dither=Image.Dither.NONE).convert("RGB"))
            for f in frames
        ]
    )


def write_gif(path: str | Path, frames: np.ndarray, fps: float = 20.0, max_bytes: int = MAX_GIF_BYTES) -> int:
    """Write RGB frames (N, H, W, 3) as a looping GIF (32 shared colours, see
    :func:`quantize_frames`); returns its size in bytes.

    Atomic: the GIF appears at ``path`` only when complete and at most ``max_bytes``
    large (ValueError otherwise, naming the file and its size).
    """
    path = Path(path)
    size = 0

    def write(tmp: Path) -> None:
        nonlocal size
        iio.imwrite(tmp, quantize_frames(np.asarray(frames)), extension=".gif", duration=1000.0 / fps, loop=0)
        size = os.path.getsize(tmp)
        if size > max_bytes:
            raise ValueError(
                f"{path}: GIF would be {size / 1e6:.1f} MB, over the {max_bytes / 1e6:.1f} MB limit "
                "(show fewer clips, fewer seconds or smaller panels)"
            )

    atomic_write(path, write)
    return size


def animate_motions(
    path: str | Path,
    motions: Sequence[Motion],
    labels: Sequence[str] | None = None,
    out_fps: float = 20.0,
    max_bytes: int = MAX_GIF_BYTES,
    **render_kw,
) -> int:
    """GIF of ``motions`` side by side (keywords as :func:`render_frames`); returns bytes."""
    frames = render_frames(
        [m.positions() for m in motions],
        [m.skeleton.parents for m in motions],
        [m.fps for m in motions],
        names=[m.skeleton.names for m in motions],
        labels=labels,
        out_fps=out_fps,
        **render_kw,
    )
    return write_gif(path, frames, fps=out_fps, max_bytes=max_bytes)
