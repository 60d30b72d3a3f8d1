"""Frame intervals: boolean masks <-> (start, stop) runs, cleaning, and the metadata text of
contacts and segments as arrays and :class:`Segment` s (the text format:
:mod:`motionvar.io.intervals`), stop exclusive. All mask operations are vectorised run-length
encodings (no loop over frames).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from ..io.intervals import format_named, format_ranges, parse_named, parse_ranges


class Segment(NamedTuple):
    """A primitive: its name and frames [start, stop)."""

    name: str
    start: int
    stop: int


def mask_to_intervals(mask: np.ndarray) -> np.ndarray:
    """(K, 2) int array of the [start, stop) runs where the 1-D ``mask`` is true."""
    m = np.asarray(mask, dtype=bool)
    if m.ndim != 1:
        raise ValueError(f"mask_to_intervals: mask must be 1-D; got shape {m.shape}")
    d = np.diff(np.concatenate([[0], m.astype(np.int8), [0]]))
    return np.stack([np.flatnonzero(d == 1), np.flatnonzero(d == -1)], axis=1).astype(np.int64)


def intervals_to_mask(intervals: np.ndarray, n_frames: int) -> np.ndarray:
    """(n_frames,) boolean mask that is true inside the [start, stop) ``intervals``."""
    iv = np.asarray(intervals, dtype=np.int64).reshape(-1, 2)
    iv = np.clip(iv, 0, n_frames)
    delta = np.zeros(n_frames + 1, dtype=np.int64)
    np.add.at(delta, iv[:, 0], 1)
    np.add.at(delta, iv[:, 1], -1)
    return np.cumsum(delta[:-1]) > 0


def clean_mask(mask: np.ndarray, min_run: int, min_gap: int) -> np.ndarray:
    """Fill interior false gaps shorter than ``min_gap`` frames, then drop true runs
    shorter than ``min_run`` frames unless they touch the clip's first or last frame
    (a contact cut off by the clip's end is still a contact)."""
    m = np.asarray(mask, dtype=bool)
    iv = mask_to_intervals(m)
    if len(iv) > 1 and min_gap > 0:
        keep_break = (iv[1:, 0] - iv[:-1, 1]) >= min_gap
        starts = np.concatenate([iv[:1, 0], iv[1:, 0][keep_break]])
        stops = np.concatenate([iv[:-1, 1][keep_break], iv[-1:, 1]])
        iv = np.stack([starts, stops], axis=1)
    if len(iv) and min_run > 0:
        long = (iv[:, 1] - iv[:, 0]) >= min_run
        at_edge = (iv[:, 0] == 0) | (iv[:, 1] == len(m))
        iv = iv[long | at_edge]
    return intervals_to_mask(iv, len(m))


def parse_intervals(text: object, what: str = "intervals") -> np.ndarray:
    """(K, 2) int array from ``"start:stop;start:stop"`` (blank or NaN: no intervals;
    :func:`motionvar.io.intervals.parse_ranges`)."""
    return np.array(parse_ranges(text, what), dtype=np.int64).reshape(-1, 2)


def parse_segments(text: object, what: str = "segments") -> list[Segment]:
    """Segments from ``"name:start:stop;..."`` (frame indices, stop exclusive;
    :func:`motionvar.io.intervals.parse_named`)."""
    return [Segment(*item) for item in parse_named(text, what)]


def format_intervals(intervals: np.ndarray) -> str:
    """Inverse of :func:`parse_intervals`."""
    return format_ranges(np.asarray(intervals, dtype=np.int64).reshape(-1, 2))


def format_segments(segments: list[Segment] | list[tuple[str, int, int]]) -> str:
    """Inverse of :func:`parse_segments`."""
    return format_named(segments)
