"""Config schema: defaults are filled, unknown keys and wrong types stop the run with the
key named, and the schema stays in step with the library's option dataclasses."""

import copy
import dataclasses
import subprocess
import sys
from pathlib import Path

import pytest
import yaml
from snakemake.utils import validate

from motionvar.prep import PrepOptions
from motionvar.synth import SynthSpec

ROOT = Path(__file__).resolve().parents[1]
SCHEMA = str(ROOT / "config" / "schema.yaml")
SNAKEFILE = str(ROOT / "Snakefile")


def load(name):
    return yaml.safe_load((ROOT / "config" / name).read_text())


def merged(base, over):
    """Snakemake's merge of a --configfile over the workflow's configfile."""
    out = copy.deepcopy(base)
    for k, v in over.items():
        out[k] = merged(out[k], v) if isinstance(v, dict) and isinstance(out.get(k), dict) else v
    return out


def test_shipped_configs_are_valid():
    full = load("config.yaml")
    validate(full, SCHEMA)
    validate(merged(load("config.yaml"), load("ci.yaml")), SCHEMA)


def test_seeds_config_is_the_ci_config_for_five_seeds():
    """config/seeds.yaml: five synthetic datasets (seeds 0-4) compared by claims_stability,
    with exactly the reduced sizes of config/ci.yaml (so the two cannot drift apart)."""
    seeds, ci = load("seeds.yaml"), load("ci.yaml")
    validate(merged(load("config.yaml"), copy.deepcopy(seeds)), SCHEMA)
    names = [f"synthetic_s{k}" for k in range(5)]
    assert seeds["run_datasets"] == names and seeds["stability"]["datasets"] == names
    assert [seeds["datasets"][n]["seed"] for n in names] == list(range(5))
    shared = {k: v for k, v in ci.items() if k != "datasets"}
    assert {k: v for k, v in seeds.items() if k not in ("datasets", "run_datasets", "stability")} == shared
    for n in names:
        assert {k: v for k, v in seeds["datasets"][n].items() if k not in ("seed", "subjects")} == {
            k: v for k, v in ci["datasets"]["synthetic"].items() if k != "subjects"
        } | {"source": "synthetic"}


def test_defaults_are_filled_per_source():
    cfg = {"datasets": {"synthetic": {"source": "synthetic"}, "mine": {"source": "bvh", "path": "x", "unit_cm": 1.0}}}
    validate(cfg, SCHEMA)
    assert cfg["run_datasets"] == ["synthetic"]
    assert cfg["datasets"]["synthetic"]["subjects"] == 25 and cfg["datasets"]["synthetic"]["seed"] == 0
    bvh = cfg["datasets"]["mine"]
    assert bvh == {
        "source": "bvh",
        "path": "x",
        "unit_cm": 1.0,
        "labels": "labels.csv",
        "drop_first_frame": False,
        "joint_map": None,
        "behaviour_aliases": {},
        "style_aliases": {},
        "neutral_style": None,
        "mixed_rigs": "skip_minority",
        "plausibility_check": True,
    }  # and none of the synthetic keys leaked in
    assert cfg["prep"] == PrepOptions().to_dict()
    assert cfg["report"]["animation_fps"] == 20


def test_every_key_has_a_description_and_objects_are_closed():
    schema = yaml.safe_load(Path(SCHEMA).read_text())
    assert schema["$schema"] == "https://json-schema.org/draft/2020-12/schema"

    def walk(node, where):
        if isinstance(node, dict):
            if node.get("type") == "object" and "properties" in node:
                # closed, or a dispatcher whose if/then branches are closed ($defs.dataset)
                assert node.get("additionalProperties") is False or "allOf" in node, (
                    f"{where}: additionalProperties must be false"
                )
                for key, sub in node["properties"].items():
                    assert "description" in sub, f"{where}.{key}: no description"
            for k, v in node.items():
                walk(v, f"{where}.{k}")

    walk(schema, "schema")


