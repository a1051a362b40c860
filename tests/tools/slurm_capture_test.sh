#!/usr/bin/env bash
# vox capture and vox bench sweep as jobs on a live single-node Slurm (slurm_cluster.sh starts it
# under the scratch folder and stops it at exit):
#  1. a capture as 4 array tasks + a join (afterok); one task's capture process SIGKILLed
#     mid-slice is requeued and renders its frames again; joined frames, contact sheet and MP4
#     byte-identical to one process's, the CSV equal outside timings, events and uploads;
#     --status while the tasks run shows Slurm's state of each task;
#  2. a truncated and a deleted frame are found by --status and --join; re-running the command
#     submits only their tasks and renders only them; a task cancelled with scancel cancels the
#     join, and the next re-run renders only that task's frames;
#  3. a sweep of 8 points as 4 array tasks gives one run's CSV (timings and costs aside) and charts.
# The tasks stop at their first manifest update while this script holds the job's lock (flock on
# DIR/job/job.lock, which vox takes for every update): that is how a task is caught mid-slice
# without any timing. Skips (77) only where Slurm cannot run: not root, or not installed.
source "$(dirname "$0")/test_setup.sh"
source "$(dirname "$0")/slurm_cluster.sh"
chmod 755 "$tmp"  # munged runs as the munge user and reaches its key and socket below
# The lock first (tasks blocked on it end at once when cancelled), then the cluster, then the files;
# a SIGTERM (ctest's timeout) goes through the same exit.
trap 'exec 9>&-; slurm_stop; rm -rf "$tmp"' EXIT
trap 'exit 1' TERM INT
slurm_start "$tmp/slurm" || exit $?

# --- helpers ---
wait_for() {  # wait_for WHAT COMMAND...: polls, 0.5 s apart, at most 600 times (a bound, not a timing)
    local what="$1" i
    shift
    for i in $(seq 1 600); do
        "$@" && return 0
        sleep 0.5
    done
    fail "gave up waiting for $what"
    return 1
}
ended() { ! squeue --noheader --jobs="$1" --states=PENDING,RUNNING,CONFIGURING,COMPLETING,REQUEUED,SUSPENDED 2>/dev/null | grep -q .; }
state_of() { squeue --noheader --jobs="$1" --states=all --format=%T 2>/dev/null | head -n 1; }
task_child() {  # task_child ARRAY I: the pid of array task I's capture process (`… --job-task I`)
    local raw pid
    raw=$(squeue --noheader --jobs="$1_$2" --states=RUNNING --format=%A 2>/dev/null)
    [ -n "$raw" ] || return 1
    for pid in $(scontrol listpids "$raw" 2>/dev/null | awk 'NR > 1 { print $1 }'); do
        tr '\0' ' ' <"/proc/$pid/cmdline" 2>/dev/null | grep -q -- "--job-task $2 *$" && { echo "$pid"; return 0; }
    done
    return 1
}
has_child() { task_child "$@" >/dev/null; }
hold_lock() { mkdir -p "$tmp/cap/job" && exec 9>>"$tmp/cap/job/job.lock" && flock 9; }
free_lock() { exec 9>&-; }
comparable() {  # a CSV without the columns that differ by design (timings, events, uploads)
    awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) keep[i] = ($i !~ /_ms$/ && $i != "events" && $i !~ /^upload_/) }
             { line = ""; for (i = 1; i <= NF; i++) if (keep[i]) line = line $i ","; print line }' "$1"
}
same_as_whole() {
    local f n=0
    for f in "$tmp/whole"/frame_*.png; do
        cmp -s "$f" "$tmp/cap/$(basename "$f")" || fail "$(basename "$f") differs from the single process's"
        n=$((n + 1))
    done
    [ "$(ls "$tmp/cap"/frame_*.png | wc -l)" -eq "$n" ] || fail "the job wrote other frames than the single process"
    cmp -s "$tmp/whole/contact_sheet_00000-00015.png" "$tmp/cap/contact_sheet_00000-00015.png" || fail "contact sheets differ"
    cmp -s "$tmp/whole/capture_00000-00015.mp4" "$tmp/cap/capture_00000-00015.mp4" || fail "MP4s differ"
    diff <(comparable "$tmp/whole/capture_00000-00015.csv") <(comparable "$tmp/cap/capture_00000-00015.csv") >/dev/null ||
        fail "the joined CSV differs outside timings, events and uploads"
    echo "ok: $1: $n frames, contact sheet and MP4 byte-identical to one process's; CSV equal outside timings"
}
cap=(capture sandbox --frames 0:15 --size 64x36 --method preview --warmup 2)
# The tasks are submitted held (passed through to sbatch) so that this script takes the lock first.
submit() { "$vox" "${cap[@]}" --out "$tmp/cap" --scheduler slurm --tasks 4 --sbatch-option=--hold >"$tmp/submit.log" 2>&1; }
ids() {
    array=$(sed -n 's/^slurm    array job \([0-9]*\):.*/\1/p' "$tmp/submit.log")
    join=$(sed -n 's/^slurm    join job \([0-9]*\).*/\1/p' "$tmp/submit.log")
}
status() { "$vox" capture --status "$tmp/cap" >"$tmp/$1" 2>&1 || fail "--status exited non-zero"; }

