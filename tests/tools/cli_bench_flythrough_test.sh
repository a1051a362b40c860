#!/usr/bin/env bash
# vox bench flythrough on a few tiny frames: every method gets a summary row with a time and an
# error, the per-frame CSV has a row per measured frame and method, progress goes to stderr, the
# chart script reads the summary, and bad input gives one line and a non-zero exit.
set -u
vox="$1"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
err=$("$vox" bench flythrough cornell --size 32x18 --frames 7 --warmup 3 --reference-every 2 --reference-spp 32 \
      --path-spp 1,2 -o "$tmp/out" 2>&1 >"$tmp/stdout"); rc=$?
if [ $rc -ne 0 ]; then echo "FAIL: exit $rc: $err"; cat "$tmp/stdout"; exit 1; fi
summary="$tmp/out/summary.csv"
for method in "cornell,none,0," "cornell,cache,0," "cornell,path,1," "cornell,path,2,"; do
    if ! grep -q "^$method" "$summary"; then echo "FAIL: no summary row '$method'"; cat "$summary"; fail=1; fi
done
# Four measured frames (3..6), four methods; references at frames 3 and 5: every row has a time,
# the reference frames an error.
rows=$(grep -c '^cornell,' "$tmp/out/frames.csv")
errors=$(awk -F, '$1 == "cornell" && $6 != ""' "$tmp/out/frames.csv" | wc -l)
if [ "$rows" -ne 16 ] || [ "$errors" -ne 8 ]; then
    echo "FAIL: frames.csv: $rows rows ($errors with an error), expected 16 (8)"; cat "$tmp/out/frames.csv"; fail=1
else
    echo "ok: frames.csv has $rows rows, $errors with an error"
fi
# Each summary row: a positive time, two reference frames, a finite error.
if ! awk -F, 'NR > 1 && !($4 > 0 && $10 == 2 && $6 >= 0 && $6 < 1e6) { bad = 1 } END { exit bad }' "$summary"; then
    echo "FAIL: summary rows:"; cat "$summary"; fail=1
fi
# No indirect term: its error is the whole of the reference's indirect light.
if ! awk -F, '$2 == "none" && ($7 < 0.999 || $7 > 1.001) { bad = 1 } END { exit bad }' "$summary"; then
    echo "FAIL: 'none' should have a relative error of 1:"; cat "$summary"; fail=1
fi
if ! grep -q "cornell" <<<"$err"; then echo "FAIL: no progress on stderr: $err"; fail=1; fi
if ! grep -q "| cornell | cache |" "$tmp/out/table.md"; then echo "FAIL: table.md"; cat "$tmp/out/table.md"; fail=1; fi
if [ -x /usr/bin/python3 ] && /usr/bin/python3 -c 'import matplotlib' 2>/dev/null; then
    out=$(/usr/bin/python3 "$(dirname "$0")/../../tools/plot_flythrough.py" "$summary" "$tmp/chart.png" 2>&1)
    if [ ! -s "$tmp/chart.png" ]; then echo "FAIL: plot_flythrough.py wrote no chart: $out"; fail=1; else echo "ok: chart"; fi
else
    echo "skip: no matplotlib for the chart check"
fi
# Bad input: one line, non-zero exit.
err=$("$vox" bench flythrough cornell --path-spp 0 -o "$tmp/bad" 2>&1 >/dev/null); rc=$?
if [ $rc -eq 0 ] || ! grep -q "path-spp: must be positive, not 0" <<<"$err"; then echo "FAIL: --path-spp 0: $err"; fail=1; fi
err=$("$vox" bench flythrough thin_wall --frames 2 -o "$tmp/bad" 2>&1 >/dev/null); rc=$?
if [ $rc -eq 0 ] || ! grep -q "no flythrough for this world (worlds/paths/thin_wall_flythrough.toml)" <<<"$err"; then
    echo "FAIL: a world without a flythrough: $err"; fail=1
fi
exit $fail
