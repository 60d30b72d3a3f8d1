"""The shipped config files as the tests read them, and Snakemake's merge of one over another."""

import copy
from pathlib import Path

import yaml

ROOT = Path(__file__).resolve().parents[1]


def load(name):
    return yaml.safe_load((ROOT / "config" / name).read_text())


def merged(base, over):
    """Snakemake's merge of a --configfile over the workflow's configfile."""
    out = copy.deepcopy(base)
    for k, v in over.items():
        out[k] = merged(out[k], v) if isinstance(v, dict) and isinstance(out.get(k), dict) else v
    return out
