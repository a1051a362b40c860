#!/usr/bin/env bash
# vox capture through the command line: the same command twice writes byte-identical frames and
# the same CSV apart from its timing columns (*_ms); a preview slice equals the whole capture's
# frames exactly; every output is there; bad path files give one line naming file and line.
source "$(dirname "$0")/test_setup.sh"

cp "$(dirname "$0")/yard.toml" "$tmp/yard.toml"

run() {  # run DIR ARGS... : a capture of the yard, stdout+stderr in DIR.log
    local dir="$1"; shift
    if ! "$vox" capture "$tmp/yard.toml" --out "$tmp/$dir" --size 64x48 --no-video "$@" >"$tmp/$dir.log" 2>&1; then
        fail "vox capture $* exited non-zero:"; cat "$tmp/$dir.log"; return 1
    fi
}
# The CSV without its timing columns (names ending in _ms).
untimed() {
    awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) keep[i] = ($i !~ /_ms$/) }
             { line = ""; for (i = 1; i <= NF; i++) if (keep[i]) line = line $i ","; print line }' "$1"
}

# 1. Determinism: ReSTIR (temporal history, events, a moving camera), twice.
run a && run b && {
    n=$(ls "$tmp/a"/frame_*.png | wc -l)
    [ "$n" -eq 12 ] || fail "expected 12 frames, got $n"
    for f in "$tmp/a"/frame_*.png; do
        cmp -s "$f" "$tmp/b/$(basename "$f")" || fail "$(basename "$f") differs between two identical runs"
    done
    [ "$(wc -l < "$tmp/a/capture.csv")" -eq 13 ] || fail "capture.csv should have a header and 12 rows"
    if ! diff <(untimed "$tmp/a/capture.csv") <(untimed "$tmp/b/capture.csv") >/dev/null; then
        fail "capture.csv differs outside its timing columns"
    fi
    grep -q "gpu_restir_temporal_ms" "$tmp/a/capture.csv" || fail "capture.csv lacks per-pass GPU columns"
    [ "$(head -c 4 "$tmp/a/contact_sheet.png" | tail -c 3)" = "PNG" ] || fail "no contact sheet"
    grep -q "video    skipped (--no-video)" "$tmp/a.log" || fail "--no-video was not reported"
    # Events show in the counts: the lamp brick goes dark on frame 3, the new block lights on frame 6.
    emitters=$(awk -F, 'NR > 1 { printf "%s ", $11 }' "$tmp/a/capture.csv")
    [[ "$emitters" == "1 1 1 0 0 0 "* ]] || fail "emitters per frame: $emitters"
    # Every method reports its rays (ReSTIR: a bound from its per-pixel counts) and, without the
    # cache, no visible cache voxels.
    counts=$(awk -F, 'NR == 2 { print $12, $15, $16, $17 }' "$tmp/a/capture.csv")
    read -r primary rays visible how <<<"$counts"
    [ "$how" = bound ] && [ "$rays" -gt "$primary" ] && [ "$visible" = 0 ] ||
        fail "ReSTIR rays / visible_cache_voxels / rays_how: '$counts'"
    echo "ok: two ReSTIR captures are identical (12 PNGs, CSV without *_ms); emitters per frame: $emitters"
}

