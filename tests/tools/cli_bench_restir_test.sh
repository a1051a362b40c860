#!/usr/bin/env bash
# vox bench restir on a tiny run (one scene, 32x32, 2 seeds): every row has per-seed values and
# their median and spread for MSE, MAE and the mean ratio, the baselines got an equal-time count,
# the ratios to ReSTIR are there, a --variant row made of lighting options is measured like the
# default rows, the markdown table has a line per row, progress goes to stderr, and bad rows give
# one line and a non-zero exit before any rendering.
source "$(dirname "$0")/test_setup.sh"

err=$("$vox" bench restir cornell --size 32x32 --seeds 2 --frames 4 --ref-spp 16 \
      --variant "restir-point:--mode point" -o "$tmp/r.json" --markdown "$tmp/r.md" 2>&1 >"$tmp/stdout"); rc=$?
if [ $rc -ne 0 ]; then echo "FAIL: exit $rc: $err"; cat "$tmp/stdout"; exit 1; fi
grep -q "cornell: restir, seed 2/2" <<<"$err" || fail "no progress line for the second seed: $err"

/usr/bin/python3 - "$tmp/r.json" <<'PY' || fail "JSON check"
import json, math, sys
d = json.load(open(sys.argv[1]))
assert d["seeds"] == 2 and d["size"] == [32, 32], d
(scene,) = d["scenes"]
assert scene["scene"] == "cornell" and scene["emitters"] > 0 and scene["equal_time_ms"] > 0, scene
rows = {r["name"]: r for r in scene["rows"]}
assert list(rows) == ["restir", "restir-unbiased", "ris", "uniform", "restir-point"], list(rows)
for name, r in rows.items():
    for metric in ("ms", "mse", "mae", "mean_ratio"):
        s, per_seed = r[metric], r["per_seed"][metric]
        assert len(per_seed) == 2 and s["count"] == 2, (name, metric, r)
        assert s["min"] <= s["q1"] <= s["median"] <= s["q3"] <= s["max"], (name, metric, s)
        assert math.isclose(s["median"], sum(per_seed) / 2), (name, metric, s)  # two seeds: the mean
        assert s["min"] == min(per_seed) and s["max"] == max(per_seed), (name, metric, s)
    assert r["mse"]["median"] > 0 and 0.2 < r["mean_ratio"]["median"] < 5, (name, r)
    v = r["versus"]["restir"]
    expect = sorted(a / b for a, b in zip(r["per_seed"]["mse"], rows["restir"]["per_seed"]["mse"]))
    assert math.isclose(v["mse_ratio"]["min"], expect[0]) and math.isclose(v["mse_ratio"]["max"], expect[1]), (name, v)
assert rows["uniform"]["equal_time"]["shadow_rays"] >= 1, rows["uniform"]
assert rows["ris"]["equal_time"]["candidates"] >= 1, rows["ris"]
assert rows["restir"]["equal_time"] is None and rows["restir-point"]["equal_time"] is None
assert "--mode point" in rows["restir-point"]["settings"], rows["restir-point"]
assert "--method uniform" in rows["uniform"]["settings"] and "--shadow-rays" in rows["uniform"]["settings"], rows["uniform"]
assert rows["restir"]["versus"]["restir"]["mse_ratio"]["median"] == 1.0
# MSE x time over ReSTIR's: the seeds' MSE ratio interval times the interleaved rounds' time ratio
# interval; two seeds cannot reach 90 %, so no verdict.
for name, r in rows.items():
    v = r["versus"]["restir"]
    w, t, m = v["mse_time_ratio"], v["time_ratio"], v["mse_ratio"]
    assert t["low"] <= t["median"] <= t["high"] and t["coverage"] >= 0.97, (name, t)
    assert math.isclose(w["low"], m["min"] * t["low"]) and math.isclose(w["high"], m["max"] * t["high"]), (name, w, m, t)
    assert math.isclose(w["median"], m["median"] * t["median"]), (name, w)
    assert math.isclose(w["coverage"], 0.5 * t["coverage"]), (name, w)
    assert w["verdict"] == "unresolved", (name, w)
assert rows["restir"]["versus"]["restir"]["time_ratio"]["median"] == 1.0
PY

# A point depends on its settings and seed alone: ReSTIR's per-seed errors are the same in a run
# without the baselines' fits and timings before them.
"$vox" bench restir cornell --size 32x32 --seeds 2 --frames 4 --ref-spp 16 --rows restir,restir-unbiased \
    -o "$tmp/again.json" >/dev/null 2>&1 || fail "second run"
/usr/bin/python3 - "$tmp/r.json" "$tmp/again.json" <<'PY' || fail "per-seed errors differ between runs"
import json, sys
a, b = ({r["name"]: r for r in json.load(open(f))["scenes"][0]["rows"]} for f in sys.argv[1:3])
for name in ("restir", "restir-unbiased"):
    assert a[name]["per_seed"]["mse"] == b[name]["per_seed"]["mse"], (name, a[name]["per_seed"], b[name]["per_seed"])
PY

# The table: a header naming the ratio columns, one line per row.
grep -q "^| scene | emitters | row | equal time | ms (÷ restir) | MSE | MAE | mean ratio | MSE ÷ restir | MAE ÷ restir | MSE×time ÷ restir \[90 % interval\] |$" "$tmp/r.md" \
    || fail "markdown header: $(head -1 "$tmp/r.md")"
[ "$(grep -c '^| cornell |' "$tmp/r.md")" -eq 5 ] || fail "markdown rows: $(cat "$tmp/r.md")"
grep -q "^| cornell | [0-9]* | uniform | [0-9]* rays | " "$tmp/r.md" || fail "uniform's ray count: $(cat "$tmp/r.md")"

# Bad rows: one line naming the problem, before the GPU is touched.
check_refused() {  # check_refused TEXT args...
    local want="$1"; shift
    local e rc
    e=$("$vox" bench restir cornell -o "$tmp/x.json" "$@" 2>&1 >/dev/null); rc=$?
    if [ $rc -eq 0 ] || [ "$(grep -c . <<<"$e")" -ne 1 ] || ! grep -qF -- "$want" <<<"$e"; then
        fail "'$*' (exit $rc), want one line with '$want': $e"
    else
        echo "ok: $e"
    fi
}
check_refused "is not a lighting option" --variant "x:--no-such-knob 3"
check_refused "--mode" --variant "x:--mode sideways"
check_refused "expected NAME:--knob value" --variant "nocolon"
check_refused "'bogus' is not restir" --rows restir,bogus
check_refused "no row named 'nope'" --versus nope
check_refused "sampling" --sampling power,sideways
[ -e "$tmp/x.json" ] && fail "a refused run wrote its JSON"
exit $((failures > 0))
