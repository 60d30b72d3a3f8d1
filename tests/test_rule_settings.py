"""What each rule passes is its config section whole: every rule with a ``settings`` param gets
exactly one merged, validated config section, which its settings class rebuilds without
dropping or renaming a key; every evaluation the library declares (motionvar.<paper>.catalog)
is one rule, made from the declaration, that passes its declared section and runs the generic
script (or its own, where it writes more) with its input set's files and loader."""

import tempfile
from pathlib import Path

import pytest

from motionvar.config_sections import SECTIONS, settings_class

ROOT = Path(__file__).resolve().parents[1]


@pytest.fixture(scope="module", params=["config.yaml", "ci.yaml"])
def workflow(request):
    """The parsed workflow (rules, config, globals) of a shipped config, without running it."""
    from snakemake.api import SnakemakeApi
    from snakemake.settings.types import ConfigSettings, OutputSettings, ResourceSettings

    configfiles = [] if request.param == "config.yaml" else [ROOT / "config" / request.param]
    with SnakemakeApi(OutputSettings(quiet={"all"})) as api:
        wf = api.workflow(
            resource_settings=ResourceSettings(cores=1),
            config_settings=ConfigSettings(configfiles=configfiles),
            snakefile=ROOT / "Snakefile",
            workdir=Path(tempfile.mkdtemp()),
        )
        yield wf._workflow


def param_names(rule):
    return list(getattr(rule.params, "_names", {}))


def test_every_settings_param_is_a_whole_section(workflow):
    """``params.settings`` is a whole section; a param named after a further section is that
    section's keys the rule reads, as the config sets them."""
    config = workflow.config
    checked = []
    for rule in workflow.rules:
        for name in param_names(rule):
            value = getattr(rule.params, name)
            if name in SECTIONS and isinstance(value, dict) and value != config[name]:
                assert value and all(config[name][k] == v for k, v in value.items()), f"rule {rule.name}: {name}"
                checked.append(rule.name)
                continue
            if name != "settings" and not (isinstance(value, dict) and name in SECTIONS):
                continue
            sections = [s for s in SECTIONS if s in config and config[s] == value]
            assert sections, f"rule {rule.name}: params.{name} is not one whole config section"
            built = settings_class(sections[0]).from_dict(value)
            assert built.to_dict() == value, f"rule {rule.name}: {sections[0]} does not round-trip"
            checked.append(rule.name)
    assert "dataset_overview" in checked and "ma2010_sec7_4" in checked


def test_every_declared_evaluation_is_one_rule(workflow):
    g = workflow.globals
    from rule_scripts import SCRIPTS, helper_module

    from motionvar.claim_catalog import EVALUATIONS

    loaders = helper_module("_evaluation").LOADERS
    assert [e.name for e in EVALUATIONS] == list(g["EVALUATIONS"]), "the workflow's evaluations are the declared ones"
    assert set(g["INPUT_SETS"]) == {e.inputs for e in EVALUATIONS} == set(loaders)
    rules = {r.name: r for r in workflow.rules}
    for d in EVALUATIONS:
        assert d.name.startswith(d.paper + "_") and d.paper in g["PAPER_CATEGORY"], (
            f"evaluation {d.name}: <paper>_<what>"
        )
        rule = rules[d.name]
        assert rule.params.settings == workflow.config[d.section], f"rule {d.name} must pass config.{d.section}"
        assert "options" not in param_names(rule), f"rule {d.name} copies config keys by hand (params.options)"
        own = d.name in g["EVALUATION_ADDITIONS"] and g["EVALUATION_ADDITIONS"][d.name].outputs
        assert rule.params.script == (d.name if own else "evaluation")
        assert (SCRIPTS / f"{rule.params.script}.py").is_file()
        assert set(rule.input.keys()) >= set(g["INPUT_SETS"][d.inputs]), f"rule {d.name}: its input set's files"


def test_every_declaration_names_functions_that_exist():
    from motionvar.claim_catalog import EVALUATIONS
    from motionvar.claims import resolve

    for d in EVALUATIONS:
        assert callable(resolve(d.measure)) and callable(resolve(d.draw)), d.name
    with pytest.raises(ValueError, match="names no function"):
        resolve("motionvar.ma2010.figures:draw_nothing")
