"""Length units of BVH files: centimetres per file unit (``unit_cm``, the ``scale`` of
:func:`motionvar.io.bvh.read_bvh` and :func:`~motionvar.io.bvh.write_bvh`), and the range a
unit may lie in.

The range spans every unit a motion file uses (mm 0.1, cm 1, CMU 5.644, inch 2.54, m 100)
with a decade to spare on each side: outside it a rig is micrometres or tens of metres tall
in the file, and the numbers written lose their precision (``%.6f`` of a 1e-3 cm bone at
1e3 cm per unit is 0.000001) or grow without meaning. The CLI's ``--unit-cm`` and the
config's ``unit_cm`` (config/schema.yaml) cite these bounds.
"""

from __future__ import annotations

import math

UNIT_CM_MIN = 1e-3  # cm per BVH length unit: 10 micrometres
UNIT_CM_MAX = 1e3  # cm per BVH length unit: 10 metres


def unit_cm_problem(value: float) -> str | None:
    """Why ``value`` is not a length unit in cm (not a finite number within
    ``UNIT_CM_MIN``-``UNIT_CM_MAX``), or None when it is one."""
    try:
        ok = math.isfinite(value) and UNIT_CM_MIN <= value <= UNIT_CM_MAX
    except TypeError:
        ok = False
    if ok:
        return None
    return f"not within {UNIT_CM_MIN:g}-{UNIT_CM_MAX:g} cm per unit (cm 1, metres 100, mm 0.1, CMU 5.644)"
