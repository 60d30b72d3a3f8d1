#!/usr/bin/env bash
# Cancel jobs started by submit.sh (Snakemake's cluster-generic executor calls it with job
# ids when a run is interrupted): stops each job's whole process group. Called as
#   cancel.sh JOBID [JOBID ...]
# For a real cluster use the scheduler's command (scancel, qdel, bkill).
for jobid in "$@"; do
    kill -TERM -- "-$jobid" 2>/dev/null || kill -TERM "$jobid" 2>/dev/null || true
done
