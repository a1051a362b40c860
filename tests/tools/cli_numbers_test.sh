#!/usr/bin/env bash
# Every numeric option of every `vox` command refuses NaN, infinities and huge values — and
# 0, -1 and -0.5 wherever they are outside its range — with one line on stderr that names the
# option, and a non-zero exit. The options are not listed here: they are read from each
# command's --help, where a numeric option (FLOAT, INT, UINT) must show its range (the check
# built by tools/vox/number_options.h); one without a range fails the test. The text options
# holding numbers (--size, --pos, --target) are tried below the loop.
source "$(dirname "$0")/test_setup.sh"

commands=("render" "play" "capture" "compare" "info" "import" "export" "start"
          "bench traverse" "bench emitters" "bench restir" "bench accuracy" "bench sweep"
          "bench stability" "bench cache" "bench frame" "bench flythrough" "bench recommend")
values=(nan inf -inf 1e300 1099511627776 0 -1 -0.5)
always_refused=" nan inf -inf 1e300 1099511627776 "

# One line, exit 1..127, naming the option.
expect_refused() {  # expect_refused OPTION -- command...
    local option="$1"; shift 2
    local err rc
    err=$("$@" 2>&1 >/dev/null); rc=$?
    if [ "$rc" -eq 0 ] || [ "$rc" -ge 128 ]; then
        fail "'$*' exited $rc (want 1..127): $err"; return
    fi
    if [ "$(printf '%s\n' "$err" | grep -c .)" -ne 1 ] || ! printf '%s' "$err" | grep -qF -- "$option"; then
        fail "'$*' printed (want one line naming $option):"; printf '%s\n' "$err"; return
    fi
    refused=$((refused + 1))
}

options=0; tried=0; refused=0; skipped=0
declare -A seen
# A value the option takes lets the command go on; this missing world (or stray argument) then
# stops it at once, with a message that does not name the option (so it counts as a failure).
nosuch="$tmp/no-such-world.toml"
for command in "${commands[@]}"; do
    # shellcheck disable=SC2086
    help=$("$vox" $command --help 2>&1) || { fail "vox $command --help"; continue; }
    # "  --fov FLOAT:(1, 179) degrees  ..." -> "--fov|(1, 179) degrees"; a numeric option without a
    # range gives "--name|".
    while IFS='|' read -r option range; do
        [ -n "$option" ] || continue
        options=$((options + 1))
        # The same option with the same range on another command is the same check (the lighting
        # knobs' options come from one function): tried once.
        [ -n "$range" ] && [ -n "${seen["$option|$range"]:-}" ] && continue
        seen["$option|$range"]=1
        tried=$((tried + 1))
        if [ -z "$range" ]; then
            fail "vox $command $option: a numeric option without a range check"
            range="?"
        fi
        for v in "${values[@]}"; do
            if [ "$range" = "?" ]; then  # no range shown: NaN, infinities and huge must still fail
                [[ "$always_refused" == *" $v "* ]] || continue
                # shellcheck disable=SC2086
                expect_refused "$option" -- "$vox" $command "$option=$v" "$nosuch"
                continue
            fi
            # Inside the range (only 0, -1 or -0.5 can be): a value, not an error; not run.
            inside=$(awk -v r="$range" -v v="$v" 'BEGIN {
                if (v !~ /^-?[0-9.]+(e[+-]?[0-9]+)?$/) { print 0; exit }  # nan, inf: in no range
                if (match(r, /^-?[0-9.e+]+\.\.-?[0-9.e+]+/)) {
                    split(substr(r, 1, RLENGTH), b, /\.\./); lo = b[1] + 0; hi = b[2] + 0;
                    print (v == int(v) && v >= lo && v <= hi) ? 1 : 0; exit
                }
                if (match(r, /^[[(]-?[0-9.e+]+, -?[0-9.e+]+[])]/)) {
                    s = substr(r, 1, RLENGTH); lb = substr(s, 1, 1); rb = substr(s, RLENGTH, 1);
                    split(substr(s, 2, RLENGTH - 2), b, /, /); lo = b[1] + 0; hi = b[2] + 0;
                    ok = (lb == "(" ? v > lo : v >= lo) && (rb == ")" ? v < hi : v <= hi);
                    print ok ? 1 : 0; exit
                }
                print "?" }')
            if [ "$inside" = "?" ]; then fail "vox $command $option: cannot read the range '$range'"; break; fi
            if [ "$inside" = 1 ]; then
                [[ "$always_refused" == *" $v "* ]] && fail "vox $command $option: range $range holds $v"
                skipped=$((skipped + 1)); continue
            fi
            # shellcheck disable=SC2086
            expect_refused "$option" -- "$vox" $command "$option=$v" "$nosuch"
        done
    done < <(printf '%s\n' "$help" | awk '
        /^ +(-[a-zA-Z],)?--[a-z0-9-]+ (FLOAT|INT|UINT|NUMBER)/ {
            line = $0; sub(/^ +(-[a-zA-Z],)?/, "", line);
            split(line, w, " "); option = w[1];
            range = "";
            if (match(line, /(FLOAT|INT|UINT|NUMBER)( ...)?:/)) {
                range = substr(line, RSTART + RLENGTH);
                sub(/ +\[.*$/, "", range); sub(/  .*$/, "", range);
            }
            print option "|" range
        }')
done
echo "numeric options: $options ($tried distinct); bad values refused: $refused; in range (not run): $skipped; failures: $failures"
[ "$options" -ge 80 ] || fail "only $options numeric options found in the help (the help format changed?)"

# Numbers inside text options.
for v in nan inf -inf 1e300 -5 0; do
    expect_refused "--size" -- "$vox" render "$nosuch" --size "${v}x64" -o "$tmp/a.png"
    expect_refused "--size" -- "$vox" capture "$nosuch" --size "64x${v}" --out "$tmp/cap"
done
for v in nan inf -inf 1e300; do
    expect_refused "--pos" -- "$vox" render "$nosuch" --pos "1,$v,3" --target 4,5,6 -o "$tmp/a.png"
    expect_refused "--target" -- "$vox" render "$nosuch" --pos 1,2,3 --target "$v,5,6" -o "$tmp/a.png"
    expect_refused "--albedo" -- "$vox" import "$tmp/no-such.vdb" --albedo "0.5,$v,0.5" --dry-run
done
# The messages say what is wrong: a sign, not 4294967291; a whole but too-large number is too large.
err=$("$vox" render "$nosuch" --size -5x64 -o "$tmp/a.png" 2>&1)
grep -qF -- "--size: width must be positive, not -5; allowed: 1..8192 pixels" <<<"$err" || fail "--size -5x64: $err"
err=$("$vox" render "$nosuch" --size 9000x64 -o "$tmp/a.png" 2>&1)
grep -qF -- "--size: width is too large (max 8192), not 9000" <<<"$err" || fail "--size 9000x64: $err"
err=$("$vox" render "$nosuch" --fov 0 -o "$tmp/a.png" 2>&1)
grep -qF -- "--fov: must be positive, not 0; allowed: (1, 179) degrees" <<<"$err" || fail "--fov 0 (is not the default): $err"
err=$("$vox" capture "$nosuch" --fps 0 --out "$tmp/cap" 2>&1)
grep -qF -- "--fps: must be positive, not 0" <<<"$err" || fail "--fps 0 (is not the default): $err"

[ $failures -eq 0 ] && echo "all numeric options checked" || echo "$failures failure(s)"
exit $((failures > 0))
