#!/usr/bin/env bash
# Nothing of the user's is lost to a write of vox (issue 41, items 1, 8 and 11):
# - a VDB sequence (smoke.0001.vdb ...) beside `vox import smoke.0001.vdb -o smoke.toml` survives
#   it, and a second import removes only the first import's own payload;
# - an output is never one of the command's inputs nor another of its outputs, by any name
#   (`-o in.vdb`, `./x/../in.vdb`, a symlink), and an import never replaces a scene file that
#   vox did not write; each refusal is one line, before anything is written;
# - file names up to 255 bytes are written (the temporary and the payload names fit).
source "$(dirname "$0")/test_setup.sh"

# expect_refusal PATTERN -- command...: non-zero exit, exactly one line on stderr matching PATTERN.
expect_refusal() {
    local pattern="$1"; shift 2
    local err rc
    err=$("$@" 2>&1 >/dev/null); rc=$?
    if [ "$rc" -eq 0 ] || [ "$(printf '%s\n' "$err" | grep -c .)" -ne 1 ] || ! printf '%s' "$err" | grep -qE -- "$pattern"; then
        fail "'$*' exited $rc and printed: $err (want one line matching: $pattern)"; return 1
    fi
    echo "ok: $err"
}
# snapshot DIR: every file's name and checksum.
snapshot() { (cd "$1" && find . -type f -print0 | sort -z | xargs -0 md5sum); }

cat > "$tmp/tiny.toml" <<'TOML'
[world]
name = "tiny"
size = [16, 16, 16]
[[material]]
name = "white"
albedo = [0.75, 0.75, 0.75]
[[generator]]
type = "box"
min = [0, 0, 0]
max = [16, 4, 16]
material = "white"
TOML

# 1. A VDB sequence beside an import of its first frame.
mkdir -p "$tmp/seq"
for i in 1 2 3; do
    "$vox" export "$tmp/tiny.toml" -o "$tmp/seq/smoke.000$i.vdb" >/dev/null 2>&1 || fail "export frame $i"
done
sequence=$(cd "$tmp/seq" && md5sum smoke.000*.vdb)
"$vox" import "$tmp/seq/smoke.0001.vdb" -o "$tmp/seq/smoke.toml" >"$tmp/log" 2>&1 || { fail "import"; cat "$tmp/log"; }
"$vox" import "$tmp/seq/smoke.0001.vdb" -o "$tmp/seq/smoke.toml" >"$tmp/log" 2>&1 || { fail "second import"; cat "$tmp/log"; }
if [ "$(cd "$tmp/seq" && md5sum smoke.000*.vdb)" = "$sequence" ]; then
    echo "ok: smoke.0001..0003.vdb survive two imports of frame 1 beside them"
else
    fail "the VDB sequence changed: $(ls "$tmp/seq" | tr '\n' ' ')"
fi
[ "$(ls "$tmp/seq" | tr '\n' ' ')" = "smoke.0001.vdb smoke.0002.vdb smoke.0003.vdb smoke.5.vdb smoke.toml " ] &&
    echo "ok: the second import removed the first's payload (smoke.4.vdb) and nothing else" ||
    fail "files after two imports: $(ls "$tmp/seq" | tr '\n' ' ')"
"$vox" info "$tmp/seq/smoke.toml" >/dev/null 2>&1 || fail "the imported world does not load"

# 2. Outputs onto inputs or onto each other: refused, nothing changed.
mkdir -p "$tmp/io/sub"
"$vox" export "$tmp/tiny.toml" -o "$tmp/io/in.vdb" >/dev/null 2>&1 || fail "export in.vdb"
ln -s in.vdb "$tmp/io/link.vdb"
cp "$tmp/tiny.toml" "$tmp/io/hand.toml"
before=$(snapshot "$tmp/io")
expect_refusal "-o .*in.vdb is the input .*in.vdb" -- "$vox" import "$tmp/io/in.vdb" -o "$tmp/io/in.vdb"
expect_refusal "-o .*in.vdb is the input" -- "$vox" import "$tmp/io/in.vdb" -o "$tmp/io/sub/../in.vdb"
expect_refusal "-o .*link.vdb is the input" -- "$vox" import "$tmp/io/in.vdb" -o "$tmp/io/link.vdb"
expect_refusal "hand.toml: .*not written by vox" -- "$vox" import "$tmp/io/in.vdb" -o "$tmp/io/hand.toml"
expect_refusal "-o .*in.vdb is the world" -- "$vox" export "$tmp/io/in.vdb" -o "$tmp/io/./in.vdb"
expect_refusal "-o .*b.png and --exr .*b.png are the same file" -- "$vox" render "$tmp/tiny.toml" -o "$tmp/io/b.png" --exr "$tmp/io/b.png"
expect_refusal "-o .*b.exr and --exr .*b.exr are the same file" -- "$vox" render "$tmp/tiny.toml" -o "$tmp/io/b.exr" --exr "$tmp/io/sub/../b.exr"
expect_refusal "--timings .*hand.toml is the world" -- "$vox" render "$tmp/io/hand.toml" -o "$tmp/io/c.png" --timings "$tmp/io/hand.toml"
expect_refusal "--edit-log .*hand.toml is the world" -- "$vox" play "$tmp/io/hand.toml" --edit-log "$tmp/io/hand.toml"
expect_refusal "--save .*s.toml and --frame-log .*s.toml are the same file" -- "$vox" play "$tmp/io/hand.toml" --save "$tmp/io/s.toml" --frame-log "$tmp/io/./s.toml"
[ "$(snapshot "$tmp/io")" = "$before" ] && echo "ok: nothing in the folder changed" || fail "the folder changed: $(ls -A "$tmp/io")"
# An import may replace its own earlier import.
"$vox" import "$tmp/io/in.vdb" -o "$tmp/io/w.toml" >/dev/null 2>&1 && "$vox" import "$tmp/io/in.vdb" -o "$tmp/io/w.toml" >/dev/null 2>&1 &&
    echo "ok: an import replaces an earlier import" || fail "an import did not replace an earlier import"

# 3. Names of 255 bytes: an export, and an import's scene file with its payload.
long=$(printf 'l%.0s' $(seq 251))
"$vox" export "$tmp/tiny.toml" -o "$tmp/io/$long.vdb" >"$tmp/log" 2>&1 && [ -f "$tmp/io/$long.vdb" ] &&
    echo "ok: export to a 255-byte name" || { fail "export to a 255-byte name:"; cat "$tmp/log"; }
longer=$(printf 'm%.0s' $(seq 250))
"$vox" import "$tmp/io/in.vdb" -o "$tmp/io/$longer.toml" >"$tmp/log" 2>&1 && "$vox" info "$tmp/io/$longer.toml" >/dev/null 2>&1 &&
    echo "ok: import to a 255-byte scene file name" || { fail "import to a 255-byte name:"; cat "$tmp/log"; }

[ $failures -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "all user-file checks passed"
