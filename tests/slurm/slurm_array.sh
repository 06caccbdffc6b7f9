#!/usr/bin/env bash
# A real Slurm run of a farm job: starts a one-node Slurm cluster from Debian's packages
# (munged, slurmctld, slurmd as the current user, everything in a scratch folder: a fresh munge
# key, a slurm.conf with this host's name, CPUs and memory, its own ports), submits an
# `sbatch --array=0-3` job writing the 4 USD tiles of a test project, waits for it, composes the
# root layer and checks that it holds the single-machine run's forest tree for tree (ids,
# species, transforms as written). Exit 77 (ctest: skipped) with the reason where Slurm cannot
# start here (packages missing, no permission to run the daemons).
# usage: slurm_array.sh <sylva-cli> <tests/data> <scratch folder>
set -uo pipefail
CLI=$1 DATA=$2 WORK=$3
SRC=$(cd "$(dirname "$0")" && pwd)
rm -rf "$WORK" && mkdir -p "$WORK" && cd "$WORK" || exit 1
WORK=$(pwd)
chmod 711 "$WORK"

fail() { echo "FAIL [slurm_array]: $*" >&2; exit 1; }
skip() { echo "SKIP: $*"; exit 77; }
for tool in munged slurmctld slurmd sbatch sinfo scontrol; do
  command -v "$tool" >/dev/null || skip "$tool not installed (scripts/install-deps.sh installs slurmctld, slurmd, slurm-client, munge)"
done

pids=()
cleanup() {
  # Only the daemons this script started, by their ids.
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null; done
  for pid in "${pids[@]}"; do
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2>/dev/null
  done
}
trap cleanup EXIT
logs() { for f in "$WORK"/log/*.log; do echo "--- $f"; tail -5 "$f"; done; }

# munge: a fresh key, a socket of our own.
mkdir -p log state spool munge out && chmod 711 munge
dd if=/dev/urandom of=munge/munge.key bs=1024 count=1 status=none && chmod 400 munge/munge.key
force=(); [[ $(id -u) == 0 ]] && force=(--force)
munged "${force[@]}" --foreground --key-file="$WORK/munge/munge.key" --socket="$WORK/munge/munge.sock" \
  --pid-file="$WORK/munge/munged.pid" --log-file="$WORK/log/munged.log" \
  --seed-file="$WORK/munge/munged.seed" >log/munged.out 2>&1 &
pids+=($!)
for _ in $(seq 50); do [[ -S munge/munge.sock ]] && break; sleep 0.1; done
[[ -S munge/munge.sock ]] || { logs; skip "munged did not start"; }

# slurm.conf for this host; ports picked from the scratch folder's name so parallel runs differ.
host=$(hostname -s)
read -r cpus mem < <(slurmd -C 2>/dev/null | awk '/^NodeName/ {
  for (i = 1; i <= NF; i++) { split($i, kv, "="); if (kv[1] == "CPUs") c = kv[2]; if (kv[1] == "RealMemory") m = kv[2] }
  print c, m }')
[[ -n "${cpus:-}" && -n "${mem:-}" ]] || skip "slurmd -C does not describe this host"
port=$(( 20000 + $(cksum <<< "$WORK" | cut -d' ' -f1) % 20000 ))
user=$(id -un)
cat > slurm.conf <<CONF
ClusterName=sylvatest
SlurmctldHost=$host
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=$user
SlurmdUser=$user
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$WORK/munge/munge.sock
StateSaveLocation=$WORK/state
SlurmdSpoolDir=$WORK/spool
SlurmctldPidFile=$WORK/slurmctld.pid
SlurmdPidFile=$WORK/slurmd.pid
SlurmctldLogFile=$WORK/log/slurmctld.log
SlurmdLogFile=$WORK/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MpiDefault=none
ReturnToService=2
SlurmdTimeout=30
NodeName=$host CPUs=$cpus RealMemory=$mem State=UNKNOWN
PartitionName=sylva Nodes=$host Default=YES MaxTime=60 State=UP
CONF
export SLURM_CONF=$WORK/slurm.conf
slurmctld -D -i -f "$SLURM_CONF" >log/slurmctld.out 2>&1 &
pids+=($!)
slurmd -D -f "$SLURM_CONF" >log/slurmd.out 2>&1 &
pids+=($!)
state=
for _ in $(seq 150); do
  state=$(sinfo -h -N -o '%T' 2>/dev/null | head -1)
  [[ $state == idle ]] && break
  sleep 0.2
done
[[ $state == idle ]] || { logs; cat log/*.out; skip "the one-node cluster did not come up (node state '${state}')"; }
echo "Slurm $(sinfo -V 2>/dev/null | cut -d' ' -f2): node $host, $cpus CPUs, $mem MB, port $port"

# The farm job, as docs/cli.md shows it: one array task per tile (task ids 0..3, tiles 1..4).
PROJECT="$DATA/projects/small.sylva"
cat > forest.sbatch <<JOB
#!/bin/bash
#SBATCH --job-name=sylva-forest
#SBATCH --array=0-3
#SBATCH --cpus-per-task=1
#SBATCH --output=$WORK/out/slurm-%A_%a.out
set -euo pipefail
tile=\$((SLURM_ARRAY_TASK_ID + 1))
"$CLI" forest "$PROJECT" -o "$WORK/out/tiles/forest_\${tile}.usda" --tile \${tile}/4 \\
    --threads \${SLURM_CPUS_PER_TASK}
echo "tile \${tile} on \$(hostname) done"
JOB
timeout 300 sbatch --wait --chdir="$WORK/out" forest.sbatch > sbatch.txt 2>&1
status=$?
cat sbatch.txt
for f in out/slurm-*.out; do echo "--- $f"; cat "$f"; done
[[ $status == 0 ]] || { logs; fail "the array job failed (sbatch --wait: $status)"; }
[[ $(grep -l "done" out/slurm-*.out | wc -l) == 4 ]] || fail "not all 4 array tasks ran"

"$CLI" compose out/forest.usda out/tiles/forest_*.usda || fail "compose failed"
"$CLI" forest "$PROJECT" -o single/forest.usda || fail "the single run failed"
python3 "$SRC/../cli/usda_trees.py" single/forest.usda > single.txt || fail "cannot list the single run"
python3 "$SRC/../cli/usda_trees.py" out/forest.usda > composed.txt || fail "cannot list the composed run"
[[ -s single.txt ]] || fail "no trees"
diff -u single.txt composed.txt || fail "the Slurm run's composed stage differs from the single run"
echo "PASS [slurm_array]: $(wc -l < composed.txt) trees, 4 tiles by Slurm = the single run"
