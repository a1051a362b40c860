# A throw-away single-node Slurm for the tests (and for trying jobs by hand): munged with a
# random key, then slurmctld and slurmd from a slurm.conf written for this host, everything —
# config, state, spool, logs, pid files, munge's socket and key — under one folder, on ports no
# other cluster here uses. Stopped by the pids in its pid files. Recipe: Debian 12's slurm-wlm
# 22.05 and munge, run as root, no cgroup.conf (see docs/CAPTURE.md#slurm).
#
#   source tests/tools/slurm_cluster.sh
#   slurm_start DIR || exit $?   # 77 with a message when Slurm cannot run here
#   ... sbatch, squeue (SLURM_CONF is exported) ...
#   slurm_stop
#
# The requeue delay is 5 s here (AuthInfo cred_expire; Slurm's default is 120 s) so that a test
# sees a requeued task run again soon.

slurm_dir=""

# Why Slurm cannot start here, or nothing.
slurm_missing() {
    [ "$(id -u)" -eq 0 ] || { echo "not root (slurmd and munged need root)"; return; }
    local p
    for p in munged slurmctld slurmd sbatch squeue scontrol sinfo runuser flock; do
        command -v "$p" >/dev/null || { echo "$p is not installed (tools/setup.sh installs slurm-wlm and munge)"; return; }
    done
    id munge >/dev/null 2>&1 || echo "there is no munge user (the munge package makes it)"
}

# Two TCP ports in a row that nothing listens on (bash's /dev/tcp: a refused connection), below 30000.
slurm_free_port() {
    local port
    for port in $(seq $((20000 + ($$ % 400) * 20)) 2 29998); do
        (: <"/dev/tcp/127.0.0.1/$port") 2>/dev/null && continue
        (: <"/dev/tcp/127.0.0.1/$((port + 1))") 2>/dev/null && continue
        echo "$port"
        return
    done
}

slurm_start() {
    slurm_dir="$1"
    local why
    why=$(slurm_missing)
    if [ -n "$why" ]; then
        echo "SKIP: no Slurm here: $why"
        return 77
    fi
    local d="$slurm_dir" host mem port cpus
    mkdir -p "$d/state" "$d/spool" "$d/log" "$d/munge"
    chown munge: "$d/munge" && chmod 700 "$d/munge"
    head -c 1024 /dev/urandom > "$d/munge/munge.key"
    chown munge: "$d/munge/munge.key" && chmod 400 "$d/munge/munge.key"
    runuser -u munge -- munged --key-file="$d/munge/munge.key" --socket="$d/munge/munge.socket" \
        --pid-file="$d/munge/munged.pid" --seed-file="$d/munge/munged.seed" --log-file="$d/munge/munged.log" --force ||
        { echo "FAIL: munged did not start: $(tail -n 3 "$d/munge/munged.log" 2>/dev/null)"; return 1; }
    host=$(hostname -s)
    mem=$(awk '/MemTotal/ { print int($2 / 1024 * 0.9) }' /proc/meminfo)
    port=$(slurm_free_port)
    # At least 4 CPUs whatever the machine has (config_overrides): every test sees the same
    # number of tasks running at once; more than the cores is fine, they share them.
    cpus=$(( $(nproc) > 4 ? $(nproc) : 4 ))
    cat > "$d/slurm.conf" <<CONF
ClusterName=voxtest
SlurmctldHost=$host
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$d/munge/munge.socket,cred_expire=5
CredType=cred/munge
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
ReturnToService=2
StateSaveLocation=$d/state
SlurmdSpoolDir=$d/spool
SlurmctldPidFile=$d/slurmctld.pid
SlurmdPidFile=$d/slurmd.pid
SlurmctldLogFile=$d/log/slurmctld.log
SlurmdLogFile=$d/log/slurmd.log
SlurmdParameters=config_overrides
NodeName=$host CPUs=$cpus RealMemory=$mem State=UNKNOWN
PartitionName=main Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
    export SLURM_CONF="$d/slurm.conf"
    slurmctld || { echo "FAIL: slurmctld did not start: $(tail -n 3 "$d/log/slurmctld.log")"; return 1; }
    slurmd || { echo "FAIL: slurmd did not start: $(tail -n 3 "$d/log/slurmd.log")"; return 1; }
    local i
    for i in $(seq 1 150); do  # the node registers within a few seconds
        if sinfo --noheader --format=%t 2>/dev/null | grep -qE '^(idle|mix|alloc)'; then
            echo "slurm: node $host idle ($cpus CPUs, ports $port-$((port + 1)), $d)"
            return 0
        fi
        sleep 0.2
    done
    echo "FAIL: the Slurm node did not become idle: $(sinfo --noheader 2>&1) $(tail -n 3 "$d/log/slurmd.log")"
    return 1
}

slurm_stop() {
    [ -n "$slurm_dir" ] || return 0
    local f pid i jobs
    # Jobs first: their processes would outlive slurmd.
    jobs=$(squeue --noheader --format=%A 2>/dev/null | sort -u | tr '\n' ' ')
    if [ -n "${jobs// /}" ]; then
        scancel $jobs 2>/dev/null
        for i in $(seq 1 100); do squeue --noheader 2>/dev/null | grep -q . || break; sleep 0.2; done
    fi
    for f in "$slurm_dir/slurmd.pid" "$slurm_dir/slurmctld.pid" "$slurm_dir/munge/munged.pid"; do
        [ -f "$f" ] || continue
        pid=$(cat "$f")
        kill "$pid" 2>/dev/null || continue
        for i in $(seq 1 100); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    done
    slurm_dir=""
}
