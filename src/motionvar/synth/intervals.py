"""Frame intervals as text, the format of the synthetic ground truth in ``metadata.csv``.

Named intervals: ``"name:start:stop;name:start:stop"`` (segments, idle postures);
unnamed: ``"start:stop;start:stop"`` (foot contacts). Frames are indices, stop exclusive.
"""

from __future__ import annotations

from collections.abc import Iterable


def format_intervals(items: Iterable[tuple[str, int, int]]) -> str:
    """``[("pick_reach", 0, 90), ...]`` -> ``"pick_reach:0:90;..."``."""
    return ";".join(f"{name}:{int(a)}:{int(b)}" for name, a, b in items)


def format_ranges(items: Iterable[tuple[int, int]]) -> str:
    """``[(0, 90), (120, 200)]`` -> ``"0:90;120:200"``."""
    return ";".join(f"{int(a)}:{int(b)}" for a, b in items)


def parse_intervals(text: str) -> list[tuple[str, int, int]]:
    """Inverse of :func:`format_intervals`; ValueError naming the bad item."""
    out = []
    for item in filter(None, (s.strip() for s in str(text).split(";"))):
        parts = item.split(":")
        if len(parts) != 3:
            raise ValueError(f"interval {item!r}: expected name:start:stop")
        out.append((parts[0], int(parts[1]), int(parts[2])))
    return out


def parse_ranges(text: str) -> list[tuple[int, int]]:
    """Inverse of :func:`format_ranges`; ValueError naming the bad item."""
    out = []
    for item in filter(None, (s.strip() for s in str(text).split(";"))):
        parts = item.split(":")
        if len(parts) != 2:
            raise ValueError(f"range {item!r}: expected start:stop")
        out.append((int(parts[0]), int(parts[1])))
    return out
