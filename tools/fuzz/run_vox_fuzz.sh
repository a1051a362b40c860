#!/usr/bin/env bash
# Fuzzes the MagicaVoxel .vox path (parse, plan, import, export, import again) for a bounded time.
#   tools/fuzz/run_vox_fuzz.sh [SECONDS=600] [SEED_DIR=../shared/data/vox]
# Builds vox_import_fuzzer in the 'fuzz' preset (clang, libFuzzer, ASan; build/fuzz) and runs it
# on out/fuzz/vox/corpus seeded with the .vox files of SEED_DIR (not committed). Findings go to
# out/fuzz/vox/artifacts/, the log to out/fuzz/vox/fuzz.log. Exit status 0: no finding.
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds="${1:-600}"
seeds="${2:-../shared/data/vox}"
out=out/fuzz/vox
mkdir -p "$out/corpus" "$out/seeds" "$out/artifacts"

cmake --preset fuzz >/dev/null
cmake --build --preset fuzz --target vox_import_fuzzer
cp "$seeds"/*.vox "$out/seeds/"
python3 tools/fuzz/vox_small_seeds.py "$out/seeds" "$seeds"/*.vox
# Inputs up to 64 KiB: the small seeds whole, the real files' first 64 KiB (their headers and
# first models); larger inputs would run a few times a second under ASan.
source tools/fuzz/libfuzzer_run.sh
run_fuzzer run_vox_fuzz vox_import_fuzzer "$out" "$seconds" 65536
