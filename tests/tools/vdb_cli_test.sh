#!/usr/bin/env bash
# OpenVDB through the `vox` binary.
#   vdb_cli_test.sh vdb_print VOX SAMPLES  OpenVDB's own vdb_print reads our files: grids, types and
#                                          voxel counts as expected (exit 77 = skipped, no vdb_print)
#   vdb_cli_test.sh errors VOX SAMPLES     bad files give one line naming the file and exit 1..127;
#                                          a good import writes a scene file that loads and renders
#   vdb_cli_test.sh memory VOX SAMPLES     importing a 10^7-voxel level set peaks (RSS, /usr/bin/time)
#                                          below 2x the world it builds (exit 77 = no /usr/bin/time)
#   vdb_cli_test.sh vdb_render VOX SAMPLES `vox export --for blender` makes a file OpenVDB's own
#                                          vdb_render renders, upright along +z (exit 77 = no vdb_render)
set -u
mode="$1"; vox="$2"; samples="$3"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

if [ "$mode" = vdb_print ]; then
    if ! command -v vdb_print >/dev/null; then
        echo "SKIP: vdb_print not found (Debian package libopenvdb-tools; tools/setup.sh installs it)"
        exit 77
    fi
    "$vox" export sandbox -o "$tmp/sandbox.vdb" >/dev/null || { echo "FAIL: export"; exit 1; }
    json=$("$vox" info sandbox --json)
    solid=$(sed -E 's/.*"solid_voxels": ([0-9]+).*/\1/' <<<"$json")
    emissive=$(sed -E 's/.*"emissive_voxels": ([0-9]+).*/\1/' <<<"$json")
    listing=$(vdb_print -l "$tmp/sandbox.vdb") || { echo "FAIL: vdb_print could not read our file"; exit 1; }
    # One block per grid: "Name: X", "Type: Tree_T_5_4_3", "Number of active voxels: 1,234".
    check_grid() {  # check_grid NAME TYPE COUNT
        local block
        block=$(awk -v n="Name: $1" '$0 == n {on = 1} on && /^$/ && seen {exit} on {print; seen = 1}' <<<"$listing")
        local type count
        type=$(grep -oE "Type: [A-Za-z0-9_]+" <<<"$block" | head -1 | cut -d' ' -f2)
        count=$(grep -E "Number of active voxels" <<<"$block" | grep -oE "[0-9,]+$" | tr -d ,)
        if [ "$type" != "$2" ] || [ "$count" != "$3" ]; then
            fail "grid $1: vdb_print says type '$type', $count active voxels; want $2, $3"
        else
            echo "ok: vdb_print: $1 is $type with $count active voxels"
        fi
    }
    check_grid material Tree_int32_5_4_3 "$solid"
    check_grid albedo Tree_vec3s_5_4_3 "$solid"
    check_grid emission Tree_vec3s_5_4_3 "$emissive"
    meta=$(vdb_print -m "$tmp/sandbox.vdb")
    grep -q "vox:material.00001.name: grass" <<<"$meta" && grep -q "vox:format: voxengine.world" <<<"$meta" \
        && echo "ok: vdb_print shows the palette metadata" || fail "palette metadata missing from vdb_print -m"
    [ $failures -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
    exit 0
fi

if [ "$mode" = vdb_render ]; then
    if ! command -v vdb_render >/dev/null; then
        echo "SKIP: vdb_render not found (Debian package libopenvdb-tools; tools/setup.sh installs it)"
        exit 77
    fi
    # A wide, thin base with a narrow tower on it, along the engine's +y.
    cat > "$tmp/tower.toml" <<'TOML'
[world]
name = "tower"
size = [32, 32, 32]
[[material]]
name = "stone"
albedo = [0.5, 0.5, 0.5]
[[generator]]
type = "box"
min = [0, 0, 0]
max = [32, 4, 32]
material = "stone"
[[generator]]
type = "box"
min = [12, 4, 12]
max = [20, 32, 20]
material = "stone"
TOML
    out=$("$vox" export "$tmp/tower.toml" -o "$tmp/tower.vdb" --for blender 2>&1) || { echo "FAIL: export --for blender: $out"; exit 1; }
    grep -q "grids    density, material" <<<"$out" && echo "ok: export --for blender writes density first" || fail "grids: $out"
    # From above a front corner, +z up on screen: a 64x64 binary PPM (P6).
    # (Run inside $tmp: vdb_render 10 cuts the output path at its first '.', and mktemp's has one.)
    (cd "$tmp" && vdb_render tower.vdb tower.ppm -res 64x64 -translate 60,-60,40 -lookat 16,-16,16 -up 0,0,1 \
        >/dev/null 2>&1) || { echo "FAIL: vdb_render could not render our export"; exit 1; }
    # Pixels that are not black, and how many of them lie in the image's top and bottom thirds.
    header=$(head -c 64 "$tmp/tower.ppm" | awk 'NR <= 3 {n += length($0) + 1} END {print n}')
    counts=$(od -An -v -tu1 -j "$header" "$tmp/tower.ppm" | tr -s ' ' '\n' | grep -v '^$' \
        | awk '{ p = int((NR - 1) / 3); lit[p] = lit[p] || ($1 > 8) }
               END { for (p in lit) if (lit[p]) { n++; if (int(p / 64) < 21) top++; if (int(p / 64) >= 43) bottom++ }
                     print n + 0, top + 0, bottom + 0 }')
    read -r lit top bottom <<<"$counts"
    echo "vdb_render: $lit of 4096 pixels lit ($top in the top third, $bottom in the bottom third)"
    [ "$lit" -gt 200 ] && echo "ok: the render is not empty" || fail "vdb_render's image is (nearly) empty"
    # Upright: the wide base fills the bottom, the narrow tower alone reaches the top.
    [ "$bottom" -gt $((2 * top)) ] && [ "$top" -gt 0 ] && echo "ok: upright along +z" \
        || fail "not upright along +z: $top lit pixels at the top, $bottom at the bottom"
    [ $failures -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
    exit 0
fi

if [ "$mode" = memory ]; then
    [ -x /usr/bin/time ] || { echo "SKIP: /usr/bin/time not found (Debian package time; tools/setup.sh installs it)"; exit 77; }
    "$samples" sphere "$tmp/sphere.vdb" 364 >/dev/null || { echo "FAIL: make_vdb_samples"; exit 1; }
    out=$(/usr/bin/time -f "peak_rss_kib %M" "$vox" import "$tmp/sphere.vdb" --dry-run 2>&1) || { echo "FAIL: import: $out"; exit 1; }
    solid=$(grep -oE "imported +[0-9]+ solid" <<<"$out" | grep -oE "[0-9]+")
    world=$(grep -oE "in memory \([0-9]+ bytes" <<<"$out" | grep -oE "[0-9]+")
    peak=$(grep -oE "peak_rss_kib [0-9]+" <<<"$out" | grep -oE "[0-9]+$")
    echo "world $world bytes, $solid solid voxels; peak RSS $peak KiB = $(awk -v p="$peak" -v w="$world" 'BEGIN{printf "%.3f", p * 1024 / w}') x the world"
    [ -n "$world" ] && [ -n "$peak" ] && [ "$solid" -gt 200000000 ] || { echo "FAIL: could not read the figures from:"; echo "$out"; exit 1; }
    [ $((peak * 1024)) -lt $((2 * world)) ] || { echo "FAIL: peak RSS is not below 2x the world"; exit 1; }
    echo "ok: below 2x"
    exit 0
fi

expect_error() {  # expect_error PATTERN FILE -- command...
    local pattern="$1" file="$2"; shift 3
    local err rc lines
    err=$("$@" 2>&1 >/dev/null); rc=$?
    lines=$(printf '%s\n' "$err" | grep -c .)
    if [ "$rc" -eq 0 ] || [ "$rc" -ge 128 ]; then fail "'$*' exited $rc (want 1..127): $err"; return; fi
    if [ "$lines" -ne 1 ] || ! grep -qF -- "$file" <<<"$err" || ! grep -qE -- "$pattern" <<<"$err"; then
        fail "'$*' printed:"; printf '%s\n' "$err"; echo "  (want one line naming $file and matching: $pattern)"; return
    fi
    echo "ok: $err"
}

"$samples" fog-box "$tmp/fog.vdb"
"$samples" wrong-types "$tmp/wrong.vdb"
"$samples" rotated "$tmp/rotated.vdb"
"$samples" giant-tile "$tmp/giant.vdb"
"$samples" sphere "$tmp/sphere.vdb" 100
size=$(stat -c %s "$tmp/sphere.vdb")
head -c $((size / 2)) "$tmp/sphere.vdb" > "$tmp/truncated.vdb"
{ head -c 16 "$tmp/sphere.vdb"; head -c 3000 /dev/urandom; } > "$tmp/noise.vdb"
: > "$tmp/empty.vdb"
printf 'not a vdb at all\n' > "$tmp/text.vdb"

for cmd in import info; do
    out=(); [ $cmd = import ] && out=(-o "$tmp/out.toml")
    expect_error "truncated or corrupt" "$tmp/truncated.vdb" -- "$vox" $cmd "$tmp/truncated.vdb" "${out[@]}"
    expect_error "corrupt|truncated|not a VDB|memory" "$tmp/noise.vdb" -- "$vox" $cmd "$tmp/noise.vdb" "${out[@]}"
    expect_error "empty file" "$tmp/empty.vdb" -- "$vox" $cmd "$tmp/empty.vdb" "${out[@]}"
    expect_error "not a VDB file" "$tmp/text.vdb" -- "$vox" $cmd "$tmp/text.vdb" "${out[@]}"
done
expect_error "nothing to import.*flow \(vec3i, unusable type\)" "$tmp/wrong.vdb" -- "$vox" import "$tmp/wrong.vdb" -o "$tmp/out.toml"
expect_error "grid 'flow' has type vec3i, which cannot be imported" "$tmp/wrong.vdb" -- "$vox" import "$tmp/wrong.vdb" --grid flow -o "$tmp/out.toml"
expect_error "rotated or sheared" "$tmp/rotated.vdb" -- "$vox" import "$tmp/rotated.vdb" -o "$tmp/out.toml"
expect_error "over the engine's limit" "$tmp/giant.vdb" -- "$vox" import "$tmp/giant.vdb" -o "$tmp/out.toml"
expect_error "would need about [0-9.]+ MiB.*over the memory budget of 4.0 MiB" "$tmp/sphere.vdb" -- "$vox" import "$tmp/sphere.vdb" --memory-budget 4 -o "$tmp/out.toml"
expect_error "no such file" "$tmp/missing.vdb" -- "$vox" import "$tmp/missing.vdb" -o "$tmp/out.toml"
expect_error "no voxel of grid 'density' reaches the fog threshold 2: the largest density in it is 1 " "$tmp/fog.vdb" -- \
    "$vox" import "$tmp/fog.vdb" --fog-threshold 2 -o "$tmp/out.toml"
[ -e "$tmp/out.toml" ] && fail "a failed import wrote $tmp/out.toml"
for size in 0 -1 nan; do
    err=$("$vox" import "$tmp/fog.vdb" --voxel-size "$size" --dry-run 2>&1 >/dev/null); rc=$?
    [ "$rc" -ge 1 ] && [ "$rc" -lt 128 ] && [ "$(grep -c . <<<"$err")" -eq 1 ] && grep -qE -- "--voxel-size: must be (positive|a finite number)" <<<"$err" \
        && echo "ok: --voxel-size $size: $err" || fail "--voxel-size $size exited $rc: $err"
done
# A size inside the option's range but too small to resample to is refused as itself, not as the
# 0 a float would have made of it.
err=$("$vox" import "$tmp/fog.vdb" --voxel-size 1e-300 --dry-run 2>&1 >/dev/null); rc=$?
[ "$rc" -ge 1 ] && [ "$rc" -lt 128 ] && [ "$(grep -c . <<<"$err")" -eq 1 ] && grep -q "1e-300" <<<"$err" && ! grep -q "got 0" <<<"$err" \
    && echo "ok: --voxel-size 1e-300: $err" || fail "--voxel-size 1e-300 exited $rc: $err"

# Grid instances (OpenVDB writes no tree for them) and grids that share a name.
"$samples" instances "$tmp/inst.vdb"
info=$("$vox" info "$tmp/inst.vdb" 2>&1) && grep -q "'density_copy': float" <<<"$info" && ! grep -q corrupt <<<"$info" \
    && echo "ok: info reads a file with a grid instance" || fail "info inst.vdb: $info"
out=$("$vox" import "$tmp/inst.vdb" --grid density_copy --dry-run 2>&1) && grep -qE "imported +900 solid" <<<"$out" \
    && echo "ok: the instance imports its parent's 900 voxels" || fail "import of the instance: $out"
"$samples" duplicate-names "$tmp/dup.vdb"
info=$("$vox" info "$tmp/dup.vdb" 2>&1) && grep -q "'density\[1\]': float" <<<"$info" \
    && echo "ok: info names the second grid density[1]" || fail "info dup.vdb: $info"
out=$("$vox" import "$tmp/dup.vdb" --grid 'density[1]' --dry-run 2>&1) && grep -qE "imported +27 solid" <<<"$out" \
    && echo "ok: --grid 'density[1]' picks the second grid" || fail "import --grid density[1]: $out"

# A scene file's vdb generator notes what it cuts off, as `vox import` does.
cat > "$tmp/crop.toml" <<TOML
[world]
size = [16, 16, 16]
[[generator]]
type = "vdb"
source = "fog.vdb"
offset = [10, 0, 0]
TOML
err=$("$vox" info "$tmp/crop.toml" 2>&1 >/dev/null)
grep -q "crop.toml: vdb generator, fog.vdb: part of the grid lands outside the world and is cut off" <<<"$err" \
    && echo "ok: the vdb generator prints the crop note: $err" || fail "no crop note from the scene file's generator: $err"

# A good import: a scene file plus its payload, which loads, describes and renders.
# The payload gets a new versioned name (scene/world_pair.h), so importing fog.vdb as fog.toml
# leaves the input alone.
cp "$tmp/fog.vdb" "$tmp/fog.vdb.orig"
if "$vox" import "$tmp/fog.vdb" -o "$tmp/fog.toml" >/dev/null 2>&1 && cmp -s "$tmp/fog.vdb" "$tmp/fog.vdb.orig" && [ -s "$tmp/fog.1.vdb" ]; then
    echo "ok: import fog.vdb -o fog.toml keeps its input and writes fog.1.vdb"
else
    fail "import fog.vdb -o fog.toml"
fi
if out=$("$vox" import "$tmp/fog.vdb" -o "$tmp/world.toml" 2>&1) && [ -s "$tmp/world.toml" ] && [ -s "$tmp/world.1.vdb" ]; then
    echo "ok: import wrote world.toml and world.1.vdb"
else
    fail "good import failed: $out"
fi
info=$("$vox" info "$tmp/world.toml" 2>&1) && grep -qE "voxels +1632 solid" <<<"$info" && echo "ok: the imported world has its 1632 voxels" || fail "info on the import: $info"
info=$("$vox" info "$tmp/sphere.vdb" 2>&1) && grep -q "import would" <<<"$info" && grep -q "level set" <<<"$info" \
    && echo "ok: info on a foreign file says what an import would do" || fail "info sphere.vdb: $info"
"$vox" render "$tmp/world.toml" --size 64x40 -o "$tmp/world.png" >/dev/null 2>&1 && [ -s "$tmp/world.png" ] \
    && echo "ok: the imported world renders" || fail "render of the imported world"
"$vox" export "$tmp/world.toml" -o "$tmp/again.vdb" >/dev/null 2>&1 && echo "ok: re-export" || fail "re-export"

[ $failures -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
