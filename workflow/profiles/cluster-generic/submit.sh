#!/usr/bin/env bash
# Submit one Snakemake job script; print a job id. Called as
#   submit.sh THREADS MEM_MB JOBSCRIPT
# As written it behaves like a tiny scheduler on this machine (a try-out that needs no
# cluster; tests/test_cluster_generic.py runs the CI config through it): the job starts
# detached as its own background process, its job id is that process's id, its output
# goes to $MOTIONVAR_CLUSTER_DIR/<jobscript name>.log and its exit status, when it ends,
# to $MOTIONVAR_CLUSTER_DIR/<job id>.rc (read by status.sh), its CPU time to <job id>.times
# (the output of bash's `times`: the last line is the job's user and system time). MOTIONVAR_CLUSTER_DIR
# defaults to logs/cluster in the working directory.
# For a real cluster replace the `nohup` line and the `echo` with your scheduler's
# submit command, which prints the job id, e.g.
#   PBS/Torque: qsub -l nodes=1:ppn="$threads",mem="$mem_mb"mb "$jobscript"
#   SGE:        qsub -terse -pe smp "$threads" -l h_vmem="$mem_mb"M "$jobscript"
#   Slurm:      sbatch --parsable -c "$threads" --mem="$mem_mb" "$jobscript"
# (and status.sh with its status command: qstat, sacct, ...).
set -euo pipefail
threads="$1"; mem_mb="$2"; jobscript="$3"
dir="${MOTIONVAR_CLUSTER_DIR:-logs/cluster}"
mkdir -p "$dir"
name="$(basename "$jobscript" .sh)"
# The job runs in its own session (setsid: cancel.sh stops its whole process group); $$
# inside it is its process id, the job id; `times` leaves the job's CPU seconds (user,
# system) in <job id>.times, for accounting.
nohup setsid bash -c 'bash "$1"; rc=$?; times >"$2/$$.times"; echo "$rc" >"$2/$$.rc.tmp"; mv "$2/$$.rc.tmp" "$2/$$.rc"' \
    job "$jobscript" "$dir" >"$dir/$name.log" 2>&1 </dev/null &
jobid=$!
echo "$(date +%FT%T) $jobid $name threads=$threads mem_mb=$mem_mb" >>"$dir/submissions.log"
echo "$jobid"
