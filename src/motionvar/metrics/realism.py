"""Realism statistics of a motion dataset: how much it varies, cycle to cycle, left to right,
channel by channel, subject to subject, and how noisy it is.

The same statistics are computed on the synthetic data and on captured data (the real sets),
so the generator's variation can be held against capture (docs/gait.md, "Realism"). Every
statistic is a plain function of arrays: a clip's joint positions, its foot contacts (the
preprocessing rule, :func:`motionvar.prep.contacts.detect_foot_contacts`), its local rotations.

Gait events of a walk (:func:`walk_events`): every contact of either foot that starts after
the clip's first frame and ends before its last is a footfall, located at its ankle's
footprint (the ankle's horizontal position at its lowest frame of the contact, as
:func:`motionvar.metrics.stride.footfall_strides` locates it); contacts cut by the clip's ends
are standing, not footfalls. ``trim`` more footfalls at either end can be left out (gait
initiation and termination). Steps join successive footfalls of alternating feet, strides
successive footfalls of one foot.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.signal import butter, find_peaks, sosfiltfilt

SIDES = ("left", "right")


@dataclass(frozen=True)
class WalkEvents:
    """The steady footfalls of one walk, in time order.

    Attributes:
        side: (N,) 0 left, 1 right.
        start, stop: (N,) contact frames [start, stop).
        footprint: (N, 2) horizontal ankle footprint (cm, the two floor axes).
        fps: frames per second.
    """

    side: np.ndarray
    start: np.ndarray
    stop: np.ndarray
    footprint: np.ndarray
    fps: float

    def __len__(self) -> int:
        return len(self.side)

    def alternating(self) -> np.ndarray:
        """(N - 1,) whether footfall i + 1 is of the other foot than footfall i."""
        return self.side[1:] != self.side[:-1]


def walk_events(
    positions: np.ndarray,
    contacts: tuple[np.ndarray, np.ndarray],
    ankles: tuple[int, int],
    fps: float,
    up_axis: int = 1,
    trim: int = 0,
) -> WalkEvents:
    """The footfalls of a walk (module docstring), less ``trim`` at either end.

    Args:
        positions: (T, J, 3) global joint positions in cm.
        contacts: the (T,) left and right contact masks.
        ankles: joint indices of the left and right ankle.
        fps: frames per second.
    """
    T = positions.shape[0]
    horizontal = [a for a in range(3) if a != up_axis]
    rows = []
    for side, (mask, joint) in enumerate(zip(contacts, ankles)):
        d = np.diff(np.concatenate([[0], np.asarray(mask, dtype=np.int8), [0]]))
        for a, b in zip(np.flatnonzero(d == 1), np.flatnonzero(d == -1)):
            if a == 0 or b >= T:
                continue  # a contact cut by the clip's ends: standing, not a footfall
            low = a + int(np.argmin(positions[a:b, joint, up_axis]))
            rows.append((a, b, side, positions[low, joint, horizontal]))
    rows.sort(key=lambda r: r[0])
    rows = rows[trim : len(rows) - trim]
    if not rows:
        empty = np.zeros(0, dtype=np.int64)
        return WalkEvents(empty, empty, empty, np.zeros((0, 2)), fps)
    start, stop, side, fp = zip(*rows)
    return WalkEvents(
        side=np.array(side, dtype=np.int64),
        start=np.array(start, dtype=np.int64),
        stop=np.array(stop, dtype=np.int64),
        footprint=np.array(fp, dtype=float),
        fps=fps,
    )


@dataclass(frozen=True)
class WalkCycles:
    """Steps and strides of one walk (cm, s), from its :class:`WalkEvents`.

    Attributes:
        step_length: (S,) distance along the walking direction between successive footfalls
            of alternating feet (the walking direction: from the footfall before to the one
            after, or the step itself at the ends).
        step_side: (S,) the foot that lands at the end of each step (0 left, 1 right).
        step_time: (S,) time between the two footfalls of each step.
        stride_length, stride_time: (R,) distance and time between successive footfalls of
            one foot (two steps, no missed contact between).
        stance_fraction: (R,) each stride's first contact's duration over the stride time.
        stride_frames: (R, 2) the frames of each stride's first and last footfall (contact starts).
    """

    step_length: np.ndarray
    step_side: np.ndarray
    step_time: np.ndarray
    stride_length: np.ndarray
    stride_time: np.ndarray
    stance_fraction: np.ndarray
    stride_frames: np.ndarray


def walk_cycles(events: WalkEvents) -> WalkCycles:
    """Steps and strides of a walk's footfalls (consecutive alternating footfalls only)."""
    fp, n = events.footprint, len(events)
    alt = events.alternating() if n > 1 else np.zeros(0, dtype=bool)
    steps = np.flatnonzero(alt)
    lengths = np.empty(len(steps))
    for k, i in enumerate(steps):
        before, after = max(i - 1, 0), min(i + 2, n - 1)
        direction = fp[after] - fp[before]
        norm = np.linalg.norm(direction)
        direction = direction / norm if norm > 0 else np.zeros(2)
        lengths[k] = float(np.dot(fp[i + 1] - fp[i], direction))
    strides = np.flatnonzero(alt[:-1] & alt[1:]) if n > 2 else np.zeros(0, dtype=np.int64)
    stride_time = (events.start[strides + 2] - events.start[strides]) / events.fps
    stance = (events.stop[strides] - events.start[strides]) / events.fps
    return WalkCycles(
        step_length=lengths,
        step_side=events.side[steps + 1],
        step_time=(events.start[steps + 1] - events.start[steps]) / events.fps,
        stride_length=np.linalg.norm(fp[strides + 2] - fp[strides], axis=1),
        stride_time=stride_time,
        stance_fraction=stance / stride_time if len(strides) else np.zeros(0),
        stride_frames=np.stack([events.start[strides], events.start[strides + 2]], axis=1).reshape(-1, 2),
    )


