#!/usr/bin/env bash
# vox bench restir on a tiny run (one scene, 32x32, 2 seeds): every row has per-seed values and
# their median and spread for MSE, MAE and the mean ratio, the baselines got an equal-cost count,
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
assert scene["scene"] == "cornell" and scene["emitters"] > 0 and scene["yardstick_ms"] > 0, scene
# The cost model: five kinds, the rows and each scaled row at two counts, one time per round.
model = scene["cost_model"]
assert list(model["kinds"]) == ["pixels", "light samples", "candidates", "shadow rays", "reuse taps"], model["kinds"]
assert len(model["points"]) == 8 and model["points"][0]["label"] == "restir", model["points"]  # + restir-point
assert all(len(p["work"]) == 5 and len(p["round_ms"]) >= 10 for p in model["points"]), model["points"]
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
# MSE x cost over ReSTIR's: the seeds' MSE ratio interval times the cost model's ratio interval
# over its rounds; two seeds cannot reach 90 %, so no verdict.
for name, r in rows.items():
    v = r["versus"]["restir"]
    w, c, m = v["mse_cost_ratio"], v["cost_ratio"], v["mse_ratio"]
    assert c["low"] <= c["median"] <= c["high"] and c["coverage"] >= 0.97, (name, c)
    assert math.isclose(w["low"], m["min"] * c["low"]) and math.isclose(w["high"], m["max"] * c["high"]), (name, w, m, c)
    assert math.isclose(w["median"], m["median"] * c["median"]), (name, w)
    assert math.isclose(w["coverage"], 0.5 * c["coverage"]), (name, w)
    assert w["verdict"] == "unresolved", (name, w)
    assert v["time_ratio"]["low"] <= v["time_ratio"]["median"] <= v["time_ratio"]["high"], (name, v["time_ratio"])
    if r["equal_time"]:  # not pinned: this run's own count, rounded in equal_time
        assert r["equal_count"] == r["fitted_count"], r
        assert list(r["equal_time"].values()) == [round(r["equal_count"])], r
# The count ladder: a scaled row is rendered at the powers of two around its equal-cost count,
# every seed at each, and its per-seed values are interpolated between them (errors log-log).
for name in ("ris", "uniform"):
    r = rows[name]
    n, rungs = r["equal_count"], r["ladder"]
    lo = rungs[0]["count"]
    assert lo & (lo - 1) == 0 and lo <= n, (name, n, rungs)
    if len(rungs) == 1:
        assert lo == n or lo == 1, (name, n, rungs)
        assert r["per_seed"]["mse"] == rungs[0]["mse"], (name, r)
        continue
    hi = rungs[1]["count"]
    assert hi == 2 * lo and n < hi, (name, n, rungs)
    w = math.log(n / lo) / math.log(2)
    for s in range(2):
        want = math.exp((1 - w) * math.log(rungs[0]["mse"][s]) + w * math.log(rungs[1]["mse"][s]))
        assert math.isclose(r["per_seed"]["mse"][s], want, rel_tol=1e-9), (name, s, r["per_seed"], rungs)
        want_ms = rungs[0]["ms"][s] + (n - lo) / (hi - lo) * (rungs[1]["ms"][s] - rungs[0]["ms"][s])
        assert math.isclose(r["per_seed"]["ms"][s], want_ms, rel_tol=1e-9), (name, s)
assert rows["restir"]["versus"]["restir"]["cost_ratio"]["median"] == 1.0
# The drift and the noise threshold behind the verdicts are recorded.
assert d["cost_drift"] == 0.15 and d["noise"] == 0.05, d
# A row timed as it is in the calibration (unbiased ReSTIR) gets its measured cost ratio: the
# median of its per-round time ratios to ReSTIR's, not the model's.
points = {p["label"]: p for p in model["points"]}
per_round = sorted(a / b for a, b in zip(points["restir-unbiased"]["round_ms"], points["restir"]["round_ms"]))
c = rows["restir-unbiased"]["versus"]["restir"]["cost_ratio"]
n = len(per_round)
want = per_round[n // 2] if n % 2 else 0.5 * (per_round[n // 2 - 1] + per_round[n // 2])
assert math.isclose(c["median"], want, rel_tol=1e-9), (c, per_round)
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

# --counts-from: the scaled rows rendered at the first run's counts, so with the same seeds every
# row's per-seed errors are the first run's, whatever this run's cost model fits.
"$vox" bench restir cornell --size 32x32 --seeds 2 --frames 4 --ref-spp 16 --counts-from "$tmp/r.json" \
    --variant "restir-point:--mode point" -o "$tmp/pinned.json" >/dev/null 2>&1 || fail "pinned run"
/usr/bin/python3 - "$tmp/r.json" "$tmp/pinned.json" <<'PY' || fail "--counts-from did not render the first run's counts"
import json, sys
a, b = ({r["name"]: r for r in json.load(open(f))["scenes"][0]["rows"]} for f in sys.argv[1:3])
for name in ("ris", "uniform"):
    assert a[name]["equal_time"] == b[name]["equal_time"], (name, a[name]["equal_time"], b[name]["equal_time"])
for name in a:
    assert a[name]["per_seed"]["mse"] == b[name]["per_seed"]["mse"], (name, a[name]["per_seed"], b[name]["per_seed"])
PY

# The table: a header naming the ratio columns, one line per row.
grep -q "^| scene | emitters | row | equal cost | cost ÷ restir | ms (÷ restir) | MSE | MAE | mean ratio | MSE ÷ restir | MAE ÷ restir | MSE×cost ÷ restir \[90 % interval\] |$" "$tmp/r.md" \
    || fail "markdown header: $(head -1 "$tmp/r.md")"
[ "$(grep -c '^| cornell |' "$tmp/r.md")" -eq 5 ] || fail "markdown rows: $(cat "$tmp/r.md")"
grep -q "^| cornell | [0-9]* | uniform | [0-9.]* rays\( ([0-9]*–[0-9]*)\)\? | " "$tmp/r.md" || fail "uniform's ray count: $(cat "$tmp/r.md")"

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
echo '{"size": [1, 1]}' > "$tmp/other.json"
check_refused "no equal-cost counts" --counts-from "$tmp/other.json"
[ -e "$tmp/x.json" ] && fail "a refused run wrote its JSON"
exit $((failures > 0))
