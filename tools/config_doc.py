"""Write config/README.md, the catalog of the configuration: the shipped config files and every
key of config/schema.yaml (the schema is the source: its descriptions and defaults, which
tests/core/test_settings.py holds equal to the settings classes), each key that one evaluation owns
marked with it (``Evaluation.own_keys``).

python tools/config_doc.py
"""

from __future__ import annotations

import json
from pathlib import Path

import yaml

ROOT = Path(__file__).resolve().parents[1]
SCHEMA = ROOT / "config" / "schema.yaml"
DOC = ROOT / "config" / "README.md"

FILES = [
    ("config.yaml", "the full replication: synthetic data at 25 subjects, every paper's evaluations (the default)"),
    ("ci.yaml", "merged over config.yaml: the same pipeline at reduced sizes (CI and the end-to-end tests)"),
    ("seeds.yaml", "the reduced pipeline for five seeds and the claims' stability across them"),
    ("seeds_full.yaml", "the full size for five seeds (README Results)"),
    ("real/<set>.yaml", "one public captured set each (docs/real-data.md), merged over config.yaml"),
    ("variants/<name>.yaml", "a reading of a paper other than the default, merged over a config"),
    ("joint_maps/<rig>.yaml", "semantic joints and joint groups of a rig (docs/own-data.md)"),
]


def _cell(text: object) -> str:
    return " ".join(str(text).split()).replace("|", "\\|")


def _default(node: dict) -> str:
    if "default" not in node or isinstance(node.get("default"), dict) and node.get("properties"):
        return ""
    return f"`{json.dumps(node['default'])}`"


def _owners() -> dict[str, str]:
    """Dotted config key -> the evaluation that owns it (the only rule given it)."""
    from motionvar.claim_catalog import EVALUATIONS

    return {f"{e.section}.{k}": e.name for e in EVALUATIONS for k in e.own_keys}


def _rows(node: dict, prefix: str, owners: dict[str, str]) -> list[str]:
    rows = []
    for key, child in node.get("properties", {}).items():
        name = f"{prefix}.{key}" if prefix else key
        meaning = _cell(child.get("description", ""))
        if name in owners:
            meaning += f" Read by `{owners[name]}` alone."
        if child.get("properties"):
            rows.append(f"| `{name}` | | {meaning} |")
            rows += _rows(child, name, owners)
        else:
            rows.append(f"| `{name}` | {_default(child)} | {meaning} |")
    return rows


def render(schema: dict) -> str:
    """The Markdown of config/README.md from the parsed schema."""
    parts = [
        "# Configuration",
        "",
        "Written from `config/schema.yaml` by `python tools/config_doc.py` (a test keeps it current).",
        "Each section's defaults are written once, in its settings class (`motionvar.config_sections`);",
        "the schema repeats them, validates every config before a run and fills what a file leaves out.",
        "A rule is passed the sections it reads (`params: settings=...`), less the keys that one evaluation",
        'owns (`Evaluation.own_keys`, marked "read by ... alone" below): an edit of such a key reruns that',
        "evaluation alone. Ma 2010's two stages before its evaluations are passed only the subsection",
        "each reads (rule ma2010_clips `ma2010.clips`, rule ma2010_model `ma2010.model`).",
        "",
        "## Files",
        "",
        "| file | what it is |",
        "|---|---|",
        *(f"| `config/{name}` | {what} |" for name, what in FILES),
        "",
    ]
    owners = _owners()
    for section, node in schema["properties"].items():
        rows = _rows(node, section, owners) if node.get("properties") else [f"| `{section}` | {_default(node)} | |"]
        if section == "datasets":  # an entry's keys, by its source
            for kind in ("synthetic_dataset", "bvh_dataset"):
                entry = schema["$defs"][kind]
                rows.append(f"| `datasets.<name>` ({kind.split('_')[0]}) | | {_cell(entry.get('description', ''))} |")
                rows += _rows(entry, "datasets.<name>", owners)
        parts += [
            f"## `{section}`",
            "",
            _cell(node.get("description", "")),
            "",
            "| key | default | meaning |",
            "|---|---|---|",
            *rows,
            "",
        ]
    return "\n".join(parts)


if __name__ == "__main__":
    DOC.write_text(render(yaml.safe_load(SCHEMA.read_text(encoding="utf-8"))), encoding="utf-8")
    print(f"{DOC}: written")
