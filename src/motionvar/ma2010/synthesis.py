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
from ..core.quaternions import qnormalize, qslerp
from ..core.skeleton import Skeleton
from .contacts import foot_contacts
from .correspondence import retime_frames
from .postprocess import CLEANUPS, FOOT_BLEND_S, land, pin_feet, reconstruct_root


def rest_foot_heights(skeleton: Skeleton, joints: np.ndarray) -> np.ndarray:
    """Height (cm) of each of ``joints`` (one foot's, e.g. ankle and toe) above the lowest
    point of that foot (its joints and end sites) in the rest pose: their planted heights."""
    joints = np.asarray(joints, dtype=np.int64)
    pos = fk(np.tile([1.0, 0, 0, 0], (skeleton.n_joints, 1)), np.zeros(3), skeleton.offsets, skeleton.parents)
    points = [pos[j, 1] for j in joints] + [
        pos[j, 1] + skeleton.end_sites[j][1] for j in joints if j in skeleton.end_sites
    ]
    return pos[joints, 1] - min(points)


#: Minimum contact time (s) of the support foot in footskate cleanup: one double-support
#: phase, ~10 % of a ~1.0-1.1 s walking cycle (docs/gait.md: double support 2 x 10 %), the
#: span within which both feet are down and the lower one may flicker. A support phase
#: (single support plus one double support) lasts ~50 % of the cycle, a running stance
#: 30-40 % of a ~0.7 s cycle (> 0.2 s): no real support is shorter.
MIN_SUPPORT_S = 0.1


@dataclass(frozen=True)
class RootSolver:
    """How the root is recovered (Sec. 6.3): the joints of the left and the right foot
    (2, F), their planted heights (2, F), for behaviours with flight phases the flight
    threshold (cm), and the support foot's minimum contact time ``min_support_s`` (s;
    0 = the literal per-frame rule, the lower foot of every frame supports; see
    :func:`.postprocess.support_foot`). ``left_foot`` / ``right_foot`` name the joint whose
    travel measures a stride (the ankle).

    ``cleanup`` (:data:`.postprocess.CLEANUPS`): "root", the paper's footskate cleanup
    (the default, what every evaluation uses): the support foot is fixed and the root
    follows from it (:func:`.postprocess.reconstruct_root`); "root+feet": that root, then
    every foot in contact (the project's contact detection on the root-solved motion, as
    the foot-skating measure sees it) is held still by leg IK where it stands in most of
    the contact, blended in and out over ``foot_blend_s`` at the contact's ends ([KSG02],
    :func:`.postprocess.pin_feet`), so the other foot of a double support does not slide
    either."""

    skeleton: Skeleton
    feet: np.ndarray
    planted: np.ndarray
    flight_threshold: float | None = None
    min_support_s: float = MIN_SUPPORT_S
    cleanup: str = "root"
    foot_blend_s: float = FOOT_BLEND_S

    def __post_init__(self) -> None:
        if not (np.isfinite(self.min_support_s) and self.min_support_s >= 0):
            raise ValueError(f"RootSolver: min_support_s must be >= 0 s; got {self.min_support_s}")
        if self.cleanup not in CLEANUPS:
            raise ValueError(f"RootSolver: cleanup must be one of {list(CLEANUPS)}; got {self.cleanup!r}")
        if not (np.isfinite(self.foot_blend_s) and self.foot_blend_s >= 0):
            raise ValueError(f"RootSolver: foot_blend_s must be >= 0 s; got {self.foot_blend_s}")

    @property
    def left_foot(self) -> int:
        return int(self.feet[0, 0])

    @property
    def right_foot(self) -> int:
        return int(self.feet[1, 0])

    def motion(self, rotations: np.ndarray, fps: float, root_height: np.ndarray | None = None) -> Motion:
        """The motion of ``rotations`` (T, J, 4) at ``fps`` with its root recovered (and, with
        ``cleanup`` "root+feet", its feet pinned); ``root_height`` (T,) is used in flight."""
        root = reconstruct_root(
            rotations,
            self.skeleton,
            self.feet,
            self.planted,
            root_height=root_height if self.flight_threshold is not None else None,
            flight_threshold=self.flight_threshold,
            min_support_frames=int(round(self.min_support_s * fps)),
        )
        motion = Motion(skeleton=self.skeleton, root_pos=root, rotations=rotations, fps=fps)
        if self.cleanup == "root" or len(rotations) < 2:  # one frame: nothing can slide
            return motion
        contacts = foot_contacts(motion, self.feet)
        pinned = pin_feet(
            rotations, root, self.skeleton, self.feet, self.planted, contacts, int(round(self.foot_blend_s * fps))
        )
        return Motion(skeleton=self.skeleton, root_pos=root, rotations=pinned, fps=fps)


