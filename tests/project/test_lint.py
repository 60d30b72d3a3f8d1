"""The code is lint-clean and formatted (ruff, configured in pyproject.toml): part of the test
command, so CI fails on a lint finding or an unformatted file."""

import shutil
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
PATHS = ["src", "tests", "workflow/scripts", "benchmarks", "tools"]


def ruff(*args):
    exe = shutil.which("ruff") or str(Path(sys.executable).with_name("ruff"))
    assert Path(exe).exists(), "ruff is not installed: pip install -e '.[test]' (pyproject.toml pins it)"
    return subprocess.run([exe, *args, *PATHS], cwd=ROOT, capture_output=True, text=True)


def test_ruff_check_is_clean():
    out = ruff("check", "--no-cache")
    assert out.returncode == 0, out.stdout + out.stderr


def test_ruff_format_is_applied():
    out = ruff("format", "--check", "--no-cache")
    assert out.returncode == 0, out.stdout + out.stderr
