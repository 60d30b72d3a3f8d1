"""Segmentation of clips into motion primitives at contact-state changes (Du 2022
Sec. 4.3, Fig. 4.5: "keyframes ... when a contact state transition occurs"), with the
primitive names of the synthetic data contract:

- walk: ``walk_start`` (clip start to the first heel strike), ``walk_leftStance`` (a left
  heel strike to the next heel strike, when that is a right one), ``walk_rightStance``, ``walk_end``
  (the last heel strike to the clip end). Heel strikes are contact onsets. ``walk_start``
  and ``walk_end`` need the clip to start / end standing (both feet planted and the root
  slower than ``contact_velocity_cm_s``); a clip cut mid-gait (real data) loses the
  partial step there instead.
- run: ``run_leftStance`` / ``run_rightStance`` from a landing to the next landing (flight
  included); the partial steps before the first and after the last landing are dropped.
- sidestep: ``sidestep``, one lateral step cycle from a landing of the trailing foot to
  its next landing. The trailing foot is the one opposite to the direction of travel
  along the body's left axis (from the hip joints of the map).
- pick / place: ``{b}_reach`` from the start until the hands stop at the target (the
  minimum of hand speed between the outward and the return movement), ``{b}_retrieve``
  from there to the end.
- idle: one segment ``idle`` over the whole clip.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from ..core.joint_map import JointMap
from ..core.motion import Motion
from .contacts import SIDES, FootContacts, detect_foot_contacts, joint_speeds
from .intervals import Segment
from .options import PrepOptions


def contact_onsets(contacts: FootContacts) -> tuple[np.ndarray, np.ndarray]:
    """All contact onsets of both feet in time order: (frames, sides) with sides
    "left"/"right" (heel strikes when walking, landings when running)."""
    frames = [contacts.onsets(s) for s in SIDES]
    sides = np.concatenate([np.full(len(f), s) for f, s in zip(frames, SIDES)])
    frames = np.concatenate(frames)
    order = np.argsort(frames, kind="stable")
    return frames[order], sides[order]


def step_segments(
    contacts: FootContacts, n_frames: int, prefix: str, start: bool = False, end: bool = False
) -> list[Segment]:
    """Stance segments from an onset of one foot to the next onset, which must be of the
    other foot, named by the foot that lands first: ``{prefix}_leftStance`` /
    ``{prefix}_rightStance`` (two onsets of the same foot in a row, a shuffle, make no
    stance); with ``start`` also ``{prefix}_start`` (clip start to the first onset), with
    ``end`` ``{prefix}_end`` (the last onset to the clip end)."""
    frames, sides = contact_onsets(contacts)
    segs = [
        Segment(f"{prefix}_{side}Stance", int(a), int(b))
        for a, b, side, other in zip(frames[:-1], frames[1:], sides[:-1], sides[1:])
        if b > a and side != other
    ]
    if start and len(frames):
        segs.insert(0, Segment(f"{prefix}_start", 0, int(frames[0])))
    if end and len(frames):
        segs.append(Segment(f"{prefix}_end", int(frames[-1]), n_frames))
    return [s for s in segs if s.stop > s.start]


def standing_ends(motion: Motion, contacts: FootContacts, options: PrepOptions) -> tuple[bool, bool]:
    """Whether the clip starts and ends standing: both feet planted and the root's floor
    speed below ``contact_velocity_cm_s`` on its first / last frame."""
    root = motion.root_pos * np.array([1.0, 0.0, 1.0]) * options.units_cm
    speed = joint_speeds(root, motion.fps, options.velocity_window_s)
    still = (speed < options.contact_velocity_cm_s) & contacts.left & contacts.right
    return bool(still[0]), bool(still[-1])


def trailing_foot(motion: Motion, joint_map: JointMap, positions: np.ndarray) -> str:
    """The trailing foot of a sidestep clip: "right" when the body travels towards its
    left (the right-hip -> left-hip direction), "left" otherwise."""
    hips = joint_map.indices(motion.skeleton, ["left_hip", "right_hip"])
    left_axis = positions[:, hips[0]] - positions[:, hips[1]]
    travel = motion.root_pos[-1] - motion.root_pos[0]
    lateral = float(np.sum(left_axis.mean(axis=0)[[0, 2]] * travel[[0, 2]]))
    return "right" if lateral > 0 else "left"


def sidestep_segments(contacts: FootContacts, trailing: str) -> list[Segment]:
    """One ``sidestep`` per pair of consecutive landings of the trailing foot."""
    on = contacts.onsets(trailing)
    return [Segment("sidestep", int(a), int(b)) for a, b in zip(on[:-1], on[1:])]


def hand_speed(motion: Motion, joint_map: JointMap, positions: np.ndarray, options: PrepOptions) -> np.ndarray:
    """(T,) summed speed of both hands in cm/s, box-filtered over ``hand_smooth_s``."""
    hands = joint_map.indices(motion.skeleton, ["left_hand", "right_hand"])
    speed = joint_speeds(positions[:, hands] * options.units_cm, motion.fps, options.velocity_window_s).sum(axis=1)
    w = max(options.frames(options.hand_smooth_s, motion.fps), 1)
    if w > 1:
        padded = np.pad(speed, (w // 2, w - 1 - w // 2), mode="edge")
        speed = np.convolve(padded, np.ones(w) / w, mode="valid")
    return speed


def reach_boundary(speed: np.ndarray, stop_fraction: float, rest_fraction: float) -> int:
    """Frame where the hands stop at the target, from the (T,) hand speed
    (``PrepOptions.hand_stop_fraction``, ``PrepOptions.hand_rest_fraction``).

    The reach is the first major hand movement: it starts where the speed first exceeds
    a quarter of the clip's peak speed, and its peak p1 is the fastest frame before the
    speed falls under half of it. The valley after p1 ends where the speed rises again
    by a tenth of the peak above its running minimum (the next movement: a release or
    the retrieve) once that minimum is under ``rest_fraction`` of the peak: a rise
    before the hands have slowed to rest is a corrective sub-movement towards the target
    (Meyer et al. 1988), part of the reach. Where the speed never falls that low before
    the next movement (the hands turn back without stopping), the first rise ends it.
    The hands have stopped at the first valley frame within ``stop_fraction`` of the
    peak's height above the valley's minimum: the minimum itself when they turn back at
    once, the start of the rest when they hold.
    """
    s0 = int(np.argmax(speed >= 0.25 * speed.max()))
    run_max = np.maximum.accumulate(speed[s0:])
    t1 = s0 + int(np.argmax(speed[s0:] < 0.5 * run_max)) if np.any(speed[s0:] < 0.5 * run_max) else len(speed) - 1
    p1 = s0 + int(np.argmax(speed[s0 : t1 + 1]))
    run_min = np.minimum.accumulate(speed[t1:])
    rising = speed[t1:] > run_min + 0.1 * speed[p1]
    after_rest = rising & (run_min <= rest_fraction * speed[p1])
    ends = after_rest if after_rest.any() else rising
    t2 = t1 + int(np.argmax(ends)) if ends.any() else len(speed)
    valley = speed[p1:t2]
    low = valley.min()
    return p1 + int(np.argmax(valley <= low + stop_fraction * (speed[p1] - low)))


def reach_segments(
    motion: Motion, joint_map: JointMap, positions: np.ndarray, options: PrepOptions, prefix: str
) -> list[Segment]:
    """``{prefix}_reach`` [0, b) and ``{prefix}_retrieve`` [b, T) at the hand-speed minimum b."""
    speed = hand_speed(motion, joint_map, positions, options)
    b = reach_boundary(speed, options.hand_stop_fraction, options.hand_rest_fraction)
    segs = [Segment(f"{prefix}_reach", 0, b), Segment(f"{prefix}_retrieve", b, motion.n_frames)]
    return [s for s in segs if s.stop > s.start]


def _locomotion(prefix: str, start_end: bool) -> Callable:
    def seg(motion, joint_map, positions, options):
        contacts = detect_foot_contacts(motion, joint_map, options, positions)
        start, end = standing_ends(motion, contacts, options) if start_end else (False, False)
        return step_segments(contacts, motion.n_frames, prefix, start, end)

    return seg


def _sidestep(motion, joint_map, positions, options):
    contacts = detect_foot_contacts(motion, joint_map, options, positions)
    return sidestep_segments(contacts, trailing_foot(motion, joint_map, positions))


def _reach(prefix: str) -> Callable:
    return lambda motion, joint_map, positions, options: reach_segments(motion, joint_map, positions, options, prefix)


SEGMENTERS: dict[str, Callable[[Motion, JointMap, np.ndarray, PrepOptions], list[Segment]]] = {
    "walk": _locomotion("walk", start_end=True),
    "run": _locomotion("run", start_end=False),
    "sidestep": _sidestep,
    "pick": _reach("pick"),
    "place": _reach("place"),
    "idle": lambda motion, joint_map, positions, options: [Segment("idle", 0, motion.n_frames)],
}
"""Behaviour -> segmenter(motion, joint_map, positions, options)."""

SEGMENT_NEEDS: dict[str, str] = {
    "walk": "a heel strike of one foot followed by one of the other foot (a step), or a start or end standing still",
    "run": "a landing of one foot followed by one of the other foot",
    "sidestep": "two landings of the trailing foot",
    "pick": "a hand movement to a target and back",
    "place": "a hand movement to a target and back",
    "idle": "at least 2 frames",
}
"""Behaviour -> what a clip must hold for its segmenter to find a primitive (for messages)."""


def segment_motion(
    motion: Motion, behaviour: str, joint_map: JointMap, options: PrepOptions | None = None
) -> list[Segment]:
    """Primitives (name, start, stop) of one clip of ``behaviour`` (see module docstring)."""
    if behaviour not in SEGMENTERS:
        raise ValueError(f"segmentation: unknown behaviour {behaviour!r} (known: {sorted(SEGMENTERS)})")
    if motion.n_frames < 2:
        raise ValueError(f"segmentation: the clip has {motion.n_frames} frame(s); need at least 2")
    return SEGMENTERS[behaviour](motion, joint_map, motion.positions(), options or PrepOptions())
