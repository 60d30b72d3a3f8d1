#!/usr/bin/env bash
# A real Slurm run of the CI config on this one machine: sets up a single-node Slurm cluster
# from the Debian packages (slurm-wlm, munge), starts munged, slurmctld and slurmd as root,
# runs config/ci.yaml through workflow/profiles/slurm with snakemake-executor-plugin-slurm
# (every rule a Slurm job: sbatch, then srun inside it), and reports the exit status, the
# jobs Slurm ran and whether the claims (claim_id, verdict) equal those of a local run.
#
#   sudo bash benchmarks/slurm_single_node.sh [--work DIR] [--local-claims CLAIMS_CSV] [--keep]
#
#   --work DIR            working directory of the run (default /tmp/motionvar_slurm_ci)
#   --local-claims CSV    claims.csv of a local run of config/ci.yaml to compare with (default:
#                         run the CI config locally first, into DIR/local)
#   --keep                leave the Slurm daemons running at the end (default: stop them, and
#                         munged if this script started it, and uninstall the Slurm plugin if
#                         this script installed it: plugin 2.8.0 runs `scontrol show config`
#                         whenever Snakemake loads its plugins, so with slurm-wlm installed and
#                         no controller running, every later `snakemake` waited ~9 s to start)
#
# Not part of CI (it installs system packages and runs daemons as root); it needs a Debian
# or Ubuntu machine with apt, the repository installed (`pip install -e .`) and about twice
# the CPU time of the local CI run.
#
# Accounting: the plugin reads job states with `sacct` by default, which needs slurmdbd and a
# database. Its documented option --slurm-status-command squeue reads them from slurmctld
# instead; completed jobs stay visible there for MinJobAge seconds (600 here; the plugin wants
# at least 3 x --slurm-init-seconds-before-status-checks). So no slurmdbd/MariaDB:
# AccountingStorageType=accounting_storage/none, and --slurm-no-account (no account to check).
set -euo pipefail

REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
WORK=/tmp/motionvar_slurm_ci
LOCAL_CLAIMS=""
KEEP=0
while [[ $# -gt 0 ]]; do
    case "$1" in
        --work) WORK="$2"; shift 2 ;;
        --local-claims) LOCAL_CLAIMS="$2"; shift 2 ;;
        --keep) KEEP=1; shift ;;
        *) echo "usage: $0 [--work DIR] [--local-claims CLAIMS_CSV] [--keep]" >&2; exit 2 ;;
    esac
done
[[ $(id -u) == 0 ]] || { echo "run as root (it installs packages and starts the Slurm daemons)" >&2; exit 2; }
PY="${PYTHON:-python}"
say() { echo "[slurm_single_node $(date +%T)] $*"; }

# ---- 1. packages ------------------------------------------------------------------------
if ! command -v slurmctld >/dev/null || ! command -v munged >/dev/null; then
    say "installing slurm-wlm and munge (apt)"
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq slurm-wlm munge >/dev/null
fi
INSTALLED_PLUGIN=0
"$PY" -c "import snakemake_executor_plugin_slurm" 2>/dev/null || {
    say "installing snakemake-executor-plugin-slurm"
    "$PY" -m pip install -q "snakemake-executor-plugin-slurm==2.8.0"
    INSTALLED_PLUGIN=1
}
say "$(slurmctld -V), $(munged --version 2>&1 | head -1 | awk '{print $1}'), plugin $("$PY" -c 'import importlib.metadata as m; print(m.version("snakemake-executor-plugin-slurm"))')"

# ---- 2. munge ---------------------------------------------------------------------------
mkdir -p /etc/munge /var/lib/munge /var/log/munge /run/munge
[[ -s /etc/munge/munge.key ]] || { say "creating the munge key"; mungekey --create --force 2>/dev/null || \
    dd if=/dev/urandom bs=1 count=1024 of=/etc/munge/munge.key 2>/dev/null; }
chown -R munge:munge /etc/munge /var/lib/munge /var/log/munge /run/munge
chmod 700 /etc/munge; chmod 400 /etc/munge/munge.key
STARTED_MUNGED=0
if ! munge -n >/dev/null 2>&1; then
    say "starting munged"
    runuser -u munge -- /usr/sbin/munged
    STARTED_MUNGED=1
    sleep 1
fi
munge -n | unmunge >/dev/null && say "munge works"

# ---- 3. slurm.conf: one node, this machine ---------------------------------------------
HOST="$(hostname -s)"
NODE_LINE="$(slurmd -C | head -1)"             # NodeName=... CPUs=... RealMemory=... as detected
SPOOL=/var/spool/motionvar_slurm
mkdir -p /etc/slurm "$SPOOL/ctld" "$SPOOL/d" /var/log/slurm
cat > /etc/slurm/slurm.conf <<EOF
# written by motionvar benchmarks/slurm_single_node.sh: one node, no accounting database
ClusterName=motionvar
SlurmctldHost=$HOST
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
MpiDefault=none
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
JobCompType=jobcomp/none
MinJobAge=600
ReturnToService=2
SlurmdTimeout=300
StateSaveLocation=$SPOOL/ctld
SlurmdSpoolDir=$SPOOL/d
SlurmctldPidFile=/run/slurmctld.pid
SlurmdPidFile=/run/slurmd.pid
SlurmctldLogFile=/var/log/slurm/slurmctld.log
SlurmdLogFile=/var/log/slurm/slurmd.log
$NODE_LINE State=UNKNOWN
PartitionName=debug Nodes=ALL Default=YES MaxTime=INFINITE State=UP
EOF
say "slurm.conf: $NODE_LINE"

