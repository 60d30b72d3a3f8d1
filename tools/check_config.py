"""Check config files before a run: YAML syntax (naming the file, line and column) and the
schema (naming the key), as the workflow will see them merged over config/config.yaml.

    python tools/check_config.py config/real/xia.yaml [more.yaml ...]

Snakemake reads files given with --configfile before the workflow starts, and its own
message for a YAML syntax error names neither the file nor the line: run this first.
"""

from __future__ import annotations

import sys
from pathlib import Path

import jsonschema
import yaml

ROOT = Path(__file__).resolve().parents[1]


def load(path: Path) -> dict:
    try:
        data = yaml.safe_load(path.read_text(encoding="utf-8"))
    except OSError as exc:
        raise SystemExit(f"{path}: cannot read ({exc.strerror or exc})") from None
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        where = f"{path}:{mark.line + 1}:{mark.column + 1}" if mark is not None else str(path)
        raise SystemExit(f"{where}: not valid YAML ({getattr(exc, 'problem', None) or exc})") from None
    if data is not None and not isinstance(data, dict):
        raise SystemExit(f"{path}: a config file is a mapping of keys, got {type(data).__name__}")
    return data or {}


def merge(base: dict, extra: dict) -> dict:
    out = dict(base)
    for key, value in extra.items():
        out[key] = merge(out[key], value) if isinstance(value, dict) and isinstance(out.get(key), dict) else value
    return out


def main(paths: list[str]) -> None:
    config = load(ROOT / "config" / "config.yaml")
    for p in paths:
        config = merge(config, load(Path(p)))
    schema = yaml.safe_load((ROOT / "config" / "schema.yaml").read_text())
    errors = sorted(jsonschema.Draft202012Validator(schema).iter_errors(config), key=lambda e: list(e.absolute_path))
    if errors:
        err = errors[0]
        raise SystemExit(f"config key {'.'.join(map(str, err.absolute_path)) or '(top level)'}: {err.message}")
    print(f"ok: {', '.join(paths) or 'config/config.yaml'}")


if __name__ == "__main__":
    main(sys.argv[1:])
