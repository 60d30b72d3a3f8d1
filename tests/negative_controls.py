"""Negative controls of the claims (docs/claims.md): for every ``replication`` and ``stand-in``
claim, an input on which the paper's statement is false, run through the claim's verdict function;
the verdict must be ``not reproduced``. Each ``tests/test_controls_<part>.py`` holds a dict
``CONTROLS`` (claim id -> a function building the measurements of such an input) and calls
:func:`check_control`; ``tests/test_claim_catalog.py`` checks that every such claim has one."""

from __future__ import annotations

import importlib
import sys
from collections.abc import Callable, Mapping
from pathlib import Path
from typing import Any

from motionvar.claim_catalog import spec

Control = Callable[[], Mapping[str, Any]]


def check_control(claim_id: str, control: Control) -> None:
    """The claim judged on its negative control is ``not reproduced``."""
    claim = spec(claim_id).claim(control())
    assert claim.verdict == "not reproduced", (claim_id, claim.verdict, claim.measured)


def control_claim(claim_id: str):
    """The claim judged on its negative control (from the control module that holds it)."""
    (module,) = all_controls()[claim_id]
    return spec(claim_id).claim(importlib.import_module(module).CONTROLS[claim_id]())


def all_controls() -> dict[str, list[str]]:
    """claim id -> the control modules (``test_controls_*``) that hold a control for it."""
    found: dict[str, list[str]] = {}
    for path in sorted(Path(__file__).parent.rglob("test_controls_*.py")):
        if str(path.parent) not in sys.path:  # pytest puts a test's folder there when it collects it
            sys.path.insert(0, str(path.parent))
        module = importlib.import_module(path.stem)
        for claim_id in module.CONTROLS:
            found.setdefault(claim_id, []).append(path.stem)
    return found
