"""Running rule scripts outside Snakemake, for tests of the adapters themselves (error
lines, no partial outputs): a stand-in for Snakemake's ``snakemake`` object, and loading
``workflow/scripts/<name>.py`` and its shared ``_rule`` module by file path (scripts
import ``_rule`` as Snakemake runs them: from their own folder)."""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path
from types import ModuleType

SCRIPTS = Path(__file__).resolve().parents[1] / "workflow" / "scripts"


def _load(name: str, module_name: str) -> ModuleType:
    spec = importlib.util.spec_from_file_location(module_name, SCRIPTS / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)  # no `snakemake` global: a script only defines main()
    return module


def rule_module() -> ModuleType:
    """``workflow/scripts/_rule.py``, registered as ``_rule`` for the scripts' imports."""
    if "_rule" not in sys.modules:
        sys.modules["_rule"] = _load("_rule", "_rule")
    return sys.modules["_rule"]


def helper_module(name: str) -> ModuleType:
    """A paper's loader module ``workflow/scripts/_<paper>.py``, registered under its
    name for the scripts' imports."""
    if name not in sys.modules:
        sys.modules[name] = _load(name, name)
    return sys.modules[name]


def script(name: str) -> ModuleType:
    """The rule script ``workflow/scripts/<name>.py`` as a module (call its ``main``); for a
    declared evaluation without a script of its own, ``evaluation.py`` (the stand-in's ``rule``
    names the evaluation)."""
    rule_module()
    helper_module("_evaluation")
    if not (SCRIPTS / f"{name}.py").exists():
        name = "evaluation"
    return _load(name, f"script_{name}")


def run(snakemake, main) -> None:
    """``_rule.run``: log, and turn bad input into one error line and exit status 1."""
    rule_module().run(snakemake, main)


class Named(list):
    """Snakemake's named lists: a list whose entries may also be attributes."""

    def __init__(self, items=(), **named):
        super().__init__([*items, *named.values()])
        self._named = named
        self.__dict__.update(named)

    def items(self):
        return self._named.items()


class FakeSnakemake:
    """The parts of the ``snakemake`` object a rule script reads."""

    def __init__(self, tmp_path, rule, input=None, output=None, params=None, wildcards=None, threads=1):
        self.rule = rule
        self.input = input or Named()
        self.output = output or Named()
        self.params = params or Named()
        self.wildcards = wildcards or Named(dataset="test")
        self.log = Named([str(tmp_path / f"{rule}.log")])
        self.threads = threads
