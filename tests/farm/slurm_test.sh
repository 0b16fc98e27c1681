#!/usr/bin/env bash
# glint farm on a real Slurm (docs/farm.md): starts a one-node cluster on localhost
# (munged, slurmctld and slurmd, with a slurm.conf written here, nothing of the machine's own),
# submits a 4-tile render and a 3-frame animation with `glint farm submit`, waits for both, and
# checks that the merged image and the frames equal single-process renders bit for bit; then
# that a second submission renders nothing again, that a task that cannot write its part makes
# the finishing job fail and name it, and times 16 tiles through the cluster against a direct
# render. Needs root (slurmd runs the jobs) and Debian's slurm-wlm and munge.
# Usage: slurm_test.sh GLINT SCENE ANIMATED_SCENE WORK_DIR
set -euo pipefail
# slurmd starts the jobs, and only root may start them: as another user, the whole test runs
# under sudo (as .ci/run's apt-get does).
if [[ $EUID != 0 ]]; then
    sudo -n true 2> /dev/null || { echo "FAIL: slurm_test.sh needs root, or sudo without a password" >&2; exit 1; }
    exec sudo -n -E "$0" "$@"
fi
glint=$1 scene=$2 anim=$3 work=$4
fail() {
    echo "FAIL: $*" >&2
    for f in "$work"/slurm/log/*.log; do echo "--- $f" >&2; tail -20 "$f" >&2; done
    exit 1
}
rm -rf "$work"
mkdir -p "$work/slurm/state" "$work/slurm/spool" "$work/slurm/log" "$work/munge"
work=$(cd "$work" && pwd)
cd "$work"

# munge: a key of our own and a socket in the work folder.
chmod 700 munge
dd if=/dev/urandom of=munge/munge.key bs=1024 count=1 status=none
chmod 400 munge/munge.key
/usr/sbin/munged --force --key-file="$work/munge/munge.key" --socket="$work/munge/socket" \
    --pid-file="$work/munge/munged.pid" --log-file="$work/munge/munged.log" \
    --seed-file="$work/munge/munged.seed"

# Ports away from a system Slurm's 6817/6818, different for each run of this test.
port=$((20000 + ($$ % 10000) * 2))
cat > slurm/slurm.conf <<EOF
ClusterName=glinttest
SlurmctldHost=localhost
SlurmctldPort=$port
SlurmdPort=$((port + 1))
AuthType=auth/munge
AuthInfo=socket=$work/munge/socket
CredType=cred/munge
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$work/slurm/state
SlurmdSpoolDir=$work/slurm/spool
SlurmctldPidFile=$work/slurm/slurmctld.pid
SlurmdPidFile=$work/slurm/slurmd.pid
SlurmctldLogFile=$work/slurm/log/slurmctld.log
SlurmdLogFile=$work/slurm/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MpiDefault=none
ReturnToService=2
SchedulerType=sched/backfill
SchedulerParameters=sched_interval=1
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MinJobAge=600
NodeName=localhost NodeAddr=127.0.0.1 CPUs=$(nproc) RealMemory=1 State=UNKNOWN
PartitionName=glint Nodes=localhost Default=YES MaxTime=INFINITE State=UP
EOF
export SLURM_CONF=$work/slurm/slurm.conf
stop_cluster() {
    scontrol shutdown > /dev/null 2>&1 || true
    sleep 1
    for pidfile in slurm/slurmd.pid slurm/slurmctld.pid munge/munged.pid; do
        [[ -f $work/$pidfile ]] && kill "$(cat "$work/$pidfile")" > /dev/null 2>&1 || true
    done
}
trap stop_cluster EXIT
/usr/sbin/slurmctld -f "$SLURM_CONF"
/usr/sbin/slurmd -f "$SLURM_CONF" -N localhost
for _ in $(seq 60); do
    sinfo -h -o %t 2>/dev/null | grep -q idle && break
    sleep 0.5
done
sinfo -h -o %t | grep -q idle || fail "the node did not come up"
echo "ok: one-node Slurm cluster up on port $port"

# Waits for the jobs glint farm submit printed (its last line: array and finishing job ids).
wait_jobs() {
    local ids=$1 deadline=$((SECONDS + 600))
    while squeue -h -j "${ids// /,}" 2>/dev/null | grep -q .; do
        (( SECONDS < deadline )) || fail "jobs $ids still running after 10 minutes"
        sleep 0.5
    done
}
state_of() { scontrol show job "$1" | sed -n 's/.*JobState=\([A-Z_]*\).*/\1/p' | head -1; }
same() {
    local out
    out=$("$glint" compare "$1" "$2" --tolerance 0 --min-fraction 1) || fail "$1 and $2 differ: $out"
    [[ $out == *"max=0@"* && $out == *"rmse_linear=0"* ]] || fail "$1 and $2 differ: $out"
}

# Four tiles, adaptive anti-aliasing (its blocks cut by no tile edge: they are on blocks).
size=(--width 160 --height 120)
ids=$("$glint" farm submit "$scene" -o "$work/tiles.png" --tiles 4 "${size[@]}" --aa adaptive | tail -1)
wait_jobs "$ids"
[[ $(state_of "${ids##* }") == COMPLETED ]] || fail "finishing job ${ids##* }: $(state_of "${ids##* }")"
"$glint" render "$scene" -o direct.png "${size[@]}" --aa adaptive
same direct.png tiles.png
echo "ok: 4 tiles through Slurm, merged = the single-process render"

# Three frames of an animation, one task each, written in a folder whose name has a space (the
# task lines and the #SBATCH paths are quoted).
mkdir "with space"
ids=$("$glint" farm submit "$anim" -o "$work/with space/anim.png" --frames 1-3 --width 96 --height 72 | tail -1)
wait_jobs "$ids"
[[ $(state_of "${ids##* }") == COMPLETED ]] || fail "frames' finishing job: $(state_of "${ids##* }")"
grep -q "3 parts of job .*: complete" "with space/anim.farm/logs/finish.log" || fail "frames not verified"
mkdir direct_frames
(cd direct_frames && "$glint" render "$anim" -o anim.png --frames 1-3 --width 96 --height 72)
for k in 1 2 3; do same "direct_frames/anim$k.png" "with space/anim$k.png"; done
echo "ok: 3 frames through Slurm = the single-process animation"

# Submitting again: every part is complete, nothing is rendered again.
ids=$("$glint" farm submit "$scene" -o "$work/tiles.png" --tiles 4 "${size[@]}" --aa adaptive | tail -1)
wait_jobs "$ids"
[[ $(grep -l "already complete" tiles.farm/logs/task-*.log | wc -l) == 4 ]] ||
    fail "a second submission rendered parts again"
same direct.png tiles.png
echo "ok: a second submission skips the 4 complete parts"

# A task that cannot write its part (a folder in its place) fails after its retries; the
# finishing job runs anyway, fails and names the part.
mkdir -p broken.farm/parts/part-2.png
ids=$("$glint" farm submit "$scene" -o "$work/broken.png" --tiles 4 "${size[@]}" --retries 1 | tail -1)
wait_jobs "$ids"
[[ $(state_of "${ids##* }") == FAILED ]] || fail "finishing job of a broken job: $(state_of "${ids##* }")"
grep -q "part-2.png" broken.farm/logs/finish.log || fail "the finishing job did not name the part"
grep -q "failed 2 times" broken.farm/logs/task-2.log || fail "task 2 did not retry"
[[ ! -e broken.png ]] || fail "a merge with a missing part wrote broken.png"
echo "ok: a failed task fails the finishing job loudly: $(grep -m1 error broken.farm/logs/finish.log)"

# Overhead per task: 16 tiles through the cluster against one direct render of 640x480.
big=(--width 640 --height 480 --aa adaptive)
t0=$(date +%s.%N)
"$glint" render "$scene" -o direct16.png "${big[@]}"
t1=$(date +%s.%N)
ids=$("$glint" farm submit "$scene" -o "$work/tiles16.png" --tiles 16 "${big[@]}" | tail -1)
wait_jobs "$ids"
t2=$(date +%s.%N)
same direct16.png tiles16.png
awk -v t0="$t0" -v t1="$t1" -v t2="$t2" 'BEGIN {
    d = t1 - t0; f = t2 - t1
    printf "timing: 640x480, 16 tiles through Slurm %.2f s, direct %.2f s: %.2f s per task more\n",
           f, d, (f - d) / 16 }'
echo "ok: 16 tiles through Slurm = the direct render"
