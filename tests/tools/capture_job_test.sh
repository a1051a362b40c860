#!/usr/bin/env bash
# vox capture as a job without a cluster (--scheduler local, and GNU parallel when installed):
# the joined frames, contact sheet and MP4 are byte-identical to one process's and the joined CSV
# equal outside timings, events and uploads; damaged, deleted and foreign frames are found by
# --status and --join and only they are rendered again by re-running the command; a task that
# keeps failing is given up after --max-attempts, with its runs in --status; a command with other
# settings or another split is refused. The Slurm flows: slurm_capture_test.sh.
source "$(dirname "$0")/test_setup.sh"
cp "$(dirname "$0")/yard.toml" "$tmp/yard.toml"

common=(capture "$tmp/yard.toml" --size 64x48 --method preview --warmup 2)
job() {  # job DIR ARGS... : the job's submitting command, output in DIR.log (appended)
    local dir="$1"; shift
    "$vox" "${common[@]}" --out "$tmp/$dir" --scheduler local --tasks 3 "$@" >>"$tmp/$dir.log" 2>&1
}
# A capture CSV without the columns that differ by design: timings (*_ms), and `events` and
# `upload_*`, which a slice's first frame counts for everything before it (docs/CAPTURE.md).
comparable() {
    awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) keep[i] = ($i !~ /_ms$/ && $i != "events" && $i !~ /^upload_/) }
             { line = ""; for (i = 1; i <= NF; i++) if (keep[i]) line = line $i ","; print line }' "$1"
}
same_as_whole() {  # same_as_whole DIR : frames, sheet, MP4 and CSV equal the single process's
    local dir="$tmp/$1" f n=0
    for f in "$tmp/whole"/frame_*.png; do
        cmp -s "$f" "$dir/$(basename "$f")" || fail "$1: $(basename "$f") differs from the single process's"
        n=$((n + 1))
    done
    cmp -s "$tmp/whole/contact_sheet.png" "$dir/contact_sheet.png" || fail "$1: contact sheets differ"
    diff <(comparable "$tmp/whole/capture.csv") <(comparable "$dir/capture.csv") >/dev/null ||
        fail "$1: joined CSV differs outside timings, events and uploads"
    [ "$(head -1 "$tmp/whole/capture.csv")" = "$(head -1 "$dir/capture.csv")" ] || fail "$1: CSV headers differ"
    if [ -e "$tmp/whole/capture.mp4" ]; then
        cmp -s "$tmp/whole/capture.mp4" "$dir/capture.mp4" || fail "$1: MP4s differ"
    fi
    echo "ok: $1: $n frames, contact sheet$([ -e "$dir/capture.mp4" ] && echo ", MP4") and CSV as one process's"
}
status() { "$vox" capture --status "$tmp/$1" >"$tmp/$1.status" 2>&1 || fail "--status $1 exited non-zero"; }

"$vox" "${common[@]}" --out "$tmp/whole" >"$tmp/whole.log" 2>&1 || { cat "$tmp/whole.log"; fail "single capture"; }

# 1. A new job: three tasks one after another, then the join.
if job a; then
    grep -q "job .*job.json: capture of frames 0..11 in 3 task(s), new" "$tmp/a.log" || fail "no 'new job' line"
    [ "$(grep -c "rendering 4 of 4" "$tmp/a.log")" -eq 3 ] || fail "each task should render its 4 frames"
    same_as_whole a
    status a
    grep -qE "^total +12 of 12 frames done, 0 missing, 0 damaged, 0 with other settings" "$tmp/a.status" ||
        { fail "status after the job:"; cat "$tmp/a.status"; }
    grep -q "^join     joined " "$tmp/a.status" || fail "status does not show the join"
    "$vox" job status "$tmp/a" | diff - "$tmp/a.status" >/dev/null || fail "vox job status differs from --status"
else
    fail "local job:"; cat "$tmp/a.log"
fi

# --render-scale reaches the tasks and the job's settings: a task's frame is one process's at that
# scale (raw preview: lit and written at 32x24).
"$vox" "${common[@]}" --render-scale 0.5 --out "$tmp/half_whole" >"$tmp/half_whole.log" 2>&1 ||
    { cat "$tmp/half_whole.log"; fail "single capture at --render-scale 0.5"; }
if job half --render-scale 0.5; then
    for i in 00001 00005 00010; do
        cmp -s "$tmp/half_whole/frame_$i.png" "$tmp/half/frame_$i.png" ||
            fail "--render-scale 0.5: the job's frame_$i.png differs from one process's"
    done
    grep -q '"render_scale"' "$tmp/half/job.json" || fail "the job's settings do not record --render-scale"
    echo "ok: --render-scale 0.5 reaches the job's tasks (frames as one process's)"
else
    fail "local job at --render-scale 0.5:"; cat "$tmp/half.log"
fi

# 2. Damage: a truncated frame, a deleted one, one recorded with other settings.
truncate -s 100 "$tmp/a/frame_00001.png"
rm "$tmp/a/frame_00006.png"
python3 - "$tmp/a/job.json" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))
m["frames"][10]["settings"] = "fnv1a64:0000000000000000"
json.dump(m, open(sys.argv[1], "w"), indent=1)
PY
status a
grep -qE "^total +9 of 12 frames done, 1 missing, 1 damaged, 1 with other settings" "$tmp/a.status" ||
    { fail "status after the damage:"; cat "$tmp/a.status"; }