def implausible_events(
    cycles: WalkCycles,
    root: np.ndarray,
    clearance: np.ndarray,
    stance_range: tuple[float, float],
    travel_tolerance: float,
    min_clearance: float,
) -> str:
    """Why a walk's gait events are not those of a walk (``"<check>: <detail>"``), or ``""``
    when they may be.

    Contacts detected on a clip that is not a steady walk (single steps, a start and stop, a
    stylised walk, markerless jitter) give footfalls no walk has; their statistics would read as
    the walk's variability. A walk's events fail when:

    - a stride's stance fraction lies outside ``stance_range`` (walking: about 0.6 of the cycle,
      Perry & Burnfield 2010; running under 0.4, Novacheck 1998);
    - a stride's length differs from the root's horizontal travel between its footfalls by more
      than ``travel_tolerance`` of that travel (one stride carries the body one stride forward;
      a missed or spurious footfall changes the stride by about a step, half of it);
    - the toe passes lower than ``min_clearance`` (cm, negative: below its own contact height)
      in a swing (:func:`toe_clearance`): the feet were not in contact where the contacts say.

    Args:
        cycles: the walk's steps and strides.
        root: (T, 2) horizontal root position (cm).
        clearance: the walk's swing clearances of both feet (cm).
        stance_range: plausible stance fractions (lo, hi).
        travel_tolerance: plausible |stride / root travel - 1|.
        min_clearance: the lowest plausible swing clearance (cm).
    """
    stance = cycles.stance_fraction
    outside = (stance < stance_range[0]) | (stance > stance_range[1])
    if outside.any():
        return f"stance fraction: {stance[outside][0]:.2f} outside [{stance_range[0]:g}, {stance_range[1]:g}]"
    a, b = cycles.stride_frames.T
    travel = np.linalg.norm(root[b] - root[a], axis=1)
    off = np.abs(cycles.stride_length - travel) > travel_tolerance * travel
    if off.any():
        k = int(np.argmax(off))
        return f"stride against the root's travel: {cycles.stride_length[k]:.0f} cm against {travel[k]:.0f} cm"
    if len(clearance) and clearance.min() < min_clearance:
        return f"toe below its contact height: {-clearance.min():.1f} cm in a swing"
    return ""


def coefficient_of_variation(x: np.ndarray) -> float:
    """SD (ddof 1) over the mean; NaN with fewer than 3 values."""
    x = np.asarray(x, dtype=float)
    return float(np.std(x, ddof=1) / np.mean(x)) if len(x) >= 3 and np.mean(x) > 0 else float("nan")


def step_asymmetry(cycles: WalkCycles) -> float:
    """|mean left step - mean right step| (cm); NaN without two steps of each foot."""
    left, right = (cycles.step_length[cycles.step_side == s] for s in (0, 1))
    return float(abs(left.mean() - right.mean())) if len(left) >= 2 and len(right) >= 2 else float("nan")


def toe_clearance(
    toe_height: np.ndarray, contact: np.ndarray, window: tuple[float, float] = (0.25, 0.75)
) -> np.ndarray:
    """Minimum toe height above the floor in the middle of each swing (cm).

    The floor is the toe's median height over the foot's contact frames; a swing is a run of
    non-contact frames between two contacts; its clearance the lowest toe height within the
    ``window`` fraction of the swing (minimum toe clearance lies at mid-swing, Winter 1992).
    """
    contact = np.asarray(contact, dtype=bool)
    if not contact.any():
        return np.zeros(0)
    floor = float(np.median(toe_height[contact]))
    d = np.diff(np.concatenate([[1], contact.astype(np.int8), [1]]))
    out = []
    for a, b in zip(np.flatnonzero(d == -1), np.flatnonzero(d == 1)):
        if a == 0 or b >= len(contact) or b - a < 4:
            continue  # not between two contacts, or too short to have a middle
        lo, hi = a + int(window[0] * (b - a)), a + int(np.ceil(window[1] * (b - a)))
        out.append(float(toe_height[lo:hi].min() - floor))
    return np.array(out)


