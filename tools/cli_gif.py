"""Render BVH files (e.g. the output of the ``motionvar`` command) as one animated GIF of
stick figures side by side (motionvar.plots.render_frames: any rig; the camera follows
each clip's root), optionally also one frame as PNG to look at.

    python tools/cli_gif.py walk.bvh idle.bvh --out docs/generated.gif --seconds 4 --png frame.png
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # a script: it chooses the backend (the library never does)

import numpy as np  # noqa: E402
from PIL import Image  # noqa: E402

from motionvar.io.bvh import BVHError, read_bvh  # noqa: E402
from motionvar.plots import render_frames, write_gif  # noqa: E402


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("bvh", nargs="+", help="BVH files, drawn side by side")
    ap.add_argument("--out", required=True, help="GIF to write")
    ap.add_argument("--labels", default=None, help="comma-separated panel titles (default: the file names)")
    ap.add_argument("--unit-cm", type=float, default=1.0, help="centimetres per BVH length unit (default 1)")
    ap.add_argument("--seconds", type=float, default=4.0, help="at most this long (default 4 s)")
    ap.add_argument("--start", type=float, default=0.0, help="start this many seconds into each clip (default 0)")
    ap.add_argument("--fps", type=float, default=12.0, help="GIF frame rate (default 12)")
    ap.add_argument("--panel-px", type=int, default=200, help="panel width and height in pixels (default 200)")
    ap.add_argument("--max-kb", type=int, default=1000, help="refuse a GIF larger than this (default 1000 kB)")
    ap.add_argument("--png", default=None, help="also write the GIF's middle frame as this PNG")
    args = ap.parse_args(argv)
    try:
        motions = [read_bvh(p, scale=args.unit_cm) for p in args.bvh]
    except BVHError as exc:
        print(f"cli_gif: error: {exc}", file=sys.stderr)
        return 2
    labels = args.labels.split(",") if args.labels else [Path(p).stem for p in args.bvh]
    if len(labels) != len(motions):
        print(f"cli_gif: error: {len(labels)} labels for {len(motions)} files", file=sys.stderr)
        return 2
    clips = [m.slice(min(int(round(args.start * m.fps)), m.n_frames - 2), m.n_frames) for m in motions]
    frames = render_frames(
        [m.positions() for m in clips],
        [m.skeleton.parents for m in clips],
        [m.fps for m in clips],
        names=[m.skeleton.names for m in clips],
        labels=labels,
        out_fps=args.fps,
        max_seconds=args.seconds,
        panel_px=args.panel_px,
    )
    try:
        size = write_gif(args.out, frames, fps=args.fps, max_bytes=args.max_kb * 1000)
    except ValueError as exc:
        print(f"cli_gif: error: {exc}", file=sys.stderr)
        return 2
    if args.png:
        Image.fromarray(np.asarray(frames[len(frames) // 2])).save(args.png)
    print(f"{args.out}: {len(frames)} frames, {size / 1000:.0f} kB")
    return 0


if __name__ == "__main__":
    sys.exit(main())
