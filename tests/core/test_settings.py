"""Every config section has one settings class, the only place its defaults are written:
the schema repeats them exactly, the shipped configs list only what differs from them, and
a section's merged config round-trips through its class (no key dropped or renamed)."""

import copy
import dataclasses
from pathlib import Path

import pytest
import yaml
from config_files import load, merged
from snakemake.utils import validate

from motionvar.config_sections import SECTIONS, settings_class
from motionvar.core.settings import Settings

ROOT = Path(__file__).resolve().parents[2]
SCHEMA_PATH = ROOT / "config" / "schema.yaml"
SCHEMA = yaml.safe_load(SCHEMA_PATH.read_text())


def validated(cfg):
    cfg = copy.deepcopy(cfg)
    validate(cfg, str(SCHEMA_PATH))
    return cfg


SHIPPED = {
    "config.yaml": lambda: load("config.yaml"),
    "ci.yaml": lambda: merged(load("config.yaml"), load("ci.yaml")),
    "seeds.yaml": lambda: merged(load("config.yaml"), load("seeds.yaml")),
    **{
        f"real/{p.name}": (lambda p=p: merged(load("config.yaml"), yaml.safe_load(p.read_text())))
        for p in sorted((ROOT / "config" / "real").glob("*.yaml"))
    },
}


def default_mismatches(schema_node, cls, where):
    """Where a schema object and a settings class disagree: keys on one side only, or a
    default written differently (the class's default is the one that counts)."""
    instance = cls()
    defaults = instance.to_dict()
    props = schema_node["properties"]
    problems = [f"{where}.{k}: in the schema, not in {cls.__name__}" for k in sorted(set(props) - set(defaults))]
    problems += [f"{where}.{k}: in {cls.__name__}, not in the schema" for k in sorted(set(defaults) - set(props))]
    hints = {f.name: f.type for f in dataclasses.fields(cls)}
    for key in sorted(set(props) & set(defaults)):
        sub = props[key]
        nested = getattr(instance, key)
        if isinstance(nested, Settings):
            problems += default_mismatches(sub, type(nested), f"{where}.{key}")
        elif "default" not in sub:
            if defaults[key] is not None:
                problems.append(f"{where}.{key}: no schema default; {cls.__name__} has {defaults[key]!r}")
        elif sub["default"] != defaults[key]:
            problems.append(
                f"{where}.{key}: schema default {sub['default']!r} != {cls.__name__} default "
                f"{defaults[key]!r} ({hints[key]})"
            )
    return problems


@pytest.mark.parametrize("section", sorted(SECTIONS))
def test_schema_defaults_are_the_settings_defaults(section):
    problems = default_mismatches(SCHEMA["properties"][section], settings_class(section), section)
    assert not problems, "\n".join(problems)


def test_a_default_written_twice_differently_fails():
    """The check above catches a schema default that differs from the class's."""
    section = "report"
    node = copy.deepcopy(SCHEMA["properties"][section])
    node["properties"]["animation_fps"]["default"] = 24
    assert default_mismatches(node, settings_class(section), section) == [
        "report.animation_fps: schema default 24 != ReportSettings default 20 (float)"
    ]


def leaf_items(d, where=""):
    for k, v in d.items():
        if isinstance(v, dict) and v:
            yield from leaf_items(v, f"{where}{k}.")
        else:
            yield f"{where}{k}", v


@pytest.mark.parametrize("section", sorted(SECTIONS))
def test_config_yaml_lists_only_departures_from_the_defaults(section):
    """config/config.yaml writes a key of a section only where it differs from the default
    (the default is written once, in the settings class)."""
    given = load("config.yaml").get(section) or {}
    defaults = dict(leaf_items(settings_class(section)().to_dict()))
    same = [k for k, v in leaf_items(given) if k in defaults and defaults[k] == v]
    assert not same, f"config.yaml repeats the default of {section}: {same}"


@pytest.mark.parametrize("config_name", sorted(SHIPPED))
@pytest.mark.parametrize("section", sorted(SECTIONS))
def test_merged_section_round_trips_through_its_settings(config_name, section):
    """What a rule passes (the merged, validated section) is exactly what its settings hold."""
    cfg = validated(SHIPPED[config_name]())
    built = settings_class(section).from_dict(cfg[section])
    assert built.to_dict() == cfg[section]


def test_replace_reaches_into_a_subsection_by_double_underscore():
    """``replace(sub__key=...)`` changes one key of a subsection (scikit-learn's nested-parameter
    names), leaving the rest and the original as they were."""
    from motionvar.ma2010.settings import Ma2010Settings

    before = Ma2010Settings()
    after = before.replace(fig6__max_clips=3, model__structure="lower_first", seed=2)
    assert (after.fig6.max_clips, after.model.structure, after.seed) == (3, "lower_first", 2)
    assert after.fig6.unit == before.fig6.unit and before.fig6.max_clips == 0
    with pytest.raises(TypeError):
        before.replace(fig6__no_such_key=1)


def test_renamed_keys_of_a_section_and_its_subsections():
    """A section's former keys as dotted config keys, its subsections' included (the workflow
    stops a config that uses one, naming the key now)."""
    from motionvar.ma2010.settings import Ma2010Settings

    renamed = Ma2010Settings.renamed_keys()
    assert renamed["ma2010.loo_max_clips"] == "ma2010.fig6.max_clips"
    assert renamed["ma2010.sec7_4.dbn_max_parents"] == "ma2010.sec7_4.dbn_max_parents_sweep"
