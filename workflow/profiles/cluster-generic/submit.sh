#!/usr/bin/env bash
# Submit one Snakemake job script; print a job id. Called as
#   submit.sh THREADS MEM_MB JOBSCRIPT
# As written it runs the job in the background on this machine (a try-out that needs no
# scheduler). For a real cluster replace the last two lines, e.g.
#   PBS/Torque: qsub -l nodes=1:ppn="$1",mem="$2"mb "$3"
#   SGE:        qsub -terse -pe smp "$1" -l h_vmem="$2"M "$3"
#   Slurm:      sbatch --parsable -c "$1" --mem="$2" "$3"
set -euo pipefail
threads="$1"; mem_mb="$2"; jobscript="$3"
mkdir -p logs/cluster
nohup bash "$jobscript" >"logs/cluster/$(basename "$jobscript").log" 2>&1 &
echo $!