def realtime_clips(
    rotations: np.ndarray,
    key_times: np.ndarray,
    reference_keys: np.ndarray,
    fps: float,
    root_height: np.ndarray | None = None,
) -> list[tuple[np.ndarray, np.ndarray | None]]:
    """Inverse time warp (Sec. 4.2) of M clips (M, T, J, 4) to real time at ``fps``: one
    vectorised slerp over the frames of all clips (see :func:`.correspondence.retime`)."""
    M, T = rotations.shape[:2]
    sources = [retime_frames(reference_keys, key_times[m], fps) for m in range(M)]  # loop over clips: sizes only
    cuts = np.cumsum([len(f) for f in sources])[:-1]
    within = np.concatenate(sources)  # fractional frame within its clip
    clip = np.repeat(np.arange(M), [len(f) for f in sources])
    i0 = np.minimum(np.floor(within).astype(np.int64), T - 2)
    alpha = np.broadcast_to((within - i0)[:, None], (len(within), rotations.shape[2]))
    rot = qnormalize(qslerp(rotations[clip, i0], rotations[clip, i0 + 1], alpha))
    rots = np.split(rot, cuts)
    if root_height is None:
        return [(r, None) for r in rots]
    heights = np.split(root_height[clip, i0] * (1 - alpha[:, 0]) + root_height[clip, i0 + 1] * alpha[:, 0], cuts)
    return list(zip(rots, heights))


def stitch(
    clips: Sequence[tuple[np.ndarray, np.ndarray | None]],
    align_heading: bool = True,
    landing_rule: str = "significant_maximum",
) -> tuple[np.ndarray, np.ndarray | None]:
    """Concatenate real-time clips with a displacement-mapped transition into each next
    clip (Eq. 14-15, landing frame by ``landing_rule``, :func:`.postprocess.landing_frame`);
    returns rotations (T, J, 4) and the root height curve or None. Every clip is edited
    only at its start, so its last frame is the one the next clip lands from; the pieces
    are joined once at the end."""
    if not clips:
        raise ValueError("stitch: no clips")
    pieces, extras = [clips[0][0]], [clips[0][1]]
    for nxt_rot, nxt_extra in clips[1:]:  # loop over clips
        last_extra = None if extras[-1] is None else extras[-1][-1]
        rot, extra = land(
            pieces[-1][-1], nxt_rot, last_extra, nxt_extra, align_heading=align_heading, landing_rule=landing_rule
        )
        pieces[-1], extras[-1] = pieces[-1][:-1], None if extras[-1] is None else extras[-1][:-1]
        pieces.append(rot)
        extras.append(extra)
    rotations = np.concatenate(pieces, axis=0)
    extra = None if any(e is None for e in extras) else np.concatenate(extras, axis=0)
    return rotations, extra


def sequence_motion(
    rotations: np.ndarray,
    key_times: np.ndarray,
    reference_keys: np.ndarray,
    solver: RootSolver,
    fps: float,
    root_height: np.ndarray | None = None,
    landing_rule: str = "significant_maximum",
) -> Motion:
    """One motion from M predicted clips: retime, stitch (``landing_rule``: see
    :func:`.postprocess.landing_frame`), clean up footskate."""
    rot, height = stitch(
        realtime_clips(rotations, key_times, reference_keys, fps, root_height), landing_rule=landing_rule
    )
    return solver.motion(rot, fps, height)
