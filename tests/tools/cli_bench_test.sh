#!/usr/bin/env bash
# vox bench recommend picks the cheapest swept setting under the target error, and says so when
# none reaches it; the indirect-light series (errors against the multi-bounce reference) are
# chosen from only with --indirect, and tools/plot_sweep.py charts them apart; with --sampling it
# picks ReSTIR's candidate sampling per scene from vox bench restir's table.
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
if [ $rc -ne 0 ] || ! grep -q "'ris area M=32' (MAE 1.200e-02, 25.00 ms" <<<"$out" \
    || ! grep -q "meets the target: not resolved at this budget (one measurement per setting)" <<<"$out"; then echo "FAIL: $out"; fail=1; else echo "ok: $out"; fi
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
# A sweep with the cost model's columns (and the front's, which recommend does not read): the cost
# decides (not total_ms), and the verdicts say whether every seed met the target and whether the
# choice is cheaper beyond the intervals.
mkdir -p "$tmp/costed"
cat > "$tmp/costed/sweep.csv" <<'CSV'
scene,method,setting,emitters,total_ms,primary_ms,lighting_ms,mae,mse,rmae,indirect,reference_bounces,mean_ratio,seeds,cost_ms,cost_low,cost_high,mae_low,mae_high,mse_low,mse_high,front_mae,front_mse
cornell,restir,"restir area M=32",256,30,2,27,0.010,1e-3,0.1,none,0,1,5,10,9,11,0.009,0.011,1e-3,1e-3,member,unresolved
cornell,ris,"ris area M=32",256,25,2,22,0.012,1e-3,0.1,none,0,1,5,8,7.5,8.5,0.011,0.016,1e-3,1e-3,unresolved,unresolved
cornell,uniform,"uniform area 4 rays",256,2,1,1,0.014,9e-3,0.5,none,0,1,5,8.2,7,9,0.013,0.014,8e-3,1e-2,unresolved,dominated
CSV
out=$("$vox" bench recommend cornell --target-mae 0.015 --sweep "$tmp/costed/sweep.csv"); rc=$?
if [ $rc -ne 0 ] || ! grep -q "'ris area M=32' (MAE 1.200e-02, 8.00 ms per frame \[7.50–8.50\]" <<<"$out" \
    || ! grep -q "meets the target: not resolved at this budget (the seeds' worst MAE 1.600e-02)" <<<"$out" \
    || ! grep -q "cheaper than 'uniform area 4 rays' (8.20 ms \[7.00–9.00\]): not resolved at this budget" <<<"$out"; then
    echo "FAIL: costed: $out"; fail=1; else echo "ok: $out"; fi
out=$("$vox" bench recommend cornell --target-mae 0.011 --sweep "$tmp/costed/sweep.csv"); rc=$?
if [ $rc -ne 0 ] || ! grep -q "meets the target: yes, every seed" <<<"$out" || grep -q "cheaper than" <<<"$out"; then
    echo "FAIL: costed 0.011: $out"; fail=1; else echo "ok: $out"; fi
# --sampling: ReSTIR's candidate sampling per scene from vox bench restir's medians over seeds,
# among the rows that differ only by sampling (not the unbiased or point-light rows), scenes by
# emitter count; overlapping spreads are said.
cat > "$tmp/restir.csv" <<'CSV'
scene,emitters,row,method,sampling,base,equal_time,ms,mse,mse_min,mse_max,mae,mae_min,mae_max,mean_ratio
mountain,9408,"restir sampling=uniform",restir,uniform,"--method restir",0,45,0.05,0.04,0.06,0.02,0.019,0.021,0.9
mountain,9408,"restir sampling=power",restir,power,"--method restir",0,30,0.10,0.05,0.2,0.03,0.02,0.04,0.8
mountain,9408,"restir-unbiased sampling=uniform",restir-unbiased,uniform,"--method restir --unbiased on",0,40,0.001,0.001,0.001,0.001,0.001,0.001,1
mountain,9408,"ris sampling=uniform",ris,uniform,"",22,30,0.001,0.001,0.001,0.001,0.001,0.001,1
cornell,256,"restir sampling=uniform",restir,uniform,"--method restir",0,18,4e-3,3e-3,5e-3,1e-2,1e-2,1e-2,1
cornell,256,"restir sampling=power",restir,power,"--method restir",0,18,1e-3,0.9e-3,1.1e-3,5e-3,5e-3,5e-3,1
cornell,256,"restir-point",restir,power,"--method restir --mode point",0,18,1e-5,1e-5,1e-5,1e-5,1e-5,1e-5,1
letters,1256,"restir",restir,power,"--method restir",0,18,1e-5,1e-5,1e-5,1e-5,1e-5,1e-5,1
CSV
out=$("$vox" bench recommend --sampling --restir "$tmp/restir.csv"); rc=$?
want_cornell="cornell (256 emitters): --sampling power (MSE 1.000e-03, 4.00x lower than uniform; MAE 5.000e-03 vs 1.000e-02; 1.00x its time)"
want_mountain="mountain (9408 emitters): --sampling uniform (MSE 5.000e-02, 2.00x lower than power; MAE 2.000e-02 vs 3.000e-02; 1.50x its time); the seeds' spreads overlap"
if [ $rc -ne 0 ] || [ "$out" != "$want_cornell"$'\n'"$want_mountain" ]; then echo "FAIL: --sampling: $out"; fail=1; else echo "ok: $out"; fi
out=$("$vox" bench recommend mountain --sampling --restir "$tmp/restir.csv"); rc=$?
if [ $rc -ne 0 ] || [ "$out" != "$want_mountain" ]; then echo "FAIL: --sampling mountain: $out"; fail=1; else echo "ok: $out"; fi
err=$("$vox" bench recommend letters --sampling --restir "$tmp/restir.csv" 2>&1 >/dev/null); rc=$?
if [ $rc -eq 0 ] || ! grep -q "no scene 'letters' with ReSTIR rows for two sampling values" <<<"$err"; then echo "FAIL: $err"; fail=1; else echo "ok: $err"; fi
err=$("$vox" bench recommend 2>&1 >/dev/null); rc=$?
if [ $rc -eq 0 ] || ! grep -q "a WORLD is needed" <<<"$err"; then echo "FAIL: $err"; fail=1; else echo "ok: $err"; fi
# The chart: direct points on sweep_<scene>.png, the indirect series on sweep_indirect_<scene>.png.
if [ -x /usr/bin/python3 ] && /usr/bin/python3 -c 'import matplotlib' 2>/dev/null; then
    out=$(/usr/bin/python3 "$(dirname "$0")/../../tools/plot_sweep.py" "$tmp/sweep.csv" "$tmp" 2>&1)
    for f in sweep_cornell.png sweep_indirect_cornell.png sweep_letters.png; do
        if [ ! -s "$tmp/$f" ]; then echo "FAIL: plot_sweep.py did not write $f: $out"; fail=1; else echo "ok: $f"; fi
    done
    if [ -e "$tmp/sweep_indirect_letters.png" ]; then echo "FAIL: an indirect chart for a scene without indirect rows"; fail=1; fi
    # With the cost model's columns: drawn against the cost, with the intervals as bars.
    out=$(/usr/bin/python3 "$(dirname "$0")/../../tools/plot_sweep.py" "$tmp/costed/sweep.csv" "$tmp/costed" 2>&1)
    if [ ! -s "$tmp/costed/sweep_cornell.png" ]; then echo "FAIL: costed chart: $out"; fail=1; else echo "ok: costed chart"; fi
else
    echo "skip: no matplotlib for the chart check"
fi
exit $fail
