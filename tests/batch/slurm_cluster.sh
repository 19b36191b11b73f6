# shellcheck shell=bash
# Private single-node Slurm cluster for tests.  Source this file, then:
#
#   dir=$(mktemp -d); trap 'slurm_cluster_stop "$dir"' EXIT
#   slurm_cluster_start "$dir" || exit 1     # exports SLURM_CONF
#   job=$(sbatch --parsable --array=0-2 --output="$dir/out-%a.txt" --wrap '...')
#   slurm_cluster_wait "$job" || exit 1      # or: sbatch --wait ... (see below)
#
# Everything (config, munge key/socket, state, spool, logs, pid files) lives
# under DIR; the daemons (munged, slurmctld, slurmd) are stopped by the pids
# recorded in DIR/run/started.  Safe under set -euo pipefail.  Needs root
# (slurmd must be root to launch jobs) and the Debian packages slurmctld,
# slurmd, slurm-client and munge.
#
# Unavoidable system-wide side effects:
#  - two TCP ports (SlurmctldPort, SlurmdPort) are listened on, on all
#    interfaces, while the cluster runs (picked free in 20000-39999);
#  - jobs run as the submitting user (root); their slurmstepd processes are
#    reparented to PID 1 (slurm_cluster_stop cancels jobs first), which reaps
#    them (in this container only after a moment: `[slurmstepd] <defunct>`).
# Nothing is written outside DIR (checked: /etc, /run, /var, /dev/shm).
# `sbatch --wait` exits with the highest exit status of the array's tasks
# (1 for a task killed by a signal), but it polls after 2 s, 10 s, 42 s, then
# every 32 s; slurm_cluster_wait polls every 0.2 s.
# The munge client tools do NOT read slurm.conf: call them with
# `munge -S DIR/munge/munge.socket` / `unmunge -S ...`.  sbatch, squeue,
# scontrol, slurmd and slurmstepd find the socket through AuthInfo=socket=.

