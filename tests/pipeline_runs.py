"""The workflow as the tests start it: the repository's Snakefile and CI config, a Snakemake
subprocess in a working directory, and the reference job its cost is counted in."""

import os
import resource
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


# A reference job: what a typical rule job does, in a fresh interpreter on one thread (the
# imports of the rules' stack, then some dense linear algebra in numpy and torch). The CI
# pipeline's cost is bounded in reference jobs measured in the same session, not in CPU
# seconds: this machine's speed varies by tens of percent from day to day and with its
# neighbours, and a reference job measured beside the pipeline varies with it.
REFERENCE_JOB = (
    "import numpy, scipy.linalg, pandas, sklearn.decomposition, torch, matplotlib\n"
    "matplotlib.use('Agg')\n"
    "import matplotlib.pyplot\n"
    "a = numpy.random.default_rng(0).standard_normal((300, 300))\n"
    "for _ in range(30): scipy.linalg.eigh(a @ a.T)\n"
    "t = torch.from_numpy(a)\n"
    "for _ in range(30): torch.linalg.eigh(t @ t.T)\n"
)
ONE_THREAD = {k: "1" for k in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS")}


def children_cpu_s() -> float:
    """CPU seconds (user + system) of this process's finished and waited-for subprocesses so far,
    their own children included: the difference of two calls is what a subprocess run between
    them cost."""
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def reference_job_cpu(repeats: int = 2) -> list[float]:
    """CPU seconds (user + system) of ``repeats`` runs of :data:`REFERENCE_JOB`."""
    out = []
    for _ in range(repeats):
        before = children_cpu_s()
        subprocess.run([sys.executable, "-c", REFERENCE_JOB], check=True, env={**os.environ, **ONE_THREAD})
        out.append(children_cpu_s() - before)
    return out
