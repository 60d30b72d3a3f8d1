"""The README runs as written: its code blocks (and the commands in its inline code) name
files, config files, config keys, Snakemake targets, options and `motionvar` arguments that
exist; its YAML config examples pass the config schema; its Python block runs; its result
counts are those of docs/results.md; it stays at most 250 lines. docs/real-data.md's
commands are checked the same way, and its labels scripts are run on the real sets beside
the repository (when present) and must write the labels shipped there."""

from __future__ import annotations

import io
import re
import shlex
import subprocess
import sys
import tomllib
from pathlib import Path

import jsonschema
import pandas as pd
import pytest
import yaml
from packaging.requirements import Requirement

from motionvar.cli.main import build_parser

ROOT = Path(__file__).resolve().parents[2]
README = ROOT / "README.md"
REAL_DATA_DOC = ROOT / "docs" / "real-data.md"
RESULTS_DOC = ROOT / "docs" / "results.md"
REAL = ROOT.parent / "shared" / "data" / "real"
MAX_LINES = 250
# snakemake options that take one value (the only ones the documents use)
SNAKEMAKE_VALUED = {"--cores", "-c", "--profile", "--workflow-profile", "--configfile", "--config", "-d", "--directory"}
SNAKEMAKE_FLAGS = {"-n", "--dry-run", "--list-rules", "--lint"}
FENCE = re.compile(r"^```(\w*)\n(.*?)^```", re.S | re.M)


def blocks(path: Path, lang: str | None = None) -> list[tuple[str, str]]:
    text = path.read_text(encoding="utf-8")
    return [(lg, body) for lg, body in FENCE.findall(text) if lang is None or lg == lang]


def prose(path: Path) -> str:
    """The text outside fenced blocks."""
    return FENCE.sub("", path.read_text(encoding="utf-8"))


def commands(path: Path) -> list[list[str]]:
    """Every command of the document's bash blocks (comments dropped, `&&` chains split,
    a heredoc's body skipped), plus the inline code spans that are commands."""
    out = []
    for body in (b for _, b in blocks(path, "bash")):
        lines = iter(body.splitlines())
        for line in lines:
            line = line.strip()
            if not line or line.startswith("#"):
                continue
            if "<<'EOF'" in line:  # python3 - ARGS > FILE <<'EOF' ... EOF: the command before <<
                line = line.split("<<'EOF'")[0].split(">")[0]
                for rest in lines:
                    if rest.strip() == "EOF":
                        break
            for part in line.split("&&"):
                argv = shlex.split(part, comments=True)
                if argv:
                    out.append(argv)
    for span in re.findall(r"`([^`\n]+)`", prose(path)):
        if re.match(r"(python -m snakemake|python tools/|python benchmarks/|bash )", span):
            out.append(shlex.split(span))
    return out


def load_yaml(path: Path) -> dict:
    return yaml.safe_load(path.read_text(encoding="utf-8")) or {}


def merge(base: dict, extra: dict) -> dict:
    out = dict(base)
    for key, value in extra.items():
        out[key] = merge(out[key], value) if isinstance(value, dict) and isinstance(out.get(key), dict) else value
    return out


def schema_errors(config: dict) -> list[str]:
    schema = load_yaml(ROOT / "config" / "schema.yaml")
    return [
        f"{'.'.join(map(str, e.absolute_path))}: {e.message}"
        for e in jsonschema.Draft202012Validator(schema).iter_errors(config)
    ]


def config_blocks(path: Path) -> dict[str, dict]:
    """The document's YAML blocks that are config files, by the name in their first line's
    comment (`# mywalks.yaml`), or by position when unnamed."""
    named = {}
    for i, (_, body) in enumerate(blocks(path, "yaml")):
        data = yaml.safe_load(body)
        if isinstance(data, dict) and "datasets" in data:
            first = body.splitlines()[0]
            m = re.match(r"#\s*(\S+\.yaml)", first)
            named[m.group(1) if m else f"block {i}"] = data
    return named


def has_key(config: dict, override: dict, where: str) -> None:
    for key, value in override.items():
        assert key in config, f"--config names {where}{key}, which the config files do not have"
        if isinstance(value, dict):
            has_key(config[key], value, f"{where}{key}.")