# ---- 4. daemons -------------------------------------------------------------------------
stop_daemons() {
    [[ $KEEP == 1 ]] && { say "leaving the Slurm daemons running (--keep)"; return; }
    say "stopping the Slurm daemons"
    scontrol shutdown >/dev/null 2>&1 || true
    sleep 2
    for pidfile in /run/slurmd.pid /run/slurmctld.pid; do
        [[ -f $pidfile ]] && kill "$(cat "$pidfile")" 2>/dev/null || true
    done
    if [[ $STARTED_MUNGED == 1 && -f /run/munge/munged.pid ]]; then
        kill "$(cat /run/munge/munged.pid)" 2>/dev/null || true
    fi
    if [[ $INSTALLED_PLUGIN == 1 ]]; then
        say "uninstalling snakemake-executor-plugin-slurm (it would slow every later snakemake start)"
        "$PY" -m pip uninstall -q -y snakemake-executor-plugin-slurm || true
    fi
}
trap stop_daemons EXIT
if ! scontrol ping 2>/dev/null | grep -q UP; then
    say "starting slurmctld and slurmd"
    slurmctld -c   # -c: a clean start (no saved state of an earlier run)
    slurmd
fi
for _ in $(seq 60); do
    state="$(sinfo -h -n "$HOST" -o %t 2>/dev/null || true)"
    [[ "$state" == idle* || "$state" == mix* || "$state" == alloc* ]] && break
    scontrol update nodename="$HOST" state=resume >/dev/null 2>&1 || true
    sleep 1
done
sinfo
say "a test job: $(srun -N1 -n1 hostname)"

# ---- 5. the local reference ---------------------------------------------------------------
mkdir -p "$WORK"
if [[ -z "$LOCAL_CLAIMS" ]]; then
    say "local run of config/ci.yaml into $WORK/local (the reference claims)"
    "$PY" -m snakemake -s "$REPO/Snakefile" -d "$WORK/local" --configfile "$REPO/config/ci.yaml" \
        --workflow-profile none --cores 2 -- results/synthetic/claims.csv >"$WORK/local.log" 2>&1
    LOCAL_CLAIMS="$WORK/local/results/synthetic/claims.csv"
fi

# ---- 6. the Slurm run ---------------------------------------------------------------------
say "Slurm run of config/ci.yaml into $WORK/slurm (log: $WORK/slurm.log)"
start=$(date +%s)
set +e
"$PY" -m snakemake -s "$REPO/Snakefile" -d "$WORK/slurm" --configfile "$REPO/config/ci.yaml" \
    --workflow-profile none --profile "$REPO/workflow/profiles/slurm" \
    --slurm-no-account --slurm-status-command squeue --slurm-init-seconds-before-status-checks 5 \
    --default-resources slurm_partition=debug runtime=60 mem_mb=2000 \
    --jobs 2 --latency-wait 30 -- results/synthetic/claims.csv >"$WORK/slurm.log" 2>&1
rc=$?
set -e
wall=$(( $(date +%s) - start ))
n_submitted=$(grep -c "Job .* has been submitted with SLURM jobid" "$WORK/slurm.log" || true)
say "snakemake exit status $rc after $wall s; $n_submitted jobs submitted to Slurm"
squeue --states=all -h -o "%i %j %T %M" | awk '{print $3}' | sort | uniq -c | sed 's/^/    jobs in slurmctld: /'
if [[ $rc != 0 ]]; then
    tail -40 "$WORK/slurm.log"
    exit "$rc"
fi

# ---- 7. claims -------------------------------------------------------------------------
"$PY" - "$LOCAL_CLAIMS" "$WORK/slurm/results/synthetic/claims.csv" <<'EOF'
import sys
import pandas as pd
cols = ["claim_id", "verdict"]
local, slurm = (pd.read_csv(p)[cols].sort_values("claim_id").reset_index(drop=True) for p in sys.argv[1:3])
same = local.equals(slurm)
print(f"[slurm_single_node] claims: {len(slurm)} from Slurm, {len(local)} local; (claim_id, verdict) "
      f"{'IDENTICAL' if same else 'DIFFERENT'}")
if not same:
    print(local.merge(slurm, on="claim_id", how="outer", suffixes=("_local", "_slurm"), indicator=True)
          .query("verdict_local != verdict_slurm").to_string(index=False))
sys.exit(0 if same else 1)
EOF