_slurm_cluster_alive() { # PID NAME: running (not a zombie) and still NAME?
    local stat
    stat=$(cat "/proc/$1/stat" 2>/dev/null) || return 1
    # Field 3 (after "(comm)") is the state; a zombie counts as dead.
    [[ ${stat#*) } != Z* ]] || return 1
    [[ $(cat "/proc/$1/comm" 2>/dev/null) == "$2" ]]
}

_slurm_cluster_listening() { # PORT: is some process listening on TCP PORT?
    [[ -n $(ss -Hltn "sport = :$1" 2>/dev/null) ]]
}

_slurm_cluster_free_port() { # print a TCP port nobody listens on (nor $1)
    local p i
    for ((i = 0; i < 200; i++)); do
        p=$((20000 + RANDOM % 20000))
        [[ $p != "${1:-}" ]] || continue
        _slurm_cluster_listening "$p" || { echo "$p"; return 0; }
    done
    return 1
}

_slurm_cluster_fail() { # DIR REASON: dump logs, stop, one-line reason
    local f
    for f in "$1"/log/*; do
        [[ -s $f ]] || continue
        echo "===== $f =====" >&2
        tail -n 50 "$f" >&2
    done
    slurm_cluster_stop "$1"
    echo "slurm_cluster_start: $2" >&2
    return 1
}

slurm_cluster_start() {
    local dir host ncpu mem ctld_port slurmd_port name pid i state=""
    [[ -n ${1:-} ]] || { echo "usage: slurm_cluster_start DIR" >&2; return 2; }
    mkdir -p "$1" && dir=$(cd "$1" && pwd -P) || return 1
    # slurm.conf values cannot hold blanks.
    [[ $dir != *[[:space:]]* ]] || { echo "slurm_cluster_start: blank in '$dir'" >&2; return 2; }
    host=$(hostname -s)
    ncpu=$(nproc)
    # Leave a margin: slurmd drains the node if RealMemory > what it detects.
    mem=$(awk '/^MemTotal:/ { m = int($2 / 1024 * 0.9); print (m > 0 ? m : 1) }' /proc/meminfo)
    mkdir -p "$dir"/{etc,spool,state,log,run,munge} || return 1
    # munged refuses a socket directory writable by others.  Its warning
    # "Socket is inaccessible" (to other users) is moot: all here run as root.
    chmod 700 "$dir/munge"
    : >"$dir/run/started"

    # --- munge: own key, socket, pid, log and seed file -------------------
    if command -v mungekey >/dev/null; then
        mungekey --create --keyfile="$dir/munge/munge.key" 2>>"$dir/log/munged.log"
    else
        dd if=/dev/urandom of="$dir/munge/munge.key" bs=1 count=1024 status=none
    fi || { _slurm_cluster_fail "$dir" "cannot create munge key"; return 1; }
    chmod 600 "$dir/munge/munge.key"   # owned by us, the user munged runs as
    # -F (foreground) + & makes munged our child: $! is its pid and we reap
    # it on stop (when it forks itself, PID 1 inherits it and, in some
    # containers, leaves a zombie).  --force: we run it as root and accept
    # the sticky world-writable /tmp above DIR.
    munged -F --force --socket="$dir/munge/munge.socket" \
        --key-file="$dir/munge/munge.key" --pid-file="$dir/run/munged.pid" \
        --log-file="$dir/log/munged.log" --seed-file="$dir/munge/munged.seed" \
        </dev/null >>"$dir/log/munged.out" 2>&1 &
    pid=$!
    echo "munged $pid" >>"$dir/run/started"
    for ((i = 0; i < 100; i++)); do   # <= 10 s until it answers
        munge -n -S "$dir/munge/munge.socket" >/dev/null 2>&1 && break
        _slurm_cluster_alive "$pid" munged ||
            { _slurm_cluster_fail "$dir" "munged exited"; return 1; }
        sleep 0.05
    done
    ((i < 100)) || { _slurm_cluster_fail "$dir" "munged not answering"; return 1; }

    # --- slurm.conf --------------------------------------------------------
    if ! ctld_port=$(_slurm_cluster_free_port) ||
        ! slurmd_port=$(_slurm_cluster_free_port "$ctld_port"); then
        _slurm_cluster_fail "$dir" "no free TCP port found"; return 1
    fi
    # Addresses are pinned to 127.0.0.1 so the short host name need not
    # resolve; the node name must still equal `hostname -s` (slurmd uses it).
    cat >"$dir/etc/slurm.conf" <<EOF
ClusterName=iblkit-test
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$dir/munge/munge.socket
CredType=cred/munge
MpiDefault=none
# No cgroups, no systemd: these make the daemons start in well under a second.
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
JobCompType=jobcomp/none
SchedulerType=sched/builtin
# Schedule batch jobs at once (default: up to 3 s later).
SchedulerParameters=batch_sched_delay=0
# CR_Core: each array task takes one core, so ncpu tasks run at once.
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
# Reject at submission a job the node can never run (it would pend forever).
EnforcePartLimits=ALL
MaxArraySize=100001
MaxJobCount=200000
# Keep finished jobs visible to 'scontrol show job' for 5 minutes.
MinJobAge=300
KillWait=5
MailProg=/bin/true
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/run/slurmctld.pid
SlurmdPidFile=$dir/run/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
NodeName=$host NodeAddr=127.0.0.1 CPUs=$ncpu RealMemory=$mem State=UNKNOWN
PartitionName=test Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
    # Read from beside slurm.conf (not /etc/slurm) by slurmd.
    printf 'CgroupPlugin=cgroup/v1\nIgnoreSystemd=yes\n' >"$dir/etc/cgroup.conf"
    : >"$dir/etc/plugstack.conf"   # keep /etc/slurm/plugstack.conf out
    export SLURM_CONF="$dir/etc/slurm.conf"

    # --- slurmctld, slurmd --------------------------------------------------
    # -D keeps them in the foreground so that $! is the daemon's pid (when
    # they fork themselves the pid file appears only later).  Their
    # stdout/stderr go to files so that no pipe of the caller (ctest) is
    # held open.
    slurmctld -D -f "$SLURM_CONF" -L "$dir/log/slurmctld.log" \
        </dev/null >"$dir/log/slurmctld.out" 2>&1 &
    echo "slurmctld $!" >>"$dir/run/started"
    slurmd -D -f "$SLURM_CONF" -L "$dir/log/slurmd.log" \
        </dev/null >"$dir/log/slurmd.out" 2>&1 &
    echo "slurmd $!" >>"$dir/run/started"

    # --- wait (<= 30 s) until the node is idle ------------------------------
    for ((i = 0; i < 300; i++)); do
        # A client that finds no controller retries only after 1 s: ask
        # once slurmctld listens.
        if _slurm_cluster_listening "$ctld_port"; then
            state=$(sinfo -h -o %T 2>/dev/null) || state=""
            [[ $state == idle ]] && return 0
        fi
        while read -r name pid; do
            _slurm_cluster_alive "$pid" "$name" ||
                { _slurm_cluster_fail "$dir" "$name (pid $pid) exited"; return 1; }
        done <"$dir/run/started"
        sleep 0.1
    done
    _slurm_cluster_fail "$dir" "node not idle after 30 s (state: '${state:-none}')"
}

slurm_cluster_stop() {
    local dir=${1:-} conf name pid i n ctld_pid="" pids=()
    [[ -n $dir && -f $dir/run/started ]] || return 0   # never started / stopped
    # Stop in reverse start order: slurmd, slurmctld, munged.
    while read -r name pid; do
        pids=("$name:$pid" "${pids[@]}")
        [[ $name == slurmctld ]] && ctld_pid=$pid
    done <"$dir/run/started"
    # Cancel leftover jobs first: their slurmstepd processes are not our
    # children and would survive slurmd.  Only ask a live slurmctld (clients
    # retry a dead one for seconds), and only this cluster (its SLURM_CONF).
    conf=$dir/etc/slurm.conf
    if [[ -n $ctld_pid ]] && _slurm_cluster_alive "$ctld_pid" slurmctld &&
        [[ -n $(SLURM_CONF=$conf squeue -h -o %i 2>/dev/null) ]]; then
        SLURM_CONF=$conf scancel --full --user="$(id -un)" 2>/dev/null || true
        for ((i = 0; i < 100; i++)); do   # <= 10 s
            [[ -z $(SLURM_CONF=$conf squeue -h -o %i 2>/dev/null) ]] && break
            sleep 0.1
        done
    fi
    for i in "${pids[@]}"; do
        name=${i%%:*} pid=${i#*:}
        _slurm_cluster_alive "$pid" "$name" || continue   # also guards pid reuse
        kill -TERM "$pid" 2>/dev/null || true
        for ((n = 0; n < 100; n++)); do   # 10 s, then SIGKILL
            _slurm_cluster_alive "$pid" "$name" || break
            sleep 0.1
        done
        if _slurm_cluster_alive "$pid" "$name"; then kill -KILL "$pid" 2>/dev/null || true; fi
        # Reap it if it is our child (started with &); its status is moot.
        wait "$pid" 2>/dev/null || true
    done
    mv "$dir/run/started" "$dir/run/stopped"   # makes a second call a no-op
    return 0
}

slurm_cluster_wait() { # JOBID [SECONDS=300]: 0 if every task COMPLETED (exit 0)
    local job=${1:?usage: slurm_cluster_wait JOBID [SECONDS]} limit=${2:-300} i out bad
    for ((i = 0; i < limit * 5; i++)); do
        # squeue lists only unfinished tasks (pending, running, completing).
        [[ -z $(squeue -h -j "$job" -o %i 2>/dev/null) ]] && break
        sleep 0.2
    done
    ((i < limit * 5)) || { echo "slurm_cluster_wait: job $job still running after $limit s" >&2; return 2; }
    # Finished records stay for MinJobAge (300 s).  One line per task.
    out=$(scontrol -o show job "$job" 2>&1) ||
        { echo "slurm_cluster_wait: job $job: $out" >&2; return 1; }
    bad=$(grep -v 'JobState=COMPLETED ' <<<"$out") || return 0
    echo "slurm_cluster_wait: job $job did not complete:" >&2
    awk '{ l = ""; for (i = 1; i <= NF; i++)
             if ($i ~ /^(JobId|ArrayTaskId|JobState|Reason|ExitCode)=/) l = l " " $i
           print " " (l == "" ? $0 : l) }' <<<"$bad" >&2
    return 1
}