def dry_run(tmp_path: Path, targets: list[str], configfiles: list[str]) -> None:
    args = [sys.executable, "-m", "snakemake", "-s", str(ROOT / "Snakefile"), "-n", "--workflow-profile", "none"]
    args += ["-d", str(tmp_path)] + [a for c in configfiles for a in ("--configfile", str(ROOT / c))]
    result = subprocess.run(args + targets, cwd=ROOT, capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, (targets, result.stdout[-3000:], result.stderr[-3000:])


def check_command(argv: list[str], doc: Path, targets: dict[tuple[str, ...], set[str]]) -> None:
    """One command: what it names exists; snakemake targets are collected (per config
    files) for one dry run each."""
    own_configs = config_blocks(doc)
    if argv[:3] == ["python3", "-m", "venv"] or argv[0] in (".", "source"):
        return
    if argv[0] == "python3" and argv[1] == "-":  # a labels script of docs/real-data.md, run below
        return
    if argv[:4] == ["python", "-m", "pip", "install"]:
        args = argv[4:]
        constraints = args[args.index("-c") + 1]
        assert (ROOT / constraints).is_file(), constraints
        spec = args[args.index("-e") + 1]
        extras = re.fullmatch(r"\.(?:\[([\w,]+)\])?", spec)
        assert extras, spec
        optional = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]["optional-dependencies"]
        assert set((extras.group(1) or "").split(",")) - {""} <= set(optional), spec
        return
    if argv[:3] == ["python", "-m", "snakemake"]:
        args, configfiles, overrides, free = argv[3:], [], [], []
        i = 0
        while i < len(args):
            a = args[i]
            if a in SNAKEMAKE_VALUED:
                value = args[i + 1]
                if a == "--configfile":
                    configfiles.append(value)
                elif a == "--config":
                    overrides.append(value)
                elif a == "--profile":
                    assert (ROOT / value / "config.yaml").is_file(), f"profile {value}"
                elif a in ("--cores", "-c"):
                    assert value.isdigit(), value
                i += 2
            elif a in SNAKEMAKE_FLAGS:
                i += 1
            else:
                assert not a.startswith("-"), f"snakemake option {a} unknown to this test: add it"
                free.append(a)
                i += 1
        config = load_yaml(ROOT / "config" / "config.yaml")
        for c in configfiles:
            if (ROOT / c).is_file():
                config = merge(config, load_yaml(ROOT / c))
            else:
                assert c in own_configs, (
                    f"--configfile {c}: neither a file nor a YAML block named '# {c}' in {doc.name}"
                )
                config = merge(config, own_configs[c])
        for o in overrides:
            key, _, value = o.partition("=")
            override = {key: yaml.safe_load(value)}
            has_key(config, override, "")
            config = merge(config, override)
        assert not schema_errors(config), (argv, schema_errors(config))
        for t in free:
            assert t.startswith("results/"), f"snakemake target {t}"
            targets.setdefault(tuple(c for c in configfiles if (ROOT / c).is_file()), set()).add(t)
        return
    if argv[:3] == ["python", "-m", "pytest"]:
        args = argv[3:]
        if "-m" in args:
            expr = args[args.index("-m") + 1]
            markers = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["pytest"]["ini_options"]["markers"]
            names = {m.split(":")[0] for m in markers}
            assert set(re.findall(r"\w+", expr)) - {"not", "and", "or"} <= names, expr
        return
    if argv[0] == "python" and argv[1].endswith(".py") or argv[0] == "bash":
        assert (ROOT / argv[1]).is_file(), argv[1]
        return
    if argv[0] == "motionvar":
        try:
            build_parser().parse_args(argv[1:])
        except SystemExit as exc:
            pytest.fail(f"`{shlex.join(argv)}` does not parse (exit {exc.code})")
        return
    pytest.fail(f"{doc.name}: command unknown to this test: {shlex.join(argv)}")


@pytest.mark.parametrize("doc", [README, REAL_DATA_DOC], ids=lambda p: p.name)
def test_commands_name_what_exists(doc, tmp_path):
    targets: dict[tuple[str, ...], set[str]] = {}
    found = commands(doc)
    assert found
    for argv in found:
        check_command(argv, doc, targets)
    for configfiles, names in targets.items():
        dry_run(tmp_path, sorted(names), list(configfiles))


def test_readme_commands_cover_the_quick_start():
    """The quick start has what the README promises: a virtual environment, the install
    with the constraints (and the CPU-only PyTorch line), the CI config, `motionvar models`,
    a `motionvar ma2010` walk, the full run and the tests."""
    text = "\n".join(shlex.join(a) for a in commands(README))
    for needed in (
        "python3 -m venv .venv",
        "python -m pip install -c constraints.txt -e '.[test]'",
        "--extra-index-url https://download.pytorch.org/whl/cpu",
        "python -m snakemake --cores 2 --configfile config/ci.yaml",
        "motionvar models",
        "motionvar ma2010",
        "python -m pytest",
    ):
        assert needed in text, needed
    assert re.search(r"^python -m snakemake --cores 2$", text, re.M)


def test_readme_at_most_250_lines():
    n = len(README.read_text(encoding="utf-8").splitlines())
    assert n <= MAX_LINES, f"README.md has {n} lines (at most {MAX_LINES}: move detail to docs/)"


