#!/usr/bin/env bash
# README.md's `vox` reference lists every sub-command `vox --help` lists: each top-level
# sub-command, and for one that has sub-commands of its own (`bench`) each of those, must start a
# line `vox NAME` (or `vox NAME SUB`) in the README's "Using `vox`" section. Fails naming the
# missing ones.
#   readme_commands_test.sh VOX README.md
set -u
vox="$1"
readme="$2"

# The names under "Subcommands:" in CLI11's help text, one per line.
subcommands() {  # subcommands HELP-TEXT
    awk '/^[A-Za-z ]*[Ss]ubcommands:$/ { on = 1; next } on && /^  +[^ ]/ { print $1; next } on { on = 0 }' <<<"$1"
}

help=$("$vox" --help) || { echo "FAIL: '$vox --help' exited $?"; exit 1; }
top=$(subcommands "$help")
if [ "$(grep -c . <<<"$top")" -lt 5 ]; then
    echo "FAIL: found too few sub-commands in 'vox --help':"; printf '%s\n' "$help"; exit 1
fi

commands=()
for name in $top; do
    nested=$(subcommands "$("$vox" "$name" --help)")
    if [ -z "$nested" ]; then
        commands+=("$name")
    else
        for sub in $nested; do commands+=("$name $sub"); done
    fi
done

# The README's reference: from its "Using `vox`" heading to the next heading.
section=$(awk '/^## Using `vox`/ { on = 1; next } /^## / { on = 0 } on' "$readme")
if [ -z "$section" ]; then echo "FAIL: $readme has no '## Using \`vox\`' section"; exit 1; fi

missing=0
for command in "${commands[@]}"; do
    if grep -qE "^ *vox $command( |$)" <<<"$section"; then
        echo "ok: vox $command"
    else
        echo "FAIL: 'vox $command' is in 'vox --help' but not in $readme's Using \`vox\` section"
        missing=$((missing + 1))
    fi
done
echo "${#commands[@]} sub-commands, $missing missing from the README"
[ "$missing" -eq 0 ]