def test_prep_section_matches_prep_options():
    props = yaml.safe_load(Path(SCHEMA).read_text())["properties"]["prep"]["properties"]
    defaults = {f.name: f.default for f in dataclasses.fields(PrepOptions)}
    assert set(props) == set(defaults)
    assert {k: v["default"] for k, v in props.items()} == defaults


def test_synthetic_dataset_entry_matches_synth_spec():
    props = yaml.safe_load(Path(SCHEMA).read_text())["$defs"]["synthetic_dataset"]["properties"]
    defaults = {f.name: f.default for f in dataclasses.fields(SynthSpec)}
    assert set(props) - {"source"} == set(defaults)
    assert {k: v["default"] for k, v in props.items() if k != "source"} == defaults


def run_dry(tmp_path, config_text):
    (tmp_path / "bad.yaml").write_text(config_text)
    return subprocess.run(
        [
            sys.executable,
            "-m",
            "snakemake",
            "-s",
            SNAKEFILE,
            "-d",
            str(tmp_path),
            "--configfile",
            str(tmp_path / "bad.yaml"),
            "-n",
            "--workflow-profile",
            "none",
        ],
        capture_output=True,
        text=True,
        timeout=120,
    )


@pytest.mark.parametrize(
    "text, expected",
    [
        ("datasets:\n  synthetic: {subjectz: 3}\n", "unknown config key(s) datasets.synthetic.subjectz"),
        ("prepp: {}\n", "unknown config key(s) prepp"),
        (
            "datasets:\n  synthetic: {subjects: many}\n",
            "config key datasets.synthetic.subjects: 'many' is not of type 'integer'",
        ),
        ("prep: {heading: sideways}\n", "config key prep.heading: 'sideways' is not one of"),
        ("datasets:\n  cmu: {source: bvh, path: /data}\n", "config key datasets.cmu: 'unit_cm' is a required property"),
        ("run_datasets: [cmu]\n", "run_datasets names ['cmu'], not in datasets"),
        ("stability: {datasets: [s0, synthetic]}\n", "stability.datasets names ['s0'], not in datasets"),
        ("stability: {datasets: [synthetic]}\n", "stability.datasets needs at least 2 datasets"),
        ("idle: {seed: 1}\n", "config key idle is now egges2004"),
    ],
)
def test_bad_config_stops_the_run_naming_the_key(tmp_path, text, expected):
    result = run_dry(tmp_path, text)
    assert result.returncode != 0
    assert "Invalid configuration: " + expected in result.stdout + result.stderr
    assert not (tmp_path / "results").exists()


def test_yaml_syntax_error_names_file_and_line(tmp_path):
    """Snakemake's own message for a broken YAML config names neither file nor line: the
    workflow checks config/config.yaml itself, and tools/check_config.py any file."""
    import shutil

    root = ROOT
    bad = "datasets:\n  synthetic: {source: synthetic\n  other: 1\n"
    (tmp_path / "mine.yaml").write_text(bad)
    tool = subprocess.run(
        [sys.executable, str(root / "tools" / "check_config.py"), str(tmp_path / "mine.yaml")],
        capture_output=True,
        text=True,
    )
    assert tool.returncode != 0 and f"{tmp_path / 'mine.yaml'}:3:8: not valid YAML" in tool.stderr

    copy = tmp_path / "repo"
    shutil.copytree(root / "workflow", copy / "workflow")
    shutil.copytree(root / "config", copy / "config")
    shutil.copy(root / "Snakefile", copy / "Snakefile")
    (copy / "config" / "config.yaml").write_text(bad)
    run = subprocess.run(
        [sys.executable, "-m", "snakemake", "-n", "--workflow-profile", "none"],
        cwd=copy,
        capture_output=True,
        text=True,
    )
    assert run.returncode != 0
    assert f"Invalid configuration file {copy / 'config' / 'config.yaml'}:3:8" in run.stdout + run.stderr
