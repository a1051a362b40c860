#!/usr/bin/env bash
# vox bench recommend picks the cheapest swept setting under the target error, and says so when
# none reaches it; the indirect-light series (errors against the multi-bounce reference) are
# chosen from only with --indirect, and tools/plot_sweep.py charts them apart.
set -u
vox="$1"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# The direct-light rows as sweeps before the indirect series wrote them (no last two columns).
cat > "$tmp/sweep.csv" <<'CSV'
scene,method,setting,emitters,total_ms,primary_ms,lighting_ms,mae,mse,rmae,indirect,reference_bounces
cornell,restir,"restir area M=32",256,30,2,27,0.010,1e-3,0.1
cornell,restir,"restir area M=8",256,20,2,17,0.020,2e-3,0.2
cornell,uniform,"uniform area 1 rays",256,8,2,5,0.050,9e-3,0.5
cornell,ris,"ris area M=32",256,25,2,22,0.012,1e-3,0.1
letters,restir,"restir area M=8",1256,5,2,2,0.001,1e-5,0.1
cornell,restir,"indirect none (restir)",256,9,2,6,0.060,1e-3,0.3,none,3
cornell,restir,"indirect cache K=32",256,40,2,37,0.030,2e-3,0.2,cache,3
cornell,restir,"indirect cache K=128",256,60,2,57,0.020,1e-3,0.1,cache,3
cornell,reference,"indirect reference 3 bounces 1 spp",256,50,2,47,0.080,9e-2,0.9,reference,3
CSV
fail=0
out=$("$vox" bench recommend cornell --target-mae 0.015 --sweep "$tmp/sweep.csv"); rc=$?
if [ $rc -ne 0 ] || ! grep -q "'ris area M=32' (MAE 1.200e-02, 25.00 ms" <<<"$out"; then echo "FAIL: $out"; fail=1; else echo "ok: $out"; fi
out=$("$vox" bench recommend cornell --target-mae 0.001 --sweep "$tmp/sweep.csv"); rc=$?
if [ $rc -eq 0 ] || ! grep -q "no swept setting reaches" <<<"$out"; then echo "FAIL: $out"; fail=1; else echo "ok: $out"; fi
err=$("$vox" bench recommend cornell --target-mae 0.1 --sweep "$tmp/missing.csv" 2>&1 >/dev/null); rc=$?
if [ $rc -eq 0 ] || ! grep -q "missing.csv: no sweep results" <<<"$err"; then echo "FAIL: $err"; fail=1; else echo "ok: $err"; fi
# The indirect points (errors against another reference) never answer a direct-light question...
out=$("$vox" bench recommend cornell --target-mae 0.005 --sweep "$tmp/sweep.csv"); rc=$?
if [ $rc -eq 0 ] || ! grep -q "the most accurate is 'restir area M=32' (MAE 1.000e-02" <<<"$out"; then echo "FAIL: $out"; fail=1; else echo "ok: $out"; fi
# ...and with --indirect only they are candidates.
out=$("$vox" bench recommend cornell --indirect --target-mae 0.025 --sweep "$tmp/sweep.csv"); rc=$?
if [ $rc -ne 0 ] || ! grep -q "'indirect cache K=128' (MAE 2.000e-02, 60.00 ms" <<<"$out"; then echo "FAIL: $out"; fail=1; else echo "ok: $out"; fi
err=$("$vox" bench recommend letters --indirect --target-mae 0.1 --sweep "$tmp/sweep.csv" 2>&1 >/dev/null); rc=$?
if [ $rc -eq 0 ] || ! grep -q "no indirect-light rows for scene 'letters'" <<<"$err"; then echo "FAIL: $err"; fail=1; else echo "ok: $err"; fi
# The chart: direct points on sweep_<scene>.png, the indirect series on sweep_indirect_<scene>.png.
if [ -x /usr/bin/python3 ] && /usr/bin/python3 -c 'import matplotlib' 2>/dev/null; then
    out=$(/usr/bin/python3 "$(dirname "$0")/../../tools/plot_sweep.py" "$tmp/sweep.csv" "$tmp" 2>&1)
    for f in sweep_cornell.png sweep_indirect_cornell.png sweep_letters.png; do
        if [ ! -s "$tmp/$f" ]; then echo "FAIL: plot_sweep.py did not write $f: $out"; fail=1; else echo "ok: $f"; fi
    done
    if [ -e "$tmp/sweep_indirect_letters.png" ]; then echo "FAIL: an indirect chart for a scene without indirect rows"; fail=1; fi
else
    echo "skip: no matplotlib for the chart check"
fi
exit $fail
