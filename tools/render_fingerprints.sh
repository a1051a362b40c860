#!/usr/bin/env bash
# Prints one line per render of a fixed set: the world, the technique and the MD5 of the linear EXR.
# Every technique is in the set: each direct method, the indirect terms (cache, path, VCT), the
# sky terms (DVF and its reference), ReGIR sampling, light tiles, temporal accumulation and the
# display's reconstruction (two rows resolve a half-size render to the image's size).
# A refactor that must not change images runs this before and after and diffs the two lists:
#   tools/render_fingerprints.sh build/release/tools/vox/vox > before.txt
# The EXR is the shown image: with vox render's default display (denoised) each row also holds
# the denoiser and the resolve, so a change to either moves the rows too (by float rounding on a
# single frame, by more where the history takes part). Flags after the binary go to every render;
# `--display raw` fingerprints the lit image alone:
#   tools/render_fingerprints.sh build/release/tools/vox/vox --display raw > before-raw.txt
set -euo pipefail
vox=${1:?usage: render_fingerprints.sh PATH/TO/vox [FLAGS FOR EVERY RENDER...]}
shift
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
worlds=(cornell letters apartments mountain dragon_city factory thin_wall sandbox)
methods=(
  "restir:--method restir --frames 3"
  "restir-unbiased:--method restir-unbiased --frames 3"
  "restir-point:--method restir --mode point --frames 2"
  "ris:--method ris"
  "uniform:--method uniform --shadow-rays 2"
  "preview:--method preview"
  "reference:--method reference --spp 2 --bounces 1"
  "cache:--method restir --indirect cache --frames 3"
  "bruteforce:--method bruteforce"
  "regir:--method restir --sampling regir --frames 3"
  "ris-regir:--method ris --sampling regir"
  "light-tiles:--method restir --light-tiles on --frames 3"
  "cache-tiles:--method ris --indirect cache --light-tiles on --frames 2"
  "path:--method restir --indirect path --frames 2"
  "vct:--method restir --indirect vct --frames 3"
  "vct-bounce:--method ris --indirect vct --vct-bounce on --vct-leak-mitigation off --frames 2"
  "sky-dvf:--method restir --sky dvf --frames 3"
  "sky-reference:--method uniform --sky reference --frames 2"
  "accumulate:--method uniform --accumulate on --frames 3"
  "half-scale:--method restir --render-scale 0.5 --frames 4"
  "half-scale-cache:--method restir --indirect cache --render-scale 0.5 --frames 4"
)
for world in "${worlds[@]}"; do
  for entry in "${methods[@]}"; do
    name=${entry%%:*}
    read -r -a flags <<< "${entry#*:}"
    "$vox" render "$world" --size 48x32 "${flags[@]}" "$@" -o "$out/$world-$name.png" --exr "$out/$world-$name.exr" > /dev/null 2>&1 \
      || { echo "$world $name FAILED"; continue; }
    echo "$world $name $(md5sum < "$out/$world-$name.exr" | cut -d' ' -f1)"
  done
done
