"""What the BVH reader tests share: a small file's header and frames (wrapped angles included),
writing it, and comparing rotations up to sign."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from motionvar.core import quaternions as Q

HEADER = """HIERARCHY
ROOT Hips
{
  OFFSET 0 0 0
  CHANNELS 6 Xposition Yposition Zposition Zrotation Yrotation Xrotation
  JOINT Chest
  {
    OFFSET 0 10 0
    CHANNELS 3 Zrotation Xrotation Yrotation
    JOINT Arm
    {
      OFFSET 5 0 0
      CHANNELS 6 Xposition Zposition Yposition Xrotation Yrotation Zrotation
      End Site
      {
        OFFSET 4 0 0
      }
    }
  }
  JOINT Leg
  {
    OFFSET 2 -3 0
    CHANNELS 3 Yrotation Xrotation Zrotation
    End Site
    {
      OFFSET 0 -8 0
    }
  }
}
MOTION
Frames: 3
Frame Time: 0.02
"""


# 18 channels: Hips 6, Chest 3, Arm 6 (positions x, z, y), Leg 3. Angles include wrapped ones.
FRAMES = np.array(
    [
        [1, 90, 2, 10, 20, 30, 350, 5, 15, 5.5, 0.25, -0.5, 30, 40, 50, 0, 0, 359],
        [2, 91, 3, 11, 21, 31, 359, 6, 16, 5.6, 0.25, -0.4, 31, 41, 51, 1, 2, 1],
        [3, 92, 4, 12, 22, 32, 3, 7, 17, 5.7, 0.25, -0.3, 32, 42, 52, 2, 4, 3],
    ],
    dtype=float,
)


def small_bvh(tmp_path: Path, header: str = HEADER, frames: np.ndarray | str = FRAMES, name: str = "s.bvh") -> Path:
    body = frames if isinstance(frames, str) else "\n".join(" ".join(f"{v:g}" for v in row) for row in frames) + "\n"
    path = tmp_path / name
    path.write_text(header + body)
    return path


def line_of(text: str, needle: str, nth: int = 0) -> int:
    """1-based number of the nth line containing ``needle``."""
    return [i + 1 for i, line in enumerate(text.splitlines()) if needle in line][nth]


def same_rotations(a: np.ndarray, b: np.ndarray, atol: float) -> bool:
    return bool(np.max(Q.qangle(a, b)) < atol)
