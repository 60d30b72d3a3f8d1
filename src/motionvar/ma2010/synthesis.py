"""From predicted clips to motions (Ma et al. 2010, Sec. 6 and 6.3): inverse time warp of
each clip to real time, transitions between consecutive clips (Eq. 14-15) and footskate
cleanup for the root. Shared by every clip-based method (ours, RBF, plain Kriging) and by
the pose-based baselines, so that all are post-processed alike.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from ..core.kinematics import fk
from ..core.motion import Motion
from ..core.skeleton import Skeleton
from .correspondence import retime
from .postprocess import reconstruct_root, transition


def rest_foot_height(skeleton: Skeleton, ankle: int, toe: int) -> float:
    """Height of the ankle above the lowest point of its foot in the rest pose (cm): the
    ankle's height when the foot is planted flat."""
    pos = fk(np.tile([1.0, 0, 0, 0], (skeleton.n_joints, 1)), np.zeros(3), skeleton.offsets, skeleton.parents)
    lowest = [pos[ankle, 1], pos[toe, 1]]
    if toe in skeleton.end_sites:
        lowest.append(pos[toe, 1] + skeleton.end_sites[toe][1])
    return float(pos[ankle, 1] - min(lowest))


@dataclass(frozen=True)
class RootSolver:
    """How the root is recovered (Sec. 6.3): the foot joints compared, the planted foot
    height and, for behaviours with flight phases, the flight threshold (cm)."""

    skeleton: Skeleton
    left_foot: int
    right_foot: int
    foot_height: float
    flight_threshold: float | None = None

    def motion(self, rotations: np.ndarray, fps: float, root_height: np.ndarray | None = None) -> Motion:
        root = reconstruct_root(
            rotations, self.skeleton, self.left_foot, self.right_foot, self.foot_height,
            root_height=root_height if self.flight_threshold is not None else None,
            flight_threshold=self.flight_threshold,
        )
        return Motion(skeleton=self.skeleton, root_pos=root, rotations=rotations, fps=fps)


def realtime_clips(
    rotations: np.ndarray, key_times: np.ndarray, reference_keys: np.ndarray, fps: float, root_height: np.ndarray | None = None
) -> list[tuple[np.ndarray, np.ndarray | None]]:
    """Inverse time warp (Sec. 4.2) of M clips (M, T, J, 4) to real time at ``fps``."""
    out = []
    for m in range(len(rotations)):  # loop over clips
        h = None if root_height is None else root_height[m]
        out.append(retime(rotations[m], reference_keys, key_times[m], fps, h))
    return out


def stitch(clips: Sequence[tuple[np.ndarray, np.ndarray | None]], align_heading: bool = True) -> tuple[np.ndarray, np.ndarray | None]:
    """Concatenate real-time clips with a displacement-mapped transition into each next
    clip (Eq. 14-15); returns rotations (T, J, 4) and the root height curve or None."""
    if not clips:
        raise ValueError("stitch: no clips")
    rot, extra = clips[0]
    for nxt_rot, nxt_extra in clips[1:]:  # loop over clips
        rot, extra = transition(rot, nxt_rot, extra, nxt_extra, align_heading=align_heading)
    return rot, extra


def sequence_motion(
    rotations: np.ndarray,
    key_times: np.ndarray,
    reference_keys: np.ndarray,
    solver: RootSolver,
    fps: float,
    root_height: np.ndarray | None = None,
) -> Motion:
    """One motion from M predicted clips: retime, stitch, clean up footskate."""
    rot, height = stitch(realtime_clips(rotations, key_times, reference_keys, fps, root_height))
    return solver.motion(rot, fps, height)
