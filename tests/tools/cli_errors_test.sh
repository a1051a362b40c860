#!/usr/bin/env bash
# Bad input to `vox` gives one line on stderr that names the file (and line), a non-zero exit,
# and no crash; a good render writes a PNG.
source "$(dirname "$0")/test_setup.sh"

expect_error() {  # expect_error PATTERN -- command...
    local pattern="$1"; shift 2
    local err rc
    # Progress lines of long work ("generating lamps 4096/1000000 …", "writing store regions …")
    # are not errors.
    err=$("$@" 2>&1 >/dev/null); rc=$?
    err=$(printf '%s\n' "$err" | grep -vE '^(generating|writing|reading) .* [0-9]+/[0-9]+ ')
    local lines
    lines=$(printf '%s\n' "$err" | grep -c .)
    if [ "$rc" -eq 0 ] || [ "$rc" -ge 128 ]; then
        echo "FAIL: '$*' exited $rc (want 1..127)"; failures=$((failures + 1)); return
    fi
    if [ "$lines" -ne 1 ] || ! printf "%s" "$err" | grep -qE -- "$pattern"; then
        echo "FAIL: '$*' printed:"; printf '%s\n' "$err"; echo "  (want one line matching: $pattern)"
        failures=$((failures + 1)); return
    fi
    echo "ok: $err"
}

printf '[world]\nsize = [16, 16, 16]\n[[material]]\nname = "a"\n[[generator]]\ntype = "terain"\n' > "$tmp/typo.toml"
printf '[world]\nsize = [16, 16\n' > "$tmp/syntax.toml"
printf '[world]\nsize = [100000, 100000, 100000]\n' > "$tmp/huge.toml"
head -c 3000 /dev/urandom > "$tmp/random.toml"
echo "a file, not a folder" > "$tmp/afile"

expect_error "typo.toml:6: unknown generator 'terain'" -- "$vox" render "$tmp/typo.toml" -o "$tmp/a.png"
expect_error "syntax.toml:2:" -- "$vox" info "$tmp/syntax.toml"
expect_error "huge.toml:2: 'size' x is too large \\(max 32768\\), not 100000" -- "$vox" info "$tmp/huge.toml"
expect_error "random.toml" -- "$vox" info "$tmp/random.toml"
expect_error "nosuchworld: no such world" -- "$vox" render nosuchworld
expect_error "--size: expected WIDTHxHEIGHT" -- "$vox" render --size 12by4
expect_error "--size: width must be positive, not 0" -- "$vox" render --size 0x10
expect_error "must end in .png or .exr" -- "$vox" render -o "$tmp/out.jpg"
expect_error "no camera named 'nope'" -- "$vox" render --camera nope -o "$tmp/a.png"
expect_error "--pos: expected x,y,z" -- "$vox" render --pos 1,2 --target 3,4,5 -o "$tmp/a.png"
expect_error "unknown|not expected|Extraction" -- "$vox" render --bogus
expect_error "afile/a.png: cannot write: '.*afile' is not a folder" -- "$vox" render --size 8x8 -o "$tmp/afile/a.png"
expect_error "afile/w.vdb: cannot write: '.*afile' is not a folder" -- "$vox" export cornell -o "$tmp/afile/w.vdb"
# MagicaVoxel files: by extension; a binary file of another name is not read as a scene file.
printf 'VOX \226\0\0\0MAIN' > "$tmp/cut.vox"
cp "$tmp/cut.vox" "$tmp/model.dat"
expect_error "cut.vox: offset 12: MAIN content size needs 4 bytes" -- "$vox" import "$tmp/cut.vox" -o "$tmp/w.toml"
expect_error "cut.vox: offset 12:" -- "$vox" info "$tmp/cut.vox"
expect_error "cut.vox: offset 12:" -- "$vox" render "$tmp/cut.vox" -o "$tmp/a.png"
expect_error "model.dat: not a scene file \(binary data; a TOML scene file, a .vdb or a .vox file was expected" -- "$vox" info "$tmp/model.dat"
expect_error "afile/w.vox: cannot write: '.*afile' is not a folder" -- "$vox" export cornell -o "$tmp/afile/w.vox"
expect_error "the file must end in .vdb or .vox" -- "$vox" export cornell -o "$tmp/w.obj"
# A world over the device's texel-view limit (lowered here: lavapipe's 2^27 takes gigabytes).
expect_error "^vox: world 'cornell' too large for the GPU's texel buffer: [0-9]+ texels, limit 50000 " -- \
    env VOX_MAX_TEXELS=50000 "$vox" render cornell --size 8x8 -o "$tmp/a.png"

out=$("$vox" render --size 64x40 -o "$tmp/ok.png" 2>&1); rc=$?
if [ $rc -ne 0 ] || ! grep -q "wrote    $tmp/ok.png" <<<"$out" || [ "$(head -c 4 "$tmp/ok.png" | tail -c 3)" != "PNG" ]; then
    echo "FAIL: a good render did not write a PNG:"; echo "$out"; failures=$((failures + 1))
else
    echo "ok: good render wrote a PNG"
fi

# Outputs go into folders that are made as needed; a path through a file is one clear line.
if "$vox" export cornell -o "$tmp/made/here/ok.vdb" >/dev/null && [ -s "$tmp/made/here/ok.vdb" ]; then
    echo "ok: export made its folder"
else
    echo "FAIL: export -o into a new folder"; failures=$((failures + 1))
fi
expect_error "afile/w.toml: cannot write: '.*afile' is not a folder" -- "$vox" import "$tmp/made/here/ok.vdb" -o "$tmp/afile/w.toml"

# A world over the memory budget is refused with one line: while generating, and before the
# renderer allocates its GPU copy; vox info prints the planned peak.
printf '[world]\nsize = [4096, 64, 4096]\n[[material]]\nname = "a"\n[[generator]]\ntype = "terrain"\ntop = "a"\nsoil = "a"\nrock = "a"\nbase_height = 20\namplitude = 16\n' > "$tmp/wide.toml"
expect_error "wide.toml:5: generator 'terrain' needs more memory than the budget of 64 MiB" -- "$vox" info "$tmp/wide.toml" --memory-budget 64
expect_error "world 'wide' needs [0-9]+ MiB to show .* over the memory budget of 500 MiB" -- "$vox" render "$tmp/wide.toml" --size 64x64 -o "$tmp/b.png" --memory-budget 500
# When the address-space limit sets the budget, the advice is to raise that limit, not --memory-budget.
expect_error "wide.toml:5: generator 'terrain' needs more memory than the budget of 293 MiB .*raise ulimit -v" -- \
    bash -c 'ulimit -v 400000 && exec "$0" info "$1"' "$vox" "$tmp/wide.toml"
if "$vox" info cornell | grep -qE "^peak +[0-9]+ MiB to show at 1280x720: world"; then
    echo "ok: vox info prints the planned peak"
else
    echo "FAIL: vox info prints no planned peak"; failures=$((failures + 1))
fi
# A world through .vox and back: export, describe, import as a scene file + payload.
if "$vox" export cornell -o "$tmp/made/c.vox" >/dev/null && "$vox" info "$tmp/made/c.vox" | grep -q "MagicaVoxel .vox" &&
    "$vox" import "$tmp/made/c.vox" -o "$tmp/made/c.toml" >/dev/null && "$vox" info "$tmp/made/c.toml" >/dev/null; then
    echo "ok: cornell through .vox export, info and import"
else
    echo "FAIL: cornell through .vox"; failures=$((failures + 1))
fi

[ $failures -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
