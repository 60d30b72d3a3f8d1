"""Config section -> its settings class (the one place each section's defaults are written).

Rule scripts build every section's settings through one door, ``_rule.config_settings(snakemake,
section)``, which calls :func:`section_settings` with the section's merged config (passed whole as
the rule's ``params.settings``, or as ``params.<section>`` for a section beside the rule's own); ``tests/core/test_settings.py`` holds every class to the schema in
``config/schema.yaml``. The classes are imported on first use, so that a rule loads only its
own paper's package."""

from __future__ import annotations

import importlib
from typing import Any

# section -> "module:Class"
SECTIONS: dict[str, str] = {
    "prep": "motionvar.prep.options:PrepOptions",
    "report": "motionvar.report.settings:ReportSettings",
    "realism": "motionvar.realism.settings:RealismSettings",
    "ma2010": "motionvar.ma2010.settings:Ma2010Settings",
    "egges2004": "motionvar.egges2004.settings:Egges2004Settings",
    "du2022_fda": "motionvar.du2022.fda.settings:FdaSettings",
    "du2022_graph": "motionvar.du2022.graph.settings:GraphSettings",
    "du2022_style": "motionvar.du2022.style.settings:StyleSettings",
}


def settings_class(section: str) -> type:
    """The settings class of a config section."""
    if section not in SECTIONS:
        raise KeyError(f"no settings class for config section {section!r} (known: {', '.join(SECTIONS)})")
    module, name = SECTIONS[section].split(":")
    return getattr(importlib.import_module(module), name)


def section_settings(section: str, values: dict[str, Any] | None) -> Any:
    """The settings object of ``section`` built from its config mapping."""
    return settings_class(section).from_dict(values)