grep -q "^problem  frame 1: damaged: frame_00001.png: 100 bytes" "$tmp/a.status" || fail "status does not name the damage"
grep -q "^missing  frames 6" "$tmp/a.status" || fail "status does not name the missing frame"
err=$("$vox" capture --join "$tmp/a" 2>&1 >/dev/null); rc=$?
if [ $rc -ne 1 ] || [ "$(printf '%s\n' "$err" | grep -c .)" -ne 1 ] ||
   ! grep -q "cannot join: frames 1 missing (6); 1 damaged (1: frame_00001.png: 100 bytes" <<<"$err" ||
   ! grep -q "1 made with other settings (10: settings fnv1a64:0000000000000000" <<<"$err"; then
    fail "--join with damage: exit $rc, '$err'"
else
    echo "ok: $err"
fi
: >"$tmp/a.log"
if job a; then
    grep -q "resumed" "$tmp/a.log" || fail "the re-run does not say it resumes"
    grep -q "task 0   frames 0..3: 1 of 4 to render (0 missing, 1 damaged, 0 with other settings)" "$tmp/a.log" ||
        fail "task 0's count"
    grep -q "task 1   frames 4..7: 1 of 4 to render (1 missing, 0 damaged, 0 with other settings)" "$tmp/a.log" ||
        fail "task 1's count"
    grep -q "task 2   frames 8..11: 1 of 4 to render (0 missing, 0 damaged, 1 with other settings)" "$tmp/a.log" ||
        fail "task 2's count"
    [ "$(grep -c "rendering 1 of 4" "$tmp/a.log")" -eq 3 ] || fail "each task should render its one frame"
    same_as_whole a
else
    fail "resume:"; cat "$tmp/a.log"
fi

# 3. A task that keeps failing (a folder where its frame goes) is given up after --max-attempts.
rm "$tmp/a/frame_00005.png" && mkdir "$tmp/a/frame_00005.png"
: >"$tmp/a.log"
if job a --max-attempts 2; then
    fail "a job with a task that cannot write succeeded"
else
    [ "$(grep -c "task 1: exit 1 on attempt" "$tmp/a.log")" -eq 2 ] || { fail "two failed attempts expected:"; cat "$tmp/a.log"; }
    grep -q "task 1: exit 1 on attempt 2 of 2: given up" "$tmp/a.log" || fail "the task was not given up"
    grep -q "^vox: .*/a: task(s) 1 failed; --status shows each run's result" "$tmp/a.log" || fail "no error line naming task 1"
    status a
    grep -qE "^1 +4\.\.7 +3 +0 +1 +0 +2/2 +failed" "$tmp/a.status" || { fail "status of the given-up task:"; cat "$tmp/a.status"; }
    grep -qE "^failures $(hostname): 2 \(task 1 attempt 1: exit 1 at .*; task 1 attempt 2: exit 1 at " "$tmp/a.status" ||
        fail "status does not list the host's failures"
    echo "ok: a failing task was given up after 2 attempts; $(grep '^failures' "$tmp/a.status" | cut -c1-60)…"
fi
rmdir "$tmp/a/frame_00005.png"
: >"$tmp/a.log"
job a && grep -q "task 1   frames 4..7: 1 of 4 to render (1 missing" "$tmp/a.log" && same_as_whole a ||
    { fail "resume after the failure:"; cat "$tmp/a.log"; }

# 4. The same folder with other settings or another split is refused, naming the difference.
expect_refusal() {  # expect_refusal PATTERN SIZE ARGS...
    local pattern="$1" size="$2"; shift 2
    local err rc
    err=$("$vox" capture "$tmp/yard.toml" --size "$size" --method preview --warmup 2 --out "$tmp/a" --scheduler local "$@" \
          2>&1 >/dev/null); rc=$?
    if [ $rc -ne 1 ] || [ "$(printf '%s\n' "$err" | grep -c .)" -ne 1 ] || ! grep -qE -- "$pattern" <<<"$err"; then
        fail "refusal for '$*': exit $rc, '$err'"
    else
        echo "ok: $err"
    fi
}
expect_refusal 'other settings \(size: "64x48" in the job, "32x24" here\)' 32x24 --tasks 3
expect_refusal "is frames 0..11 in 3 tasks, this command asks for 0..11 in 2 tasks" 64x48 --tasks 2

# 5. GNU parallel runs the same tasks.
if parallel --version 2>/dev/null | grep -q "GNU parallel"; then
    if "$vox" "${common[@]}" --out "$tmp/p" --scheduler parallel --tasks 3 --throttle 2 >"$tmp/p.log" 2>&1; then
        same_as_whole p
        [ "$(grep -c '' "$tmp/p/job/parallel.log")" -eq 4 ] || fail "parallel's joblog should list 3 tasks"
    else
        fail "parallel job:"; cat "$tmp/p.log"
    fi
else
    echo "note: GNU parallel is not installed (tools/setup.sh installs it): --scheduler parallel not tested"
fi

[ $failures -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
