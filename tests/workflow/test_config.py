"""Config schema: defaults are filled, unknown keys and wrong types stop the run with the
key named, and the schema stays in step with the library's option dataclasses."""

import copy
import dataclasses
import subprocess
import sys
from pathlib import Path

import pytest
import yaml
from config_files import load, merged
from jsonschema import Draft202012Validator
from snakemake.utils import validate

from motionvar.prep import PrepOptions
from motionvar.synth import SynthSpec

ROOT = Path(__file__).resolve().parents[2]
SCHEMA = str(ROOT / "config" / "schema.yaml")
SNAKEFILE = str(ROOT / "Snakefile")


def test_shipped_configs_are_valid():
    full = load("config.yaml")
    validate(full, SCHEMA)
    validate(merged(load("config.yaml"), load("ci.yaml")), SCHEMA)
    for variant in sorted((ROOT / "config" / "variants").glob("*.yaml")):
        validate(merged(load("config.yaml"), load(f"variants/{variant.name}")), SCHEMA)


def test_seeds_config_is_the_ci_config_for_five_seeds():
    """config/seeds.yaml: five synthetic datasets (seeds 0-4) compared by claims_stability,
    with exactly the reduced sizes of config/ci.yaml (so the two cannot drift apart)."""
    seeds, ci = load("seeds.yaml"), load("ci.yaml")
    validate(merged(load("config.yaml"), copy.deepcopy(seeds)), SCHEMA)
    names = [f"synthetic_s{k}" for k in range(5)]
    assert seeds["run_datasets"] == names and seeds["stability"]["datasets"] == names
    assert [seeds["datasets"][n]["seed"] for n in names] == list(range(5))
    shared = {k: v for k, v in ci.items() if k not in ("datasets", "stability")}
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


def schema_errors(config):
    schema = yaml.safe_load(Path(SCHEMA).read_text())
    return [
        f"{'.'.join(map(str, e.absolute_path))}: {e.message}" for e in Draft202012Validator(schema).iter_errors(config)
    ]


def schema_nodes(node, where="schema"):
    """(dotted place, subschema) of every dict in the schema."""
    if isinstance(node, dict):
        yield where, node
        for k, v in node.items():
            yield from schema_nodes(v, f"{where}.{k}")
    elif isinstance(node, list):
        for i, v in enumerate(node):
            yield from schema_nodes(v, f"{where}.{i}")


def bvh_entry(**keys):
    return {"datasets": {"mine": {"source": "bvh", "path": "x", "unit_cm": 1.0, **keys}}}


@pytest.mark.parametrize(
    "unit_cm, error",
    [
        (1e300, "1e+300 is greater than the maximum of 1000.0"),
        (1e-4, "0.0001 is less than the minimum of 0.001"),
        (0.0, "0.0 is less than the minimum of 0.001"),
        (1e-3, None),
        (1e3, None),
    ],
)
def test_unit_cm_is_a_physical_unit(unit_cm, error):
    """cm per BVH unit from 0.001 to 1000 (10 micrometres to 10 m): 1e300 would pass a bare > 0."""
    assert schema_errors(bvh_entry(unit_cm=unit_cm)) == ([f"datasets.mine.unit_cm: {error}"] if error else [])


def test_unit_cm_bounds_are_the_librarys():
    """The schema writes the numbers of motionvar.io.units, which the CLI's --unit-cm takes."""
    from motionvar.io.units import UNIT_CM_MAX, UNIT_CM_MIN

    unit_cm = yaml.safe_load(Path(SCHEMA).read_text())["$defs"]["bvh_dataset"]["properties"]["unit_cm"]
    assert (unit_cm["minimum"], unit_cm["maximum"]) == (UNIT_CM_MIN, UNIT_CM_MAX)


