"""What each rule passes is its config section: every rule with a ``settings`` param gets
exactly one merged, validated config section (less what other evaluations own, or a stage's
subsections alone), which its settings class rebuilds without dropping or renaming a key; every evaluation the library declares (motionvar.<paper>.catalog)
is one rule, made from the declaration, that passes its declared section and runs the generic
script (or its own, where it writes more) with its input set's files and loader."""

import re
import tempfile
from pathlib import Path

import pytest

from motionvar.config_sections import SECTIONS, settings_class

ROOT = Path(__file__).resolve().parents[2]


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


# stages given only the subsections they read (section_for's ``only``): rule -> (section, the
# subsections, the functions that get its settings object: file, qualified name)
STAGES = {
    "ma2010_clips": (
        "ma2010",
        ("clips",),
        [("workflow/scripts/ma2010_clips.py", "main"), ("src/motionvar/ma2010/examples.py", "walk_cycles")],
    ),
    "ma2010_model": (
        "ma2010",
        ("model",),
        [
            ("workflow/scripts/ma2010_model.py", "main"),
            ("workflow/scripts/_ma2010.py", "load_walks"),
            ("src/motionvar/ma2010/examples.py", "WalkCycles.fit_model"),
            ("src/motionvar/ma2010/svi.py", "style_variation_model"),
        ],
    ),
}


def _given(section, rule, config):
    """Config section ``section`` as rule ``rule`` gets it: less the keys evaluations other than
    ``rule`` own, or only the subsections a stage reads (STAGES)."""
    from motionvar.claim_catalog import EVALUATIONS

    if rule in STAGES and STAGES[rule][0] == section:
        return {k: v for k, v in config[section].items() if k in STAGES[rule][1]}
    owned = {k for e in EVALUATIONS if e.section == section and e.name != rule for k in e.own_keys}
    return {k: v for k, v in config[section].items() if k not in owned}


def test_every_settings_param_is_its_section_less_what_others_own(workflow):
    """``params.settings`` is one config section less the keys that other evaluations own
    (``Evaluation.own_keys``), or a stage's subsections (STAGES); a param named after a further section is that section's keys the
    rule reads, as the config sets them."""
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
            sections = [s for s in SECTIONS if s in config and _given(s, rule.name, config) == value]
            assert sections, f"rule {rule.name}: params.{name} is not one config section as _given says"
            built = settings_class(sections[0]).from_dict(value).to_dict()
            assert {k: built[k] for k in value} == value, f"rule {rule.name}: {sections[0]} does not round-trip"
            checked.append(rule.name)
    assert "dataset_overview" in checked and "ma2010_sec7_4" in checked and "du2022_style_cvae" in checked
    assert set(STAGES) <= set(checked)
    cvae = next(r for r in workflow.rules if r.name == "du2022_style_cvae")
    assert "gif_panel_px" not in cvae.params.settings and "cvae" in cvae.params.settings


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
        given = _given(d.section, d.name, workflow.config)
        assert rule.params.settings == given, f"rule {d.name} must pass config.{d.section}"
        assert set(d.own_keys) <= set(given), f"{d.name}: own keys that config.{d.section} does not have"
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


# modules that only one evaluation runs, beside its measuring module and its own script (the
# paper's figures.py and generate.py import constants or helpers of them; neither is given settings)
ONLY_FOR = {
    "ma2010_sec7_4": ("ma2010/comparison.py",),
    "egges2004_repetition": ("egges2004/evaluations/fig7_8_extrema.py",),
}


def _attributes(path: Path) -> set[str]:
    import ast

    return {n.attr for n in ast.walk(ast.parse(path.read_text())) if isinstance(n, ast.Attribute)}


def test_an_evaluations_own_keys_are_read_by_its_code_alone():
    """A key one evaluation owns (no other rule is given it) is read, as an attribute, by no module
    of its section's package and no rule script of its paper but the evaluation's measuring module, its own
    script, the settings class and the modules only it runs (ONLY_FOR, imported by nothing else
    that a rule runs)."""
    import importlib

    from motionvar.claim_catalog import EVALUATIONS

    src, scripts = ROOT / "src" / "motionvar", ROOT / "workflow" / "scripts"
    owners = [d for d in EVALUATIONS if d.own_keys]
    assert {"ma2010_sec8", "du2022_fig5_4", "egges2004_speed"} <= {d.name for d in owners}
    for d in owners:
        settings_file = Path(importlib.import_module(settings_class(d.section).__module__).__file__)
        measure_file = Path(importlib.import_module(d.measure.partition(":")[0]).__file__)
        own = {measure_file, settings_file, scripts / f"{d.name}.py", *(src / m for m in ONLY_FOR.get(d.name, ()))}
        paper_scripts = [*scripts.glob(f"{d.paper}_*.py"), *scripts.glob("_*.py"), scripts / "evaluation.py"]
        files = [*settings_file.parent.rglob("*.py"), *paper_scripts]
        for f in files:
            if f in own:
                continue
            read = set(d.own_keys) & _attributes(f)
            assert not read, f"{f.relative_to(ROOT)} reads {sorted(read)}, which {d.name} owns"
        for helper in ONLY_FOR.get(d.name, ()):
            stem = Path(helper).stem
            users = [
                f
                for f in files
                if f not in own
                and f.name not in ("figures.py", "generate.py", "__init__.py")
                and re.search(rf"\bimport\b.*\b{stem}\b|\b{stem}\b import", f.read_text())
            ]
            assert not users, f"{helper} runs for {d.name} only, but {users} import it"


def _function(path: Path, qualname: str):
    import ast

    node = ast.parse(path.read_text())
    for part in qualname.split("."):
        node = next(n for n in ast.walk(node) if getattr(n, "name", None) == part)
    return node


def test_a_stage_reads_only_the_subsections_it_is_given():
    """The functions that get a stage's settings object (STAGES) read no other field of it, and
    pass it on to none but each other; so an edit the stage is not given cannot change it."""
    import ast

    for rule, (section, keep, functions) in STAGES.items():
        fields = set(settings_class(section).__dataclass_fields__)
        names = {q.rpartition(".")[2] for _, q in functions}
        for path, qualname in functions:
            fn = _function(ROOT / path, qualname)
            bound = {a.arg for a in fn.args.args if a.arg in ("settings", "s")}
            bound |= {
                t.id
                for n in ast.walk(fn)
                if isinstance(n, ast.Assign)
                for t in n.targets
                if isinstance(t, ast.Name) and t.id in ("settings", "s")
            }
            assert bound, f"{path}: {qualname} binds no settings object"
            read = {
                n.attr
                for n in ast.walk(fn)
                if isinstance(n, ast.Attribute) and isinstance(n.value, ast.Name) and n.value.id in bound
            }
            assert read & fields <= set(keep), f"{rule}: {qualname} reads {sorted(read & fields - set(keep))}"
            for call in (n for n in ast.walk(fn) if isinstance(n, ast.Call)):
                passed = [*call.args, *(k.value for k in call.keywords)]
                if any(isinstance(a, ast.Name) and a.id in bound for a in passed):
                    callee = getattr(call.func, "attr", getattr(call.func, "id", ""))
                    assert callee in names | {"settings"}, f"{rule}: {qualname} passes its settings to {callee}"
