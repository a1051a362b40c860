#!/usr/bin/env bash
# vox bench display on a few tiny frames: a summary row per (world, row) with a time and an error,
# per-frame CSV rows, stability lines from a world's timeline, the chart script, and one-line
# errors for bad input.
set -u
vox="$1"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
err=$("$vox" bench display cornell --size 48x32 --scales 0.5 --frames 4 --reference-every 2 --reference-spp 4 \
      --stability-world none -o "$tmp/out" 2>&1 >"$tmp/stdout"); rc=$?
if [ $rc -ne 0 ]; then echo "FAIL: exit $rc: $err"; cat "$tmp/stdout"; exit 1; fi
summary="$tmp/out/summary.csv"
for row in "cornell,raw 0.5,0.5,24x16" "cornell,upsampled 0.5,0.5,24x16" "cornell,denoised 0.5,0.5,24x16" "cornell,raw 1,1,48x32"; do
    if ! grep -q "^$row," "$summary"; then echo "FAIL: no summary row '$row'"; cat "$summary"; fail=1; fi
done
# Four frames, four rows; references at frames 1 and 3.
rows=$(grep -c '^cornell,' "$tmp/out/frames.csv")
errors=$(awk -F, '$1 == "cornell" && $5 != ""' "$tmp/out/frames.csv" | wc -l)
if [ "$rows" -ne 16 ] || [ "$errors" -ne 8 ]; then
    echo "FAIL: frames.csv: $rows rows ($errors with an error), expected 16 (8)"; cat "$tmp/out/frames.csv"; fail=1
else
    echo "ok: frames.csv has $rows rows, $errors with an error"
fi
# Each summary row: a positive time, two reference frames, an error in range, an SSIM in (0, 1].
if ! awk -F, 'NR > 1 && !($10 > 0 && $15 == 2 && $6 >= 0 && $6 < 10 && $8 > 0 && $8 <= 1) { bad = 1 } END { exit bad }' "$summary"; then
    echo "FAIL: summary rows:"; cat "$summary"; fail=1
fi
if ! grep -q "| cornell | denoised 0.5 |" "$tmp/out/table.md"; then echo "FAIL: table.md"; cat "$tmp/out/table.md"; fail=1; fi
if [ -x /usr/bin/python3 ] && /usr/bin/python3 -c 'import matplotlib' 2>/dev/null; then
    out=$(/usr/bin/python3 "$(dirname "$0")/../../tools/plot_display.py" "$tmp/out" "$tmp/chart.png" 2>&1)
    if [ ! -s "$tmp/chart.png" ]; then echo "FAIL: plot_display.py wrote no chart: $out"; fail=1; else echo "ok: chart"; fi
else
    echo "skip: no matplotlib for the chart check"
fi
# Stability on a world with a timeline (the sandbox's: edits, lights, the cart), tiny.
err=$("$vox" bench display sandbox --size 32x24 --scales 0.5 --frames 1 --reference-spp 1 --stability-spp 2 \
      --still-frames 3 --after-frames 4 --ghost-frames 2 -o "$tmp/stab" 2>&1 >"$tmp/stdout2"); rc=$?
if [ $rc -ne 0 ]; then echo "FAIL: stability run exit $rc: $err"; fail=1; fi
for what in '"edit empty",raw 0.5,frames_to_10pct' '"light lamp off",denoised 0.5,frames_to_10pct' '"object cart",raw 1,ghost_trail_frames' 'still_flicker'; do
    if ! grep -q "$what" "$tmp/stab/stability.csv"; then echo "FAIL: stability.csv lacks '$what'"; fail=1; fi
done
if ! grep -q "^| denoised 0.5 |" "$tmp/stab/table.md"; then echo "FAIL: no stability table"; cat "$tmp/stab/table.md"; fail=1; fi
# Bad input: one line, non-zero exit.
err=$("$vox" bench display cornell --scales 2 -o "$tmp/bad" 2>&1 >/dev/null); rc=$?
if [ $rc -eq 0 ] || ! grep -q "scales: 2 is not in" <<<"$err"; then echo "FAIL: --scales 2: $err"; fail=1; fi
err=$("$vox" bench display thin_wall --frames 2 --stability-world none -o "$tmp/bad" 2>&1 >/dev/null); rc=$?
if [ $rc -eq 0 ] || ! grep -q "no \[path\] in the scene and no worlds/paths/thin_wall_flythrough.toml" <<<"$err"; then
    echo "FAIL: a world without a path: $err"; fail=1
fi
exit $fail