"$vox" "${cap[@]}" --out "$tmp/whole" >"$tmp/whole.log" 2>&1 || { fail "single capture:"; cat "$tmp/whole.log"; }

# --- 1. four array tasks; task 1's capture process killed mid-slice ---
submit || { fail "submit:"; cat "$tmp/submit.log"; }
ids
echo "submitted: array job $array, join job $join"
[ -n "$array" ] && [ -n "$join" ] || { fail "no job ids in:"; cat "$tmp/submit.log"; exit 1; }
grep -q "afterok:$array" "$tmp/submit.log" || fail "the join does not wait for the array (afterok)"
[ "$(squeue --noheader --jobs="$join" --format=%E)" = "afterok:${array}_*(unfulfilled)" ] ||
    fail "join dependency: $(squeue --noheader --jobs="$join" --format=%E)"
hold_lock
scontrol release "$array,$join"
wait_for "task 1's capture process" has_child "$array" 1
status status_running.txt
grep -qE "^1 .* · slurm ${array}_1 RUNNING on $(hostname -s)" "$tmp/status_running.txt" ||
    { fail "status during the run:"; cat "$tmp/status_running.txt"; }
grep -q "^join     not joined · slurm $join PENDING (Dependency)" "$tmp/status_running.txt" || fail "status: join"
echo "--status while the tasks run:"; sed 's/^/  | /' "$tmp/status_running.txt"
child=$(task_child "$array" 1)
kill -9 "$child"
free_lock
wait_for "the join job $join" ended "$join"
[ "$(state_of "$join")" = COMPLETED ] || { fail "join: $(state_of "$join")"; cat "$tmp/cap/job/join.log"; }
log1="$tmp/cap/job/task_1.log"
grep -q "task 1: killed by signal 9 (Killed) on attempt 1 of 3: run again" "$log1" || { fail "task 1's first run:"; cat "$log1"; }
grep -q "task 1: attempt 2 of 3" "$log1" || fail "task 1 was not run again"
grep -q "task 1   frames 4..7: rendering 4 of 4" "$log1" || fail "the requeued task 1 should render its 4 frames"
status status_after_kill.txt
grep -qE "^1 +4\.\.7 +4 +0 +0 +0 +2/3 +done" "$tmp/status_after_kill.txt" || { fail "status after the requeue:"; cat "$tmp/status_after_kill.txt"; }
grep -q "^failures $(hostname): 1 (task 1 attempt 1: killed by signal 9 (Killed) at " "$tmp/status_after_kill.txt" ||
    fail "status does not show the host's failure"
same_as_whole "killed task requeued"

# --- 2. damage, resume, scancel ---
truncate -s 100 "$tmp/cap/frame_00002.png"
rm "$tmp/cap/frame_00009.png"
status status_damaged.txt
grep -qE "^0 +0\.\.3 +3 +0 +1 +0 " "$tmp/status_damaged.txt" && grep -qE "^2 +8\.\.11 +3 +1 +0 +0 " "$tmp/status_damaged.txt" &&
    grep -q "^problem  frame 2: damaged: frame_00002.png: 100 bytes" "$tmp/status_damaged.txt" ||
    { fail "status with damage:"; cat "$tmp/status_damaged.txt"; }
err=$("$vox" capture --join "$tmp/cap" 2>&1 >/dev/null) && fail "--join succeeded with damage"
grep -q "cannot join: frames 1 missing (9); 1 damaged (2: frame_00002.png: 100 bytes" <<<"$err" || fail "--join: '$err'"
submit || { fail "resubmit:"; cat "$tmp/submit.log"; }
ids
grep -q "task 0   frames 0..3: 1 of 4 to render (0 missing, 1 damaged" "$tmp/submit.log" &&
    grep -q "task 1   frames 4..7: complete" "$tmp/submit.log" &&
    grep -q "task 2   frames 8..11: 1 of 4 to render (1 missing" "$tmp/submit.log" &&
    grep -q "^slurm    array job $array: tasks 0,2," "$tmp/submit.log" || { fail "resume:"; cat "$tmp/submit.log"; }
