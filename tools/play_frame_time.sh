#!/usr/bin/env bash
# What a player waits for in `vox play` at a window size, with play's defaults (full lighting,
# the reconstruction, auto exposure) — issue 37's "≤ 100 ms at 1280×720" figure, under Xvfb:
#   1. a still session, the render-scale controller live: the scale it settles at, and the median
#      wall time of the frames after its last change;
#   2. tools/frame_time.script (flying in, turning, backing out) at that scale fixed (a script turns
#      the controller off so its frames repeat): median and p95 wall time.
# Usage: tools/play_frame_time.sh VOX OUT [WORLD] [WIDTHxHEIGHT] [extra vox play options...]
set -euo pipefail
vox="$1"; out="$2"; world="${3:-sandbox}"; size="${4:-1280x720}"
shift $(($# < 4 ? $# : 4))
here="$(cd "$(dirname "$0")" && pwd)"
mkdir -p "$out"
command -v xvfb-run >/dev/null || { echo "play_frame_time: xvfb-run not found (apt-get install xvfb)" >&2; exit 1; }
screen="-screen 0 $(tr x ' ' <<< "$size" | awk '{print $1 + 64 "x" $2 + 64}')x24"

echo "1. still, auto scale: vox play $world --size $size --frames 300 $*"
xvfb-run -a -s "$screen" "$vox" play "$world" --size "$size" --frames 300 --no-hud \
    --frame-log "$out/still.csv" "$@" > "$out/still.out"
grep "auto scale" "$out/still.out" || true

summary() {  # CSV FIRST_FRAME -> "median p95 scale"
    /usr/bin/env python3 - "$1" "$2" <<'EOF'
import csv, statistics, sys
rows = [r for r in csv.DictReader(open(sys.argv[1])) if int(r["frame"]) >= int(sys.argv[2])]
ms = sorted(float(r["wall_ms"]) for r in rows)
p95 = ms[min(len(ms) - 1, int(0.95 * len(ms)))]
print(f"{statistics.median(ms):.1f} {p95:.1f} {rows[-1]['render_width']}x{rows[-1]['render_height']} {len(ms)}")
EOF
}
# The frames after the controller's last change (it decides every 30 frames).
last=$(grep -o "^frame [0-9]*: render" "$out/still.out" | tail -1 | grep -o "[0-9]*" || echo 0)
read -r median p95 render frames < <(summary "$out/still.csv" "$((last + 1))")
width=${size%x*}; rw=${render%x*}
scale=$(awk -v r="$rw" -v w="$width" 'BEGIN { printf "%.4f", r / w }')
echo "   settled at $render (scale $scale): wall median $median ms, p95 $p95 ms over $frames frames"

echo "2. scripted flight at scale $scale: tools/frame_time.script"
xvfb-run -a -s "$screen" "$vox" play "$world" --size "$size" --render-scale "$scale" --no-hud \
    --script "$here/frame_time.script" --frame-log "$out/flight.csv" "$@" > "$out/flight.out"
read -r median p95 render frames < <(summary "$out/flight.csv" 0)
echo "   $render: wall median $median ms, p95 $p95 ms over $frames frames"