def high_frequency_rms(relative_positions: np.ndarray, fps: float, band_hz: tuple[float, float]) -> float:
    """RMS (cm) of joint positions relative to the root in a frequency band: capture noise.

    ``relative_positions`` (T, J, 3); a 2nd-order Butterworth band-pass, run forwards and
    backwards; the band's upper edge is cut to 0.95 of the Nyquist frequency. NaN for a clip
    too short to filter.
    """
    lo, hi = band_hz[0], min(band_hz[1], 0.95 * fps / 2.0)
    T = relative_positions.shape[0]
    if lo >= hi or T < 16:
        return float("nan")
    sos = butter(2, [lo, hi], btype="bandpass", fs=fps, output="sos")
    x = relative_positions.reshape(T, -1)
    filtered = sosfiltfilt(sos, x - x.mean(axis=0), axis=0, padlen=min(3 * 5, T - 1))
    return float(np.sqrt(np.mean(filtered**2)))


def rotation_channel_sd(rotations: np.ndarray) -> np.ndarray:
    """(J, 3) SD in degrees of each joint's three rotation channels over the frames.

    ``rotations`` (T, J, 4) local unit quaternions (w, x, y, z), frames of many clips stacked.
    A channel is a component of the rotation vector of each frame's rotation relative to the
    joint's mean rotation (the normalised mean of the quaternions, each first put in the
    hemisphere of the joint's first frame).
    """
    q = np.asarray(rotations, dtype=float)
    q = q * np.where(np.sum(q * q[:1], axis=-1, keepdims=True) < 0, -1.0, 1.0)
    mean = q.mean(axis=0)
    mean /= np.linalg.norm(mean, axis=-1, keepdims=True)
    # conj(mean) (x) q as a linear map of q: one (4, 4) matrix per joint
    w, x, y, z = mean[:, 0], -mean[:, 1], -mean[:, 2], -mean[:, 3]
    left = np.stack(
        [
            np.stack([w, -x, -y, -z], -1),
            np.stack([x, w, -z, y], -1),
            np.stack([y, z, w, -x], -1),
            np.stack([z, -y, x, w], -1),
        ],
        axis=1,
    )
    relative = np.einsum("jab,tjb->tja", left, q)
    relative *= np.where(relative[..., :1] < 0, -1.0, 1.0)  # the shorter way round
    vec = relative[..., 1:]
    sin_half = np.linalg.norm(vec, axis=-1, keepdims=True)
    angle = 2.0 * np.arctan2(sin_half, relative[..., :1])
    scale = np.divide(angle, sin_half, out=np.full_like(angle, 2.0), where=sin_half > 0)
    return np.degrees((vec * scale).std(axis=0))


def channel_classes(sd_deg: np.ndarray, static_deg: float, near_static_deg: float) -> np.ndarray:
    """'static' (SD below ``static_deg``), 'near-static' (below ``near_static_deg``) or 'moving'."""
    sd = np.asarray(sd_deg, dtype=float)
    return np.where(sd < static_deg, "static", np.where(sd < near_static_deg, "near-static", "moving"))


def speed_peaks(speed: np.ndarray, prominence: float) -> int:
    """Number of peaks of a (T,) speed profile with at least ``prominence`` × its maximum."""
    speed = np.asarray(speed, dtype=float)
    if len(speed) < 3 or speed.max() <= 0:
        return 0
    padded = np.concatenate([[0.0], speed, [0.0]])  # a peak at either end counts
    peaks, _ = find_peaks(padded, prominence=prominence * speed.max())
    return int(len(peaks))


def path_ratio(path: np.ndarray) -> float:
    """Path length over straight-line distance of a (T, 3) trajectory (1: a straight line)."""
    path = np.asarray(path, dtype=float)
    straight = np.linalg.norm(path[-1] - path[0])
    return float(np.linalg.norm(np.diff(path, axis=0), axis=1).sum() / straight) if straight > 0 else float("nan")


def within_between_ratio(values: np.ndarray, groups: np.ndarray, min_per_group: int = 2) -> float:
    """Pooled within-group SD over the SD of group means, of (N,) or (N, D) values (rows
    of D features: root-mean-square over features), over the groups of at least
    ``min_per_group`` values. NaN with fewer than 2 such groups."""
    x = np.asarray(values, dtype=float)
    x = x[:, None] if x.ndim == 1 else x
    groups = np.asarray(groups)
    labels = [g for g in np.unique(groups) if np.sum(groups == g) >= max(min_per_group, 2)]
    if len(labels) < 2:
        return float("nan")
    means = np.stack([x[groups == g].mean(axis=0) for g in labels])
    within = np.concatenate([x[groups == g] - m for g, m in zip(labels, means)])
    dof = len(within) - len(labels)
    within_sd = np.sqrt(np.sum(within**2) / (dof * x.shape[1]))
    between_sd = np.sqrt(np.sum((means - means.mean(axis=0)) ** 2) / ((len(labels) - 1) * x.shape[1]))
    return float(within_sd / between_sd) if between_sd > 0 else float("nan")