# 2. A preview slice is the whole capture's frames, exactly, and says which frames it holds.
run p --method preview && run s --method preview --frames 5:8 --warmup 0 && {
    for i in 5 6 7 8; do
        f=$(printf "frame_%05d.png" "$i")
        cmp -s "$tmp/p/$f" "$tmp/s/$f" || fail "preview slice frame $i differs from the whole capture"
    done
    [ ! -e "$tmp/s/frame_00004.png" ] && [ ! -e "$tmp/s/frame_00009.png" ] || fail "the slice wrote frames outside 5:8"
    [ -e "$tmp/s/capture_00005-00008.csv" ] && [ -e "$tmp/s/contact_sheet_00005-00008.png" ] ||
        fail "slice outputs are not named after the slice"
    # Frame, time, camera and counts agree; the events and upload columns differ by design (a
    # slice applies earlier events and uploads the whole world before its first frame).
    diff <(cut -d, -f1,2,4-15 "$tmp/p/capture.csv" | sed -n '7,10p') \
         <(cut -d, -f1,2,4-15 "$tmp/s/capture_00005-00008.csv" | tail -n +2) >/dev/null ||
        fail "the slice's CSV rows differ from the whole capture's"
    rays=$(awk -F, 'NR == 2 { print $15 }' "$tmp/p/capture.csv")
    [ -n "$rays" ] && [ "$rays" -ge 3072 ] || fail "preview rays column: '$rays'"
    [ "$(awk -F, 'NR == 2 { print $17 }' "$tmp/p/capture.csv")" = counted ] || fail "preview rays are not marked counted"
    echo "ok: preview slice 5:8 equals the whole capture's frames 5..8"
}
# With the irradiance cache: the visible cache voxels, and the cache's rays on top of ReSTIR's.
run c --indirect cache --frames 0:2 --warmup 0 && {
    counts=$(awk -F, 'NR == 2 { print $15, $16, $17 }' "$tmp/c/capture_00000-00002.csv")
    read -r rays visible how <<<"$counts"
    arays=$(awk -F, 'NR == 2 { print $15 }' "$tmp/a/capture.csv")
    [ "$how" = bound ] && [ "$visible" -gt 0 ] && [ "$rays" -gt "$arays" ] ||
        fail "cache rays / visible_cache_voxels / rays_how: '$counts' (ReSTIR alone: $arays rays)"
    echo "ok: with the cache, frame 0: $rays rays, $visible visible cache voxels"
}
# A slice with warm-up renders the warm-up frames without writing them.
run w --frames 9: --warmup 4 && {
    [ "$(ls "$tmp/w"/frame_*.png | wc -l)" -eq 3 ] || fail "--frames 9: should write frames 9..11"
    grep -q "after 4 warm-up frame(s)" "$tmp/w.log" || fail "the warm-up was not reported"
    echo "ok: --frames 9: --warmup 4 wrote 3 frames"
}

# --render-scale as in vox render: the lighting at a fraction of --size, the reconstruction
# (--display upsampled) resolving it to --size; raw frames are the lit image, at the render size.
png_size() { od -An -tu1 -j16 -N8 "$1" | awk '{ print $3 * 256 + $4 "x" $7 * 256 + $8 }'; }
run h --render-scale 0.5 --display upsampled --frames 0:1 --warmup 0 && {
    for f in "$tmp/h"/frame_*.png; do
        [ "$(png_size "$f")" = 64x48 ] || fail "$(basename "$f") is $(png_size "$f"), want --size 64x48"
    done
    grep -q "64x48, lit at 32x24 (--render-scale 0.5)" "$tmp/h.log" || fail "the render size was not reported"
    rays=$(awk -F, 'NR == 2 { print $12 }' "$tmp/h/capture_00000-00001.csv")
    [ "$rays" = 768 ] || fail "primary_rays at --render-scale 0.5: '$rays', want 32x24 = 768"
    echo "ok: --render-scale 0.5 --display upsampled: 64x48 frames lit at 32x24"
}
run hr --render-scale 0.5 --frames 0:0 --warmup 0 && {
    [ "$(png_size "$tmp/hr/frame_00000.png")" = 32x24 ] || fail "a raw frame at --render-scale 0.5 is $(png_size "$tmp/hr/frame_00000.png"), want 32x24"
    echo "ok: --render-scale 0.5 --display raw: 32x24 frames"
}

