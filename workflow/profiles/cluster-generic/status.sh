#!/usr/bin/env bash
# Status of one job started by submit.sh, as Snakemake's cluster-generic executor wants it:
# one line, running | success | failed. Called as
#   status.sh JOBID
# A job that left an exit status (in $MOTIONVAR_CLUSTER_DIR/<job id>.rc) succeeded if it is
# 0; a job still alive is running; a job that vanished without a status (killed) failed.
# For a real cluster ask the scheduler instead, e.g. for Slurm
#   sacct -j "$1" -X -n -o State | grep -q COMPLETED && echo success ...
set -uo pipefail
jobid="$1"
dir="${MOTIONVAR_CLUSTER_DIR:-logs/cluster}"
if [[ -f "$dir/$jobid.rc" ]]; then
    if [[ "$(cat "$dir/$jobid.rc")" == 0 ]]; then echo success; else echo failed; fi
elif kill -0 "$jobid" 2>/dev/null; then
    echo running
elif [[ -f "$dir/$jobid.rc" ]]; then  # it ended between the two checks
    if [[ "$(cat "$dir/$jobid.rc")" == 0 ]]; then echo success; else echo failed; fi
else
    echo failed
fi
