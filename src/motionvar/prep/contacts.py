"""Foot-contact detection from ankle and toe velocity and height (Du 2022 Sec. 4.3:
key frames are the frames where the foot-contact state changes).

A foot is planted on a frame when its ankle or its toe joint is both *slow* (speed below
``contact_velocity_cm_s``) and *low* (less than ``contact_height_cm`` above that joint's
floor level, a low percentile of its height over the clip). The ankle catches heel
contact, the toe catches the forefoot after heel-off and forefoot landings in running.
Speeds are central differences over ``velocity_window_s`` times the frame rate, and all
lengths are multiplied by ``units_cm``, so the thresholds mean the same at any fps and in
any unit. Joints come from the :class:`JointMap`, never from CMU names.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..core.extremities import foot_points
from ..core.joint_map import JointMap
from ..core.motion import Motion
from .intervals import clean_mask, mask_to_intervals
from .options import PrepOptions

SIDES = ("left", "right")


@dataclass(frozen=True)
class FootContacts:
    """Per-foot contact masks of one clip: ``left`` and ``right`` are (T,) booleans."""

    left: np.ndarray
    right: np.ndarray
    fps: float

    def mask(self, side: str) -> np.ndarray:
        if side not in SIDES:
            raise ValueError(f"FootContacts: side must be one of {SIDES}; got {side!r}")
        return self.left if side == "left" else self.right

    def intervals(self, side: str) -> np.ndarray:
        """(K, 2) [start, stop) contact runs of one foot."""
        return mask_to_intervals(self.mask(side))

    @property
    def left_intervals(self) -> np.ndarray:
        return self.intervals("left")

    @property
    def right_intervals(self) -> np.ndarray:
        return self.intervals("right")

    def onsets(self, side: str) -> np.ndarray:
        """Frames where a contact of ``side`` begins after the first frame: heel strikes
        when walking, landings when running."""
        starts = self.intervals(side)[:, 0]
        return starts[starts > 0]


def joint_speeds(positions: np.ndarray, fps: float, window_s: float) -> np.ndarray:
    """Speeds (T, ...) of positions (T, ..., 3): central differences over ``window_s``
    (one-sided at the clip's ends), in length units per second."""
    T = positions.shape[0]
    if T < 2:
        raise ValueError(f"joint_speeds: need at least 2 frames; got {T}")
    k = max(int(round(window_s * fps / 2.0)), 1)
    t = np.arange(T)
    hi, lo = np.minimum(t + k, T - 1), np.maximum(t - k, 0)
    dt = ((hi - lo) / fps).reshape((T,) + (1,) * (positions.ndim - 2))
    return np.linalg.norm(positions[hi] - positions[lo], axis=-1) / dt


def foot_positions(positions: np.ndarray, motion: Motion, joint_map: JointMap) -> np.ndarray:
    """(T, 2 feet, 2 joints [ankle, toe], 3) positions picked from (T, J, 3) via the map; a rig
    without toe joints gives its ankles' End Sites instead (:func:`~motionvar.core.extremities.foot_points`)."""
    try:
        return foot_points(motion, joint_map, positions)
    except ValueError as exc:
        raise ValueError(f"foot contacts: {exc}") from exc


def detect_foot_contacts(
    motion: Motion,
    joint_map: JointMap,
    options: PrepOptions | None = None,
    positions: np.ndarray | None = None,
) -> FootContacts:
    """Contact masks of both feet (see the module docstring for the rule).

    Args:
        motion: the clip (y up).
        joint_map: semantic joints ``{left,right}_{ankle,toe}`` of the rig.
        options: thresholds (:class:`PrepOptions`); defaults when None.
        positions: (T, J, 3) global joint positions if already computed (saves an FK).
    """
    opt = options or PrepOptions()
    if motion.n_frames < 2:
        raise ValueError(f"foot contacts: the clip has {motion.n_frames} frame(s); need at least 2")
    pos = motion.positions() if positions is None else np.asarray(positions, dtype=float)
    feet = foot_positions(pos, motion, joint_map) * opt.units_cm  # (T, 2, 2, 3) in cm
    speed = joint_speeds(feet, motion.fps, opt.velocity_window_s)  # (T, 2, 2)
    height = feet[..., 1]
    floor = np.percentile(height, opt.floor_percentile, axis=0)  # per foot joint
    planted = ((speed < opt.contact_velocity_cm_s) & (height - floor < opt.contact_height_cm)).any(axis=2)
    min_run, min_gap = opt.frames(opt.min_contact_s, motion.fps), opt.frames(opt.min_gap_s, motion.fps)
    left, right = (clean_mask(planted[:, f], min_run, min_gap) for f in range(2))
    return FootContacts(left=left, right=right, fps=motion.fps)