# With ffmpeg on PATH the capture ends with an MP4 of every written frame; without, it says so.
if command -v ffmpeg >/dev/null && command -v ffprobe >/dev/null; then
    if "$vox" capture "$tmp/yard.toml" --out "$tmp/v" --size 64x48 --method preview >"$tmp/v.log" 2>&1; then
        frames=$(ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames -of csv=p=0 "$tmp/v/capture.mp4")
        [ "$frames" = "12" ] || fail "capture.mp4 holds '$frames' frames, want 12"
        echo "ok: capture.mp4 with $frames frames"
    else
        fail "capture with video failed:"; cat "$tmp/v.log"
    fi
else
    PATH=/nonexistent "$vox" capture "$tmp/yard.toml" --out "$tmp/v" --size 32x24 --method preview >"$tmp/v.log" 2>&1 ||
        fail "capture without ffmpeg failed"
    grep -q "video    skipped: ffmpeg is not on PATH" "$tmp/v.log" || fail "a missing ffmpeg was not reported"
    echo "ok: no ffmpeg on PATH: video skipped with a message (MP4 not tested)"
fi

# 3. Bad input: one line naming the file (and line), a non-zero exit.
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
key='[[path.key]]\ntime = 0\nposition = [0, 30, 0]\ntarget = [30, 0, 30]\n'
printf "[path]\n$key[[path.key]]\ntime = 1\nposition = [9, 30, 0]\ntarget = [30, 0, 30]\nfovy = 40\n" > "$tmp/typo.toml"
printf "[path]\nduration = 1\n$key[[path.event]]\ntime = 0.5\ntype = \"box\"\nmin = [0, 0, 0]\nmax = [4, 4, 4]\nmaterial = \"gold\"\n" > "$tmp/gold.toml"
printf "[path]\n$key[[path.key]]\ntime = 0\nposition = [9, 30, 0]\ntarget = [30, 0, 30]\n" > "$tmp/order.toml"
printf "[path]\n$key[[path.event]]\ntime = 0\ntype = \"light\"\nmaterial = \"lamp\"\non = \"off\"\n" > "$tmp/onoff.toml"
printf "[path\n" > "$tmp/syntax.toml"
printf '[world]\nsize = [16, 16, 16]\n' > "$tmp/nopath.toml"
c=("$vox" capture "$tmp/yard.toml" --out "$tmp/e" --size 16x16 --no-video)
expect_error "typo.toml:10: unknown key 'fovy'" -- "${c[@]}" --path "$tmp/typo.toml"
expect_error "gold.toml:12: unknown material 'gold'" -- "${c[@]}" --path "$tmp/gold.toml"
expect_error "order.toml:7: key times must increase" -- "${c[@]}" --path "$tmp/order.toml"
expect_error "onoff.toml:10: 'on' must be true or false" -- "${c[@]}" --path "$tmp/onoff.toml"
expect_error "syntax.toml:1:" -- "${c[@]}" --path "$tmp/syntax.toml"
expect_error "nopath.toml: no \[path\] table" -- "$vox" capture "$tmp/nopath.toml" --out "$tmp/e"
expect_error "--path nosuchpath: no such path file" -- "${c[@]}" --path nosuchpath
expect_error "--frames: frame 40 is past the path's last frame \(11\)" -- "${c[@]}" --frames 40:50
expect_error "--frames: expected A:B" -- "${c[@]}" --frames 3-5
expect_error "--frames: 5:3 ends before it starts" -- "${c[@]}" --frames 5:3
# Negative frames are refused as given, not read as 4294967295 (nor a last frame of -1 as "to the end").
expect_error "--frames: the first frame is too small \(min 0\), not -1" -- "${c[@]}" --frames -1:
expect_error "--frames: the last frame is too small \(min 0\), not -1" -- "${c[@]}" --frames 3:-1
expect_error "required|--out" -- "$vox" capture "$tmp/yard.toml"
expect_error "--render-scale: must be positive, not 0; allowed: \[0.0625, 1\]" -- "${c[@]}" --render-scale 0
expect_error "--render-scale: too large \(max 1\), not 2" -- "${c[@]}" --render-scale 2

[ $failures -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
