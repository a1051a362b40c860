#!/usr/bin/env bash
# vox bench frame at a tiny size: every configuration (lighting row x camera) gets a row in
# frame.csv and frame.json, one per measured frame in frames.csv, the cache's row counts its
# rays and updates and the direct-light row has none; tools/plot_frame.py charts the JSON; bad
# options are one-line errors.
set -u
vox="$1"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
check() {  # check DESCRIPTION COMMAND...
    if "${@:2}"; then echo "ok: $1"; else echo "FAIL: $1"; fail=1; fi
}

"$vox" bench frame --worlds cornell --sizes 32x18 --frames 3 --warmup 1 -o "$tmp/out" >"$tmp/stdout" 2>"$tmp/stderr"
rc=$?
check "bench frame exits 0 ($(tail -3 "$tmp/stderr"))" test $rc -eq 0
check "the table names every configuration" test "$(grep -c '^| cornell | 32x18 |' "$tmp/stdout")" -eq 4
check "progress on stderr" grep -q "bench frame 16/16" "$tmp/stderr"
check "frame.csv: a header and 4 rows" test "$(wc -l <"$tmp/out/frame.csv")" -eq 5
check "frames.csv: a header and 3 frames x 4 configurations" test "$(wc -l <"$tmp/out/frames.csv")" -eq 13

# The JSON parses and holds what the CSV does: wall >= 0, p95 >= median, rays counted, the
# cache's passes and updates only in the cache rows.
check "frame.json parses and is consistent" python3 - "$tmp/out/frame.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
c = d["configs"]
assert len(c) == 4, c
assert {(x["indirect"], x["camera"]) for x in c} == {(i, k) for i in ("cache", "none") for k in ("still", "moving")}
for x in c:
    assert x["frames"] == 3 and x["width"] == 32 and x["height"] == 18, x
    assert 0 < x["wall_median_ms"] <= x["wall_p95_ms"], x
    assert x["gpu_median_ms"] > 0 and x["rays"] >= 32 * 18, x
    assert "primary_rays" in x["pass_ms"] or any(k.startswith("primary") for k in x["pass_ms"]), x
    cache = any(k.startswith("cache.") for k in x["pass_ms"])
    if x["indirect"] == "cache":
        assert cache and x["cache_rays"] > 0 and x["cache_updated"] > 0, x
    else:
        assert not cache and x["cache_rays"] == 0 and x["cache_updated"] == 0, x
    assert x["path"] == ("cornell_sway" if x["camera"] == "moving" else ""), x
PY

if [ -x /usr/bin/python3 ] && /usr/bin/python3 -c 'import matplotlib' 2>/dev/null; then
    out=$(/usr/bin/python3 "$(dirname "$0")/../../tools/plot_frame.py" "$tmp/out/frame.json" "$tmp/charts" 2>&1)
    check "plot_frame.py writes frame_32x18.png ($out)" test -s "$tmp/charts/frame_32x18.png"
else
    echo "skip: no matplotlib for the chart check"
fi

err=$("$vox" bench frame --worlds cornell --cameras sideways -o "$tmp/bad" 2>&1 >/dev/null)
check "a bad camera is a one-line error ($err)" grep -qx "vox: --cameras: expected still and/or moving, got 'sideways'" <<<"$err"
err=$("$vox" bench frame --worlds cornell --indirect-rows sometimes -o "$tmp/bad" 2>&1 >/dev/null)
check "a bad lighting row is a one-line error ($err)" test "$(grep -c . <<<"$err")" -eq 1 -a -n "$(grep 'indirect-rows' <<<"$err")"
exit $fail
