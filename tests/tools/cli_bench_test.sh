#!/usr/bin/env bash
# vox bench recommend picks the cheapest swept setting under the target error, and says so when
# none reaches it.
set -u
vox="$1"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cat > "$tmp/sweep.csv" <<'CSV'
scene,method,setting,emitters,total_ms,primary_ms,lighting_ms,mae,mse,rmae
cornell,restir,"restir area M=32",256,30,2,27,0.010,1e-3,0.1
cornell,restir,"restir area M=8",256,20,2,17,0.020,2e-3,0.2
cornell,uniform,"uniform area 1 rays",256,8,2,5,0.050,9e-3,0.5
cornell,ris,"ris area M=32",256,25,2,22,0.012,1e-3,0.1
letters,restir,"restir area M=8",1256,5,2,2,0.001,1e-5,0.1
CSV
fail=0
out=$("$vox" bench recommend cornell --target-mae 0.015 --sweep "$tmp/sweep.csv"); rc=$?
if [ $rc -ne 0 ] || ! grep -q "'ris area M=32' (MAE 1.200e-02, 25.00 ms" <<<"$out"; then echo "FAIL: $out"; fail=1; else echo "ok: $out"; fi
out=$("$vox" bench recommend cornell --target-mae 0.001 --sweep "$tmp/sweep.csv"); rc=$?
if [ $rc -eq 0 ] || ! grep -q "no swept setting reaches" <<<"$out"; then echo "FAIL: $out"; fail=1; else echo "ok: $out"; fi
err=$("$vox" bench recommend cornell --target-mae 0.1 --sweep "$tmp/missing.csv" 2>&1 >/dev/null); rc=$?
if [ $rc -eq 0 ] || ! grep -q "missing.csv: no sweep results" <<<"$err"; then echo "FAIL: $err"; fail=1; else echo "ok: $err"; fi
exit $fail
