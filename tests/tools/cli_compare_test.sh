#!/usr/bin/env bash
# `vox compare A B`: one clear line on stderr and a non-zero exit for bad input; for good input
# the metrics it prints (zero against itself, MAE/MSE symmetric), a heat map and a JSON record.
source "$(dirname "$0")/test_setup.sh"

expect_error() {  # expect_error PATTERN -- command...
    local pattern="$1"; shift 2
    local err rc
    err=$("$@" 2>&1 >/dev/null); rc=$?
    if [ "$rc" -eq 0 ] || [ "$rc" -ge 128 ]; then fail "'$*' exited $rc (want 1..127)"; return; fi
    if [ "$(printf '%s\n' "$err" | grep -c .)" -ne 1 ] || ! printf "%s" "$err" | grep -qE -- "$pattern"; then
        fail "'$*' printed:"; printf '%s\n' "$err"; echo "  (want one line matching: $pattern)"; return
    fi
    echo "ok: $err"
}
field() { sed -n "s/^$1 *\([^ ]*\).*/\1/p" <<<"$2"; }  # field NAME OUTPUT -> the value after NAME

"$vox" render sandbox --camera overview --size 64x40 -o "$tmp/a.exr" >/dev/null || fail "render a.exr"
"$vox" render sandbox --camera street --size 64x40 -o "$tmp/b.exr" >/dev/null || fail "render b.exr"
"$vox" render sandbox --size 32x20 -o "$tmp/small.exr" >/dev/null || fail "render small.exr"
echo "not an image" > "$tmp/text.exr"

expect_error "nope.exr: no such file" -- "$vox" compare "$tmp/nope.exr" "$tmp/a.exr"
expect_error "nope.exr: no such file" -- "$vox" compare "$tmp/a.exr" "$tmp/nope.exr"
expect_error "text.exr: cannot read EXR" -- "$vox" compare "$tmp/text.exr" "$tmp/a.exr"
expect_error "a.exr is 64x40 but the reference .*small.exr is 32x20" -- "$vox" compare "$tmp/a.exr" "$tmp/small.exr"
expect_error "--heatmap-error: expected abs, squared or relative" -- "$vox" compare "$tmp/a.exr" "$tmp/b.exr" --heatmap-error max
expect_error "must end in .png" -- "$vox" compare "$tmp/a.exr" "$tmp/b.exr" --heatmap "$tmp/h.jpg"
expect_error "required|Extraction|expected" -- "$vox" compare "$tmp/a.exr"

# Against itself: all zero.
out=$("$vox" compare "$tmp/a.exr" "$tmp/a.exr" 2>&1) || fail "compare a a exited non-zero: $out"
for m in MAE MSE RMAE; do
    [ "$(field $m "$out")" = "0" ] || fail "compare a a: $m is '$(field $m "$out")', want 0"
done

# Two different views: positive errors; MAE and MSE symmetric, RMAE relative to the reference.
ab=$("$vox" compare "$tmp/a.exr" "$tmp/b.exr" --heatmap "$tmp/heat/ab.png" --json "$tmp/ab.json" 2>&1) || fail "compare a b: $ab"
ba=$("$vox" compare "$tmp/b.exr" "$tmp/a.exr" 2>&1) || fail "compare b a: $ba"
echo "$ab"
mae=$(field MAE "$ab"); mse=$(field MSE "$ab"); rmae=$(field RMAE "$ab")
awk -v v="$mae" 'BEGIN { exit !(v > 0) }' || fail "MAE of two different views is '$mae'"
awk -v v="$mse" 'BEGIN { exit !(v > 0) }' || fail "MSE of two different views is '$mse'"
[ "$mae" = "$(field MAE "$ba")" ] || fail "MAE not symmetric: $mae vs $(field MAE "$ba")"
[ "$mse" = "$(field MSE "$ba")" ] || fail "MSE not symmetric: $mse vs $(field MSE "$ba")"
[ "$rmae" != "$(field RMAE "$ba")" ] || fail "RMAE should depend on which image is the reference"

# The heat map: a PNG, 64 wide, the image's 40 rows plus the legend strip.
if [ "$(head -c 4 "$tmp/heat/ab.png" | tail -c 3)" != "PNG" ]; then
    fail "no heat map PNG"
else
    dims=$(od -An -tu1 -j16 -N8 "$tmp/heat/ab.png" | awk '{ print $1*16777216+$2*65536+$3*256+$4 "x" $5*16777216+$6*65536+$7*256+$8 }')
    [ "$dims" = "64x57" ] || fail "heat map is $dims, want 64x57 (64x40 plus a 17-row legend)"
fi
# The JSON holds more digits than the printout (9 vs 6 significant): equal to 6 digits.
jmae=$(sed -n 's/.*"mae": \([^,]*\),.*/\1/p' "$tmp/ab.json")
awk -v j="$jmae" -v p="$mae" 'BEGIN { d = j - p; if (d < 0) d = -d; exit !(j != "" && d <= 1e-5 * p) }' ||
    fail "JSON \"mae\": '$jmae' differs from the printed MAE $mae"
grep -q "\"rmae_epsilon\": 0.01" "$tmp/ab.json" || fail "JSON lacks the RMAE epsilon"
grep -q "\"heatmap\": {\"path\"" "$tmp/ab.json" || fail "JSON lacks the heat map"

[ $failures -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "all ok"
