"""What the claims of every chapter of Du 2022 share."""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

Measurements = Mapping[str, Any]


def _share(n_ok: float, n: int) -> float:
    return n_ok / n if n else float("nan")


def _first_min(values: Mapping[str, float]) -> str | None:
    """The key of the smallest value (the first of ties; NaN skipped, as pandas' idxmin)."""
    valid = {k: v for k, v in values.items() if not math.isnan(v)}
    return min(valid, key=valid.get) if valid else None