hold_lock
scontrol release "$array,$join"
wait_for "task 2's capture process" has_child "$array" 2
wait_for "task 0's capture process" has_child "$array" 0
status status_resuming.txt
grep -qE "^time .* ETA [0-9:]+ with 2 task\(s\) running" "$tmp/status_resuming.txt" ||
    { fail "no ETA while resuming:"; cat "$tmp/status_resuming.txt"; }
echo "--status while resuming:"; sed 's/^/  | /' "$tmp/status_resuming.txt"
scancel "${array}_2"
free_lock
wait_for "the join job $join" ended "$join"
[ "$(state_of "$join")" = CANCELLED ] || fail "the join should be cancelled with task 2, is $(state_of "$join")"
grep -q "task 0   frames 0..3: rendering 1 of 4 (2)" "$tmp/cap/job/task_0.log" || fail "task 0 should render frame 2 only"
status status_cancelled.txt
grep -qE "^2 +8\.\.11 +3 +1 +0 +0 +1/3 +stopped · slurm ${array}_2 CANCELLED" "$tmp/status_cancelled.txt" ||
    { fail "status after scancel:"; cat "$tmp/status_cancelled.txt"; }
# A cancel is the user's decision, not a failure of the task's host: only the SIGKILL is listed.
grep -qx "failures $(hostname): 1 (task 1 attempt 1: killed by signal 9 (Killed) at [0-9TZ:-]*)" "$tmp/status_cancelled.txt" ||
    { fail "the host's failures after scancel:"; grep "^failures" "$tmp/status_cancelled.txt"; }
submit || { fail "second resubmit:"; cat "$tmp/submit.log"; }
ids
grep -q "task 2   frames 8..11: 1 of 4 to render (1 missing" "$tmp/submit.log" &&
    grep -q "^slurm    array job $array: tasks 2," "$tmp/submit.log" || { fail "second resume:"; cat "$tmp/submit.log"; }
scontrol release "$array,$join"
wait_for "the join job $join" ended "$join"
[ "$(state_of "$join")" = COMPLETED ] || fail "join after the second resume: $(state_of "$join")"
grep -q "task 2   frames 8..11: rendering 1 of 4 (9)" "$tmp/cap/job/task_2.log" || fail "task 2 should render frame 9 only"
same_as_whole "damaged, deleted and cancelled frames resumed"

# --- 3. a sweep of 8 points as 4 array tasks ---
sweep=(bench sweep cornell --methods restir,ris --candidates 1,8 --modes point,area --brick-lights on --indirect ""
       --size 32x18 --frames 4 --ref-spp 16 --seeds 2)
"$vox" "${sweep[@]}" -o "$tmp/sweep1" >"$tmp/sweep1.log" 2>&1 || { fail "single sweep:"; cat "$tmp/sweep1.log"; }
"$vox" "${sweep[@]}" -o "$tmp/sweep4" --scheduler slurm --tasks 4 >"$tmp/submit.log" 2>&1 || { fail "sweep job:"; cat "$tmp/submit.log"; }
ids
wait_for "the sweep's join $join" ended "$join"
[ "$(state_of "$join")" = COMPLETED ] || { fail "sweep join: $(state_of "$join")"; cat "$tmp/sweep4/job/join.log"; }
# Without the timings: total_ms, primary_ms, lighting_ms and the cost model's cost_ms, cost_low,
# cost_high (fitted to each task's own rounds), nor the front's columns (each task's front is over
# its own points); errors and their spreads must match exactly.
untimed_sweep() { cut -d, -f1-4,8-14,18-21 "$1"; }
[ "$(grep -c '' "$tmp/sweep4/sweep.csv")" -eq 9 ] || fail "the sweep job's CSV should have 8 points"
diff <(untimed_sweep "$tmp/sweep1/sweep.csv") <(untimed_sweep "$tmp/sweep4/sweep.csv") >/dev/null ||
    { fail "sweep CSVs differ outside timings:"; diff <(untimed_sweep "$tmp/sweep1/sweep.csv") <(untimed_sweep "$tmp/sweep4/sweep.csv"); }
charts1=$(cd "$tmp/sweep1" && ls *.png 2>/dev/null | tr '\n' ' ')
charts4=$(cd "$tmp/sweep4" && ls *.png 2>/dev/null | tr '\n' ' ')
[ "$charts1" = "$charts4" ] || fail "charts differ: '$charts1' vs '$charts4'"
echo "ok: sweep of 8 points as 4 array tasks: CSV as one run's outside timings; charts: ${charts4:-none (no matplotlib)}"

[ $failures -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
