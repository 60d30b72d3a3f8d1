"""Shared fixtures. ``ci_run``: the whole workflow on config/ci.yaml in a temporary working
directory, run once per test session through the default profile (its default target ends
with the dataset's report, reports/synthetic.html); used by tests/workflow/test_pipeline_e2e.py,
tests/workflow/test_progress.py and, as the local reference run, by tests/workflow/test_cluster_generic.py. The
test command runs the tests in parallel processes (pytest-xdist, pyproject.toml); the first
process that asks for ``ci_run`` runs the pipeline and the others wait for it and read it back,
so a session runs the CI pipeline locally once. Two reference jobs run before it and two after
(tests/pipeline_runs.py): the budget test bounds the pipeline's CPU in their units."""

import json
import os
import statistics
import subprocess
import time
from pathlib import Path
from typing import NamedTuple

import pytest
from pipeline_runs import CI_CONFIG, children_cpu_s, reference_job_cpu, run_snakemake


class CiRun(NamedTuple):
    work: Path
    wall_s: float
    cpu_s: float  # user + system of the whole process tree
    result: subprocess.CompletedProcess
    reference_cpu_s: float  # the median reference job's, measured around the run


@pytest.fixture(scope="session")
def ci_run(tmp_path_factory) -> CiRun:
    """One local run of config/ci.yaml on 2 cores, shared by the session's processes (module
    docstring)."""
    from filelock import FileLock

    shared = tmp_path_factory.getbasetemp()
    if "PYTEST_XDIST_WORKER" in os.environ:
        shared = shared.parent  # the folder every xdist worker's base folder lies in
    work, record = shared / "ci_run", shared / "ci_run.json"
    with FileLock(str(shared / "ci_run.lock")):
        if not record.is_file():
            work.mkdir()
            references = reference_job_cpu()
            before = children_cpu_s()
            start = time.perf_counter()
            result = run_snakemake("-d", str(work), "--configfile", CI_CONFIG, "--cores", "2", cwd=work)
            wall = time.perf_counter() - start
            cpu = children_cpu_s() - before
            references += reference_job_cpu()
            run = {"wall": wall, "cpu": cpu, "references": references, "returncode": result.returncode}
            record.write_text(json.dumps({**run, "stdout": result.stdout, "stderr": result.stderr}))
    run = json.loads(record.read_text())
    result = subprocess.CompletedProcess(["snakemake"], run["returncode"], run["stdout"], run["stderr"])
    reference = statistics.median(run["references"])
    print(
        f"CI pipeline: wall {run['wall']:.1f} s, CPU {run['cpu']:.1f} s; reference job CPU "
        f"{', '.join(f'{r:.2f}' for r in run['references'])} s (median {reference:.2f})"
    )
    assert result.returncode == 0, result.stdout[-4000:] + result.stderr[-8000:]
    return CiRun(work, run["wall"], run["cpu"], result, reference)


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
