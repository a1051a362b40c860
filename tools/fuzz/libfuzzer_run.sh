# Sourced by the run_*_fuzz.sh scripts: one libFuzzer run and its summary, the same for every target.
#   run_fuzzer NAME TARGET OUT SECONDS MAX_LEN
# Runs build/fuzz/tools/fuzz/TARGET on OUT/corpus seeded from OUT/seeds for SECONDS, findings to
# OUT/artifacts/, the whole log to OUT/fuzz.log; prints libFuzzer's pulses and final statistics and
# a last line "NAME: exit S, N executions, K artifact(s)". Returns the fuzzer's exit status (0: no
# finding). Leak checks stay on; returning null from an over-large malloc is never needed, as the
# engine's allocation budget refuses such requests before they reach malloc.
run_fuzzer() {
    local name="$1" target="$2" out="$3" seconds="$4" max_len="$5" status execs findings
    echo "$name: $(ls "$out/seeds" | wc -l) seed files, fuzzing for ${seconds}s"
    export ASAN_OPTIONS="${ASAN_OPTIONS:-abort_on_error=1:detect_leaks=1}"
    set +e
    "build/fuzz/tools/fuzz/$target" "$out/corpus" "$out/seeds" \
        -max_total_time="$seconds" -max_len="$max_len" -timeout=30 -rss_limit_mb=2048 \
        -artifact_prefix="$out/artifacts/" -print_final_stats=1 2>&1 | tee "$out/fuzz.log" |
        grep -E "^#[0-9]+.*(pulse|DONE)|ERROR|SUMMARY|stat::" | tail -n 40
    status=${PIPESTATUS[0]}
    set -e
    execs=$(grep -E "stat::number_of_executed_units" "$out/fuzz.log" | awk '{print $2}' | tail -1)
    findings=$(ls "$out/artifacts" | wc -l)
    echo "$name: exit ${status}, ${execs:-?} executions, ${findings} artifact(s) in $out/artifacts"
    return "$status"
}
