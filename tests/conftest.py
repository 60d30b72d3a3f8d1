"""Shared fixtures. ``ci_run``: the whole workflow on config/ci.yaml in a temporary working
directory, run once per test session through the default profile (its default target ends
with the dataset's report, reports/synthetic.html); used by tests/test_pipeline_e2e.py and,
as the local reference run, by tests/test_cluster_generic.py (so CI runs the CI pipeline
locally once)."""

import resource
import subprocess
import sys
import time
from pathlib import Path

import pytest

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


@pytest.fixture(scope="session")
def ci_run(tmp_path_factory):
    """(working directory, wall s, CPU s of the process tree, CompletedProcess) of one local
    run of config/ci.yaml on 2 cores."""
    work = tmp_path_factory.mktemp("ci_run")
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    result = run_snakemake("-d", str(work), "--configfile", CI_CONFIG, "--cores", "2", cwd=work)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    print(f"CI pipeline: wall {wall:.1f} s, CPU {cpu:.1f} s")
    assert result.returncode == 0, result.stdout[-4000:] + result.stderr[-8000:]
    return work, wall, cpu, result


@pytest.fixture(scope="module")
def one_torch_thread():
    """Torch on one thread for a module of tiny networks: more threads oversubscribe a
    shared machine (10x slower here). Modules opt in with
    ``pytestmark = pytest.mark.usefixtures("one_torch_thread")``."""
    import torch

    n = torch.get_num_threads()
    torch.set_num_threads(1)
    yield
    torch.set_num_threads(n)
