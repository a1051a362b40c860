# Sourced by the command-line tests: `vox` from the first argument, a scratch folder removed on
# exit, and a failure counter (exit with `exit $((failures > 0))`).
set -u
vox="$1"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
