#!/usr/bin/env bash
# vox bench sweep as a job on this machine (--scheduler local): the tasks measure with the
# options the job was submitted with. --seeds was once left off the tasks' command, so each task
# measured the default 3 rounds whatever was asked: the joined CSV's `seeds` column and the
# errors' min-max must be those of one process with the same --seeds.
source "$(dirname "$0")/test_setup.sh"

sweep=(bench sweep cornell --methods ris --candidates 1,4 --modes point --brick-lights on --indirect ""
       --size 16x16 --frames 2 --ref-spp 4 --seeds 2)
"$vox" "${sweep[@]}" -o "$tmp/whole" >"$tmp/whole.log" 2>&1 || { fail "single sweep:"; cat "$tmp/whole.log"; }
"$vox" "${sweep[@]}" -o "$tmp/job" --scheduler local --tasks 2 >"$tmp/job.log" 2>&1 ||
    { fail "sweep job:"; cat "$tmp/job.log"; }
python3 - "$tmp/job/job.json" <<'PY' || fail "the job's task command lacks --seeds 2"
import json, sys
task = json.load(open(sys.argv[1]))["task_command"]
sys.exit(0 if any(a == "--seeds" and b == "2" for a, b in zip(task, task[1:])) else 1)
PY
# The seeds column (14) of every point, and the errors' spreads (18-21), as one process's.
seeds=$(tail -n +2 "$tmp/job/sweep.csv" | cut -d, -f14 | sort -u | tr '\n' ' ')
[ "$seeds" = "2 " ] || fail "the job's points were measured in '$seeds' rounds, not 2"
spreads() { tail -n +2 "$1" | cut -d, -f1-4,8-14,18-21; }
diff <(spreads "$tmp/whole/sweep.csv") <(spreads "$tmp/job/sweep.csv") >/dev/null ||
    { fail "the job's errors differ from one process's:"; diff <(spreads "$tmp/whole/sweep.csv") <(spreads "$tmp/job/sweep.csv"); }
[ "$(grep -c '' "$tmp/job/sweep.csv")" -eq 3 ] || fail "the job's CSV should have 2 points"
# The cost model's own rounds are reported.
grep -q "cost model (2 points, [0-9]* rounds)" "$tmp/whole.log" || fail "no cost model line: $(tail -3 "$tmp/whole.log")"
[ $failures -eq 0 ] && echo "ok: sweep job of 2 points, --seeds 2 in its tasks, errors as one process's"
exit $((failures > 0))
