#!/usr/bin/env bash
# `microbake plan --format slurm` on a real single-node Slurm (issue 14 part 2): starts its own munged (own socket,
# the installed key) and a slurmctld and slurmd from a minimal generated slurm.conf (own ports, own state folders,
# all under a temporary folder), submits the planned job array with sbatch, waits for it and checks that every
# asset is byte-identical to `microbake bake`'s. Exit 77 (CTest: skipped) with the reason when not root or when
# slurm-wlm/munge are not installed (scripts/install-deps.sh installs them only with MICROBAKE_SLURM_TEST=1).
# Every wait has a hard limit; the daemons are stopped by their pids on exit.
# Usage: tests/plan/slurm_test.sh MICROBAKE_EXE
set -euo pipefail
exe=$(realpath "$1")
[ "$(id -u)" -eq 0 ] || { echo "SKIPPED: the Slurm test starts slurmctld, slurmd and munged and must run as root"; exit 77; }
for tool in munged slurmctld slurmd sbatch squeue; do
  command -v "$tool" >/dev/null ||
    { echo "SKIPPED: $tool is not installed (MICROBAKE_SLURM_TEST=1 scripts/install-deps.sh installs slurm-wlm, munge)"; exit 77; }
done
[ -r /etc/munge/munge.key ] || { echo "SKIPPED: no munge key (/etc/munge/munge.key)"; exit 77; }

work=$(mktemp -d)
chmod 755 "$work"
pids=()
cleanup() {
  for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done
  sleep 0.5
  for p in "${pids[@]}"; do kill -9 "$p" 2>/dev/null || true; done
  rm -rf "$work"
}
trap cleanup EXIT
fail() {
  echo "FAIL: $*" >&2
  for log in "$work"/slurm/*.log; do echo "--- $log" >&2; tail -n 20 "$log" >&2 || true; done
  exit 1
}
cd "$work"
mkdir -p slurm/state slurm/spool maps scenes

# munged on its own socket
munged --force --socket="$work/slurm/munge.sock" --pid-file="$work/slurm/munged.pid" \
  --log-file="$work/slurm/munged.log" --seed-file="$work/slurm/munge.seed" --key-file=/etc/munge/munge.key
for _ in $(seq 50); do [ -s slurm/munged.pid ] && break; sleep 0.1; done
[ -s slurm/munged.pid ] || fail "munged did not start"
pids+=("$(cat slurm/munged.pid)")

host=$(hostname -s)
port=$((20000 + RANDOM % 20000))
cat > slurm/slurm.conf <<CONF
ClusterName=microbaketest
SlurmctldHost=$host(127.0.0.1)
SlurmUser=root
SlurmdUser=root
SlurmctldPort=$port
SlurmdPort=$((port + 1))
AuthType=auth/munge
AuthInfo=socket=$work/slurm/munge.sock
CredType=cred/munge
StateSaveLocation=$work/slurm/state
SlurmdSpoolDir=$work/slurm/spool
SlurmctldPidFile=$work/slurm/slurmctld.pid
SlurmdPidFile=$work/slurm/slurmd.pid
SlurmctldLogFile=$work/slurm/slurmctld.log
SlurmdLogFile=$work/slurm/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
MpiDefault=none
JobCompType=jobcomp/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
NodeName=$host NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=test Nodes=$host Default=YES MaxTime=10 State=UP
CONF
export SLURM_CONF="$work/slurm/slurm.conf"
timeout 20 slurmctld -i || fail "slurmctld did not start"
for _ in $(seq 100); do [ -s slurm/slurmctld.pid ] && break; sleep 0.1; done
pids+=("$(cat slurm/slurmctld.pid)")
timeout 20 slurmd || fail "slurmd did not start"
for _ in $(seq 100); do [ -s slurm/slurmd.pid ] && break; sleep 0.1; done
pids+=("$(cat slurm/slurmd.pid)")
for _ in $(seq 150); do
  sinfo -h -o %t 2>/dev/null | grep -Eq '^(idle|mix|alloc)' && break
  sleep 0.2
done
sinfo -h -o %t | grep -Eq '^(idle|mix|alloc)' || fail "the node did not come up: $(sinfo 2>&1)"

"$exe" gen bumps --size 32 -o maps/bumps.png -q
"$exe" gen panels --size 32 -o maps/panels.png --creases maps/panels.json -q
cat > scenes/s.json <<JSON
{"camera": {"position": [0, 1.5, 3], "look_at": [0, 0, 0], "fov_y": 45, "width": 16, "height": 12},
 "shapes": [{"type": "plane", "size": [2, 2], "material": "a"}],
 "lights": [{"type": "point", "position": [1, 2, 1], "intensity": [4, 4, 4]}],
 "materials": {
  "a": {"normal_map": {"path": "../maps/bumps.png", "convention": "+Y"},
        "effects": [{"name": "sh", "order": 3}, {"name": "glints", "lut_size": 32, "patch": 8}]},
  "b": {"normal_map": {"path": "../maps/panels.png"},
        "effects": [{"name": "crease", "curves": "../maps/panels.json", "band": 1.5}]}}}
JSON
"$exe" bake scenes/s.json --out-dir baked -q
mkdir -p jobs
"$exe" plan scenes/s.json --out-dir by_slurm --microbake "$exe" --format slurm -o jobs/bake.sbatch >/dev/null
tasks=$(wc -l < jobs/bake.commands)
timeout 120 sbatch --wait --quiet jobs/bake.sbatch || fail "the job array failed or timed out: $(cat slurm-*.out 2>/dev/null)"
expected=$(cd baked && ls | sort)
got=$(cd by_slurm && ls | sort)
[ "$got" = "$expected" ] || fail "Slurm wrote other files: $got, bake: $expected"
for f in $expected; do cmp -s "baked/$f" "by_slurm/$f" || fail "$f differs from bake's"; done
echo "ok: a $tasks-task Slurm job array wrote the $tasks assets bake writes, byte for byte"