@pytest.mark.parametrize("doc", [README, REAL_DATA_DOC], ids=lambda p: p.name)
def test_named_files_exist(doc):
    text = prose(doc)
    missing = []
    for link in re.findall(r"\]\(([^)\s]+)\)", text):
        if not re.match(r"\w+://", link) and not (doc.parent / link.split("#")[0]).exists():
            missing.append(link)
    for span in re.findall(r"`([^`\s]+)`", text):
        if "<" in span or span.startswith(("results/", "reports/", "/")) or "/" not in span and "." not in span:
            continue
        if re.match(r"(config|docs|workflow|tools|src|tests|benchmarks|profiles)/", span) or span in (
            "constraints.txt",
            "LICENSE",
            "CITATION.cff",
            "pyproject.toml",
        ):
            if not (ROOT / span).exists():
                missing.append(span)
    assert not missing, f"{doc.name} names files that do not exist: {missing}"


def test_result_files_named_are_made_by_rules():
    """Concrete results/ and reports/ paths in the README's prose: below the dataset's
    folder, the file name is one the workflow writes; reports lie where the workflow puts
    them."""
    workflow = "\n".join(p.read_text() for p in (ROOT / "workflow").rglob("*") if p.suffix in (".smk", ".yaml", ".py"))
    workflow += (ROOT / "Snakefile").read_text()
    for span in re.findall(r"`((?:results|reports)/[^`\s]*)`", prose(README)):
        parts = span.rstrip("/").split("/")
        if parts[0] == "reports":
            assert "reports/" in workflow, span
        elif len(parts) > 2 and "<" not in parts[-1]:
            assert parts[-1] in workflow, span


def test_yaml_config_examples_pass_the_schema():
    base = load_yaml(ROOT / "config" / "config.yaml")
    for doc in (README, REAL_DATA_DOC):
        for name, data in config_blocks(doc).items():
            errors = schema_errors(merge(base, data))
            assert not errors, (doc.name, name, errors)


def test_python_block_runs():
    for body in (b for _, b in blocks(README, "python")):
        exec(compile(body, "README.md", "exec"), {})


def test_result_counts_match_docs_results():
    """README's counts per paper and kind are docs/results.md's (tools/readme_results.py writes both)."""
    readme = README.read_text(encoding="utf-8")
    counts = readme.split("<!-- counts:start -->\n", 1)[1].split("<!-- counts:end -->", 1)[0]
    assert counts.startswith("| paper | kind | claims | verdicts |")
    rows = [row.split(" | ") for row in counts.splitlines()[2:] if row.startswith("| ") and "---" not in row]
    assert {"replication", "stand-in", "consistency"} <= {row[1] for row in rows}
    assert counts in RESULTS_DOC.read_text(encoding="utf-8")


@pytest.mark.skipif(not REAL.is_dir(), reason=f"{REAL} absent")
def test_real_data_labels_scripts_write_the_shipped_labels():
    scripts = re.findall(r"^(python3 - /data/(\w+) > \S+ <<'EOF'\n.*?\nEOF)$", REAL_DATA_DOC.read_text(), re.S | re.M)
    assert {name for _, name in scripts} == {"xia", "bandai_ds1", "dfki_markerless"}
    for script, name in scripts:
        assert (ROOT / "config" / "real" / f"{name}.yaml").is_file()
        body = script.split("\n", 1)[1].rsplit("\nEOF", 1)[0]
        out = subprocess.run(
            [sys.executable, "-", str(REAL / name)], input=body, capture_output=True, text=True, check=True
        ).stdout
        mine = pd.read_csv(io.StringIO(out), dtype=str, keep_default_na=False)
        shipped = pd.read_csv(REAL / name / "labels.csv", dtype=str, keep_default_na=False)[list(mine.columns)]
        key = ["file"]
        pd.testing.assert_frame_equal(
            mine.sort_values(key).reset_index(drop=True), shipped.sort_values(key).reset_index(drop=True)
        )


def test_constraints_pin_the_declared_dependencies():
    """constraints.txt pins every dependency of the package and of its extras, each within
    the range pyproject.toml declares."""
    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    pins = {}
    for line in (ROOT / "constraints.txt").read_text().splitlines():
        line = line.split("#")[0].strip()
        if line:
            name, version = line.split("==")
            pins[re.sub(r"[-_.]+", "-", name).lower()] = version
    for spec in project["dependencies"] + sum(project["optional-dependencies"].values(), []):
        req = Requirement(spec)
        name = re.sub(r"[-_.]+", "-", req.name).lower()
        assert name in pins, f"constraints.txt does not pin {req.name}"
        assert req.specifier.contains(pins[name], prereleases=True), f"{req.name}=={pins[name]} outside {req.specifier}"


def test_ci_runs_the_readme_test_command():
    """.ci/run runs exactly the README's test command (install included, so a fresh clone passes)."""
    ci = [
        line
        for line in (ROOT / ".ci" / "run").read_text().splitlines()
        if line and not line.startswith(("#", "set ", "cd "))
    ]
    assert len(ci) == 1, ci
    bash = "\n".join(text for _, text in blocks(README, "bash"))
    assert ci[0] in bash.splitlines(), f".ci/run runs {ci[0]!r}, which is not a line of the README"
    assert ci[0].endswith("python -m pytest") and "pip install" in ci[0]