def test_every_seed_is_non_negative():
    schema = yaml.safe_load(Path(SCHEMA).read_text())
    seeds = [where for where, node in schema_nodes(schema) if "seed" in node.get("properties", {})]
    assert len(seeds) == 6, seeds
    for where, node in schema_nodes(schema):
        if "seed" in node.get("properties", {}):
            assert node["properties"]["seed"]["minimum"] == 0, where
    errors = schema_errors({"ma2010": {"seed": -1}, "datasets": {"synthetic": {"source": "synthetic", "seed": -1}}})
    assert errors == [
        "datasets.synthetic.seed: -1 is less than the minimum of 0",
        "ma2010.seed: -1 is less than the minimum of 0",
    ]


def test_patterns_end_at_the_end_of_the_text():
    """jsonschema matches `pattern` with Python's re.search, whose `$` also matches before a final
    newline: every pattern ends with `(?!\\n)$`, and a name with a trailing newline is refused."""
    schema = yaml.safe_load(Path(SCHEMA).read_text())
    patterns = {where: node["pattern"] for where, node in schema_nodes(schema) if isinstance(node.get("pattern"), str)}
    assert len(patterns) >= 7
    assert [w for w, p in patterns.items() if not (p.startswith("^") and p.endswith("(?!\\n)$"))] == []
    for name, ok in (("ab", True), ("ab\n", False), ("a/b", False), ("..", False), ("-a", False)):
        assert (schema_errors({"datasets": {name: {"source": "synthetic"}}}) == []) == ok, name
    assert schema_errors({"du2022_style": {"styles": ["old\n"]}, "du2022_graph": {"primitives": ["walk\n"]}}) != []


@pytest.mark.parametrize(
    "folder, ok",
    [
        ("results/stability_b", True),
        ("results/..", False),
        ("results/.", False),
        ("results/a/../..", False),
        ("/tmp/stability", False),
        ("results/s\n", False),
        ("stability", False),
    ],
)
def test_stability_folder_is_a_folder_of_results(folder, ok):
    assert (schema_errors({"stability": {"folder": folder}}) == []) == ok


def test_primitives_that_name_files_are_names():
    """du2022_graph, du2022_fda and du2022_style primitives become file names under results/<dataset>/models/."""
    config = {
        "du2022_graph": {
            "primitives": ["../../x"],
            "search": {"primitives": ["/abs"]},
            "synthesis": {"reach_primitive": "a/b"},
        },
        "du2022_fda": {"reconstruction": {"primitives": ["a.b"]}},
        "du2022_style": {"distance_primitive": "../x"},
    }
    assert sorted(e.split(":")[0] for e in schema_errors(config)) == [
        "du2022_fda.reconstruction.primitives.0",
        "du2022_graph.primitives.0",
        "du2022_graph.search.primitives.0",
        "du2022_graph.synthesis.reach_primitive",
        "du2022_style.distance_primitive",
    ]


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
        ("style: {gif_panel_px: 150}\n", "config key style is now du2022_style"),
        ("graph: {seed: 1}\n", "config key graph is now du2022_graph"),
        ("ma2010: {loo_max_clips: 3}\n", "config key ma2010.loo_max_clips is now ma2010.fig6.max_clips"),
        ("ma2010: {sec7_4: {dbn_max_parents: 8}}\n", "config key ma2010.sec7_4.dbn_max_parents is now"),
        ('datasets:\n  "ab\\n": {source: synthetic}\n', "config key datasets: 'ab\\n' does not match"),
        ("stability: {folder: results/..}\n", "config key stability.folder: 'results/..' does not match"),
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


def test_config_readme_is_the_schema_written_out():
    """config/README.md lists every config file kind and every key of the schema with its default
    and meaning (tools/config_doc.py writes it from config/schema.yaml)."""
    import importlib.util

    path = Path(__file__).resolve().parents[2] / "tools" / "config_doc.py"
    spec = importlib.util.spec_from_file_location("config_doc", path)
    tool = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(tool)
    schema = yaml.safe_load(tool.SCHEMA.read_text(encoding="utf-8"))
    text = tool.DOC.read_text(encoding="utf-8")
    assert text == tool.render(schema), "run python tools/config_doc.py"
    for key in ("ma2010.fig6.max_clips", "egges2004.held_out_by", "stability.marks", "datasets.<name>.unit_cm"):
        assert f"`{key}`" in text, key
