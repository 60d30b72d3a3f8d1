"""A real cluster-style run: config/ci.yaml through Snakemake's cluster-generic executor and
the profile workflow/profiles/cluster-generic, whose submit.sh starts every job as its own
detached process on this machine (its own session, a job id, an exit status read back by
status.sh), the way a batch scheduler would. A few jobs, not the whole pipeline: the data,
preprocessing, Du ch. 3's chain to one SFPCA model (a torch fit) and two evaluations of
different papers. Their claims (claim_id, verdict, value) and the SFPCA model's arrays must
equal those of the local run of the same config (the session's ``ci_run``, tests/conftest.py):
no rule may depend on running inside the scheduler's process, on shared memory or on the
order of jobs. Needs snakemake-executor-plugin-cluster-generic (the test extras)."""

from __future__ import annotations

import os
import re
import signal
import time
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from pipeline_runs import CI_CONFIG, ROOT, children_cpu_s, run_snakemake

pytest.importorskip("snakemake_executor_plugin_cluster_generic")

PROFILE = ROOT / "workflow" / "profiles" / "cluster-generic"
CLAIMS = ("results/synthetic/claims/du2022_fig3_9.json", "results/synthetic/claims/egges2004_fitting.json")
MODEL = "results/synthetic/models/du2022_fda/sfpca/pick_reach.npz"
TARGETS = (*CLAIMS, MODEL)


def _job_cpu(times_file: Path) -> float:
    """User + system CPU seconds of a job's children, from bash's `times` output."""
    lines = times_file.read_text().split("\n")
    total = 0.0
    for m, s in re.findall(r"(\d+)m([\d.]+)s", lines[1] if len(lines) > 1 else ""):
        total += 60 * int(m) + float(s)
    return total


def _stop_leftovers(cluster: Path) -> None:
    """Stop the process group of every submitted job still alive (a failed or timed-out run)."""
    log = cluster / "submissions.log"
    if not log.is_file():
        return
    for line in log.read_text().splitlines():
        jobid = int(line.split()[1])
        if not (cluster / f"{jobid}.rc").exists():
            try:
                os.killpg(jobid, signal.SIGTERM)
            except (ProcessLookupError, PermissionError):
                pass


@pytest.fixture(scope="module")
def cluster_run(tmp_path_factory):
    work = tmp_path_factory.mktemp("cluster_run")
    cluster = work / "cluster"
    env = {**os.environ, "MOTIONVAR_CLUSTER_DIR": str(cluster)}
    before = children_cpu_s()
    start = time.perf_counter()
    try:
        result = run_snakemake(
            "-d",
            str(work),
            "--configfile",
            CI_CONFIG,
            "--workflow-profile",
            "none",
            "--profile",
            str(PROFILE),  # executor, latency wait; the scripts by absolute path (other cwd):
            "--cluster-generic-submit-cmd",
            f"bash {PROFILE}/submit.sh {{threads}} {{resources.mem_mb}}",
            "--cluster-generic-status-cmd",
            f"bash {PROFILE}/status.sh",
            "--cluster-generic-cancel-cmd",
            str(PROFILE / "cancel.sh"),
            "--jobs",
            "2",
            "--seconds-between-status-checks",
            "1",
            "--latency-wait",
            "10",
            "--",
            *TARGETS,
            cwd=work,
            env=env,
            timeout=1800,
        )
    finally:
        _stop_leftovers(cluster)
    wall = time.perf_counter() - start
    main_cpu = children_cpu_s() - before
    jobs_cpu = sum(_job_cpu(p) for p in cluster.glob("*.times"))
    print(
        f"cluster-generic run: wall {wall:.1f} s, CPU {main_cpu + jobs_cpu:.1f} s "
        f"(jobs {jobs_cpu:.1f} s, Snakemake's main process {main_cpu:.1f} s)"
    )
    assert result.returncode == 0, result.stdout[-4000:] + result.stderr[-8000:]
    return work, cluster, result


@pytest.mark.e2e
def test_every_job_went_through_the_scheduler(cluster_run):
    work, cluster, result = cluster_run
    submitted = (cluster / "submissions.log").read_text().splitlines()
    ids = [line.split()[1] for line in submitted]
    ran = re.findall(r"Submitted job \d+ with external jobid '(\d+)'", result.stdout + result.stderr)
    assert sorted(ran) == sorted(ids) and len(ids) >= 6  # every job a submission, with its own id
    rules = {line.split()[2].split(".")[1] for line in submitted}
    assert {"data", "preprocess", "du2022_fda_sfpca", "du2022_fig3_9", "egges2004_fitting"} <= rules
    assert all((cluster / f"{i}.rc").read_text().strip() == "0" for i in ids)
    assert len(set(ids)) == len(ids) and str(os.getpid()) not in ids


@pytest.mark.e2e
def test_cluster_outputs_equal_the_local_ones(cluster_run, ci_run):
    work, _, _ = cluster_run
    local = ci_run.work
    cols = ["claim_id", "verdict", "value"]
    for name in CLAIMS:
        ours = pd.read_json(work / name)[cols]
        theirs = pd.read_json(local / name)[cols]
        assert len(ours) >= 1
        pd.testing.assert_frame_equal(ours, theirs)
    with np.load(work / MODEL) as ours, np.load(local / MODEL) as theirs:
        assert sorted(ours.files) == sorted(theirs.files)
        for key in ours.files:
            assert np.array_equal(ours[key], theirs[key]), key
