"""The package layout (docs/development.md, "Code map"): shared parts below the paper packages, imports
only downward, no paper package reaching into another, no Snakemake in the library, no
pickle and no matplotlib backend chosen at import time."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

SRC = Path(__file__).resolve().parents[2] / "src" / "motionvar"

# Level of each top-level part of motionvar: a module may import its own part and parts
# of a lower level only. The three paper packages share the top level and never import
# one another.
LEVELS = {
    "core": 0,
    "metrics": 0,
    "claims": 0,
    "io": 1,
    "applicability": 1,  # needs over a dataset's metadata and its rig's joint map (core)
    "report": 1,
    "synth": 2,
    "prep": 2,
    "models": 2,
    "plots": 2,
    "ma2010": 3,
    "du2022": 3,
    "egges2004": 3,
    "realism": 3,  # a dataset's realism table: metrics over the preprocessing's contacts
    "cli": 4,  # the `motionvar` command: glue over the papers and shared parts; nothing imports it
    "config_sections": 4,  # config section -> settings class of each paper (rule scripts, tests)
    "claim_catalog": 4,  # every paper's claim declarations (rule scripts, report, tests)
}
PAPERS = {"ma2010", "du2022", "egges2004"}


def _modules() -> list[tuple[str, Path]]:
    out = []
    for path in sorted(SRC.rglob("*.py")):
        parts = list(path.relative_to(SRC).with_suffix("").parts)
        out.append((".".join(["motionvar", *parts]), path))
    return out


def _imports(module: str, path: Path) -> list[tuple[str, int]]:
    """Absolute names of everything ``path`` imports, with line numbers."""
    tree = ast.parse(path.read_text(), filename=str(path))
    package = module.split(".")
    if path.name != "__init__.py":
        package = package[:-1]
    names = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names += [(a.name, node.lineno) for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package[: len(package) - node.level + 1]
                name = ".".join(base + ([node.module] if node.module else []))
            else:
                name = node.module or ""
            names.append((name, node.lineno))
    return names


def _part(module: str) -> str:
    return module.split(".")[1]


MODULES = _modules()


def test_every_part_has_a_level():
    parts = {_part(m) for m, p in MODULES if p.name != "__init__.py" or m.count(".") > 1}
    parts.discard("__init__")
    assert parts <= set(LEVELS), f"parts without a level in LEVELS: {sorted(parts - set(LEVELS))}"


@pytest.mark.parametrize("module,path", MODULES, ids=[m for m, _ in MODULES])
def test_imports_only_downward(module, path):
    if module == "motionvar.__init__":
        return
    own = _part(module)
    bad = []
    for name, line in _imports(module, path):
        if name.split(".")[0] == "snakemake":
            bad.append(f"line {line}: imports snakemake (library code never does)")
        if name.split(".")[0] == "pickle":
            bad.append(f"line {line}: imports pickle (models are .npz + JSON, motionvar.io.model_file)")
        if not name.startswith("motionvar.") or name == "motionvar":
            continue
        other = _part(name)
        if other == own:
            continue
        if own in PAPERS and other in PAPERS:
            bad.append(f"line {line}: {own} imports {name} (papers never import each other)")
        elif LEVELS[other] >= LEVELS[own]:
            bad.append(f"line {line}: {own} (level {LEVELS[own]}) imports {name} (level {LEVELS[other]})")
    assert not bad, f"{path.relative_to(SRC.parent)}: " + "; ".join(bad)


@pytest.mark.parametrize("module,path", MODULES, ids=[m for m, _ in MODULES])
def test_no_backend_chosen_at_import(module, path):
    """``matplotlib.use`` changes the backend of whoever imports the module; rule scripts
    choose it, the library never does (not even inside a function)."""
    tree = ast.parse(path.read_text())
    for node in ast.walk(tree):
        if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and node.func.attr == "use":
            target = node.func.value
            assert not (isinstance(target, ast.Name) and target.id in ("matplotlib", "mpl")), (
                f"{path}: line {node.lineno} calls matplotlib.use"
            )


SCRIPTS = SRC.parents[1] / "workflow" / "scripts"
MAX_SCRIPT_LINES = 50  # lines as ruff format writes them (one argument a line where a call wraps)


RUNNERS = ("_rule.py", "_evaluation.py")
MAX_LOADER_LINES = 25


@pytest.mark.parametrize("path", sorted(p for p in SCRIPTS.glob("*.py") if p.name not in RUNNERS), ids=lambda p: p.name)
def test_rule_scripts_are_thin(path):
    """A rule script (and a paper's loader module ``_<paper>.py``) reads its inputs and
    params, calls the library and writes outputs: under 50 lines, and it builds no claim
    (claims come from the evaluation that measured them). ``_rule.py`` (logging, error lines,
    output writing) and ``_evaluation.py`` (the declared evaluations' runner and their input
    sets' loaders: :func:`test_input_set_loaders_are_thin`) are shared runners, not rule scripts."""
    text = path.read_text()
    n_lines = len(text.splitlines())
    assert n_lines < MAX_SCRIPT_LINES, f"{path.name}: {n_lines} lines (a rule script stays under {MAX_SCRIPT_LINES})"
    tree = ast.parse(text)
    for node in ast.walk(tree):
        if isinstance(node, ast.Call):
            name = node.func.id if isinstance(node.func, ast.Name) else getattr(node.func, "attr", "")
            assert name not in ("Claim", "verdict_threshold", "verdict_from_bool", "verdict_from_fraction"), (
                f"{path.name}: line {node.lineno} builds a claim or a verdict (that belongs to the library)"
            )


def test_every_rule_file_is_included():
    """The Snakefile names every rule file (directly or through an included file), so a
    rename stops the run instead of silently dropping a paper."""
    root = SRC.parents[1]
    rules = root / "workflow" / "rules"
    text = (root / "Snakefile").read_text() + "".join(p.read_text() for p in rules.glob("*.smk"))
    missing = [p.name for p in rules.glob("*.smk") if p.name not in text]
    assert not missing, f"rule files never included: {missing}"


def test_no_module_imports_itself_back():
    """No circle of imports between the modules of a package (a module and the ones it reaches
    never lead back to it), counting imports inside functions too; a package's ``__init__`` is
    left out (its lazy exports name its modules by design)."""
    modules = {m.removesuffix(".__init__") for m, _ in MODULES}
    edges: dict[str, set[str]] = {}
    for module, path in MODULES:
        if path.name == "__init__.py":
            continue
        targets = set()
        for name, _ in _imports(module, path):
            while name and name not in modules:  # motionvar.ma2010.examples.foot_contacts -> the module
                name = name.rpartition(".")[0]
            if (
                name
                and name != module
                and not any(p.name == "__init__.py" and m == name + ".__init__" for m, p in MODULES)
            ):
                targets.add(name)
        edges[module] = targets
    circles, state = [], {}

    def visit(node, stack):
        state[node] = "open"
        for nxt in sorted(edges.get(node, ())):
            if state.get(nxt) == "open":
                circles.append(stack[stack.index(nxt) :] + [nxt])
            elif nxt not in state:
                visit(nxt, stack + [nxt])
        state[node] = "done"

    for node in sorted(edges):
        if node not in state:
            visit(node, [node])
    assert not circles, "import circles: " + "; ".join(" -> ".join(c) for c in circles)


def test_input_set_loaders_are_thin():
    """Each function of ``_evaluation.py`` (a declared evaluation's runner, an input set's loader)
    reads files and calls the library in under 25 lines."""
    tree = ast.parse((SCRIPTS / "_evaluation.py").read_text())
    for node in tree.body:
        if isinstance(node, ast.FunctionDef):
            n = node.end_lineno - node.lineno + 1
            assert n < MAX_LOADER_LINES, f"_evaluation.py: {node.name} has {n} lines"
