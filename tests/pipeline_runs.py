"""The workflow as the tests start it: the repository's Snakefile and CI config, and a Snakemake
subprocess in a working directory."""

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SNAKEFILE = str(ROOT / "Snakefile")
CI_CONFIG = str(ROOT / "config" / "ci.yaml")


def run_snakemake(*args, cwd, timeout=900, env=None):
    """``python -m snakemake -s Snakefile ARGS`` in ``cwd`` (output captured)."""
    return subprocess.run(
        [sys.executable, "-m", "snakemake", "-s", SNAKEFILE, *args],
        cwd=cwd,
        capture_output=True,
        text=True,
        timeout=timeout,
        env=env,
    )
