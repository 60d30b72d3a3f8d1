"""Frame intervals as metadata text (``metadata.csv`` of a dataset, the synthetic ground truth):
named, ``"name:start:stop;name:start:stop"`` (segments, idle postures and phases), and unnamed,
``"start:stop;start:stop"`` (foot contacts). Frames are indices, stop exclusive. The one place
the format is written and read (:mod:`motionvar.prep.intervals` turns ranges into masks)."""

from __future__ import annotations

from collections.abc import Iterable

import numpy as np


def _is_blank(text: object) -> bool:
    return text is None or (isinstance(text, float) and np.isnan(text)) or str(text).strip() == ""


def format_named(items: Iterable[tuple[str, int, int]]) -> str:
    """``[("pick_reach", 0, 90), ...]`` -> ``"pick_reach:0:90;..."``."""
    return ";".join(f"{name}:{int(a)}:{int(b)}" for name, a, b in items)


def format_ranges(items: Iterable[tuple[int, int]] | np.ndarray) -> str:
    """``[(0, 90), (120, 200)]`` (or a (K, 2) array) -> ``"0:90;120:200"``."""
    return ";".join(f"{int(a)}:{int(b)}" for a, b in items)


def parse_named(text: object, what: str = "segments") -> list[tuple[str, int, int]]:
    """Inverse of :func:`format_named` (blank or NaN: none); ValueError naming ``what`` and the
    item unless each is ``name:start:stop`` with a name and 0 <= start < stop."""
    if _is_blank(text):
        return []
    out = []
    for item in filter(None, (s.strip() for s in str(text).split(";"))):
        parts = item.rsplit(":", 2)
        try:
            name, start, stop = parts[0], int(parts[1]), int(parts[2])
        except (ValueError, IndexError):
            raise ValueError(f"{what}: cannot read {item!r} as 'name:start:stop' in {text!r}") from None
        if not name or not 0 <= start < stop:
            raise ValueError(f"{what}: {item!r} needs a name and 0 <= start < stop")
        out.append((name, start, stop))
    return out


def parse_ranges(text: object, what: str = "intervals") -> list[tuple[int, int]]:
    """Inverse of :func:`format_ranges` (blank or NaN: none); ValueError naming ``what`` and the
    item unless each is ``start:stop`` with 0 <= start < stop."""
    if _is_blank(text):
        return []
    out = []
    for item in filter(None, (s.strip() for s in str(text).split(";"))):
        parts = item.split(":")
        try:
            start, stop = (int(p) for p in parts)
        except ValueError:
            raise ValueError(f"{what}: cannot read {item!r} as 'start:stop' in {text!r}") from None
        if not 0 <= start < stop:
            raise ValueError(f"{what}: interval {item!r} needs 0 <= start < stop")
        out.append((start, stop))
    return out
