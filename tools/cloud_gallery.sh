#!/usr/bin/env bash
# Renders every part of the cloud library (grammars/clouds/*.l) to OUT_DIR/NAME.png, one composition in each
# style and palette, and head C1-B growing (OUT_DIR/growth.gif, through tools/make_video.sh and ffmpeg),
# for the gallery in docs/CLOUDS.md.
# Usage: tools/cloud_gallery.sh [SIMECO] [OUT_DIR]   (defaults: build/src/app/simeco, docs/images/clouds)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
simeco=${1:-$root/build/src/app/simeco}
out=${2:-$root/docs/images/clouds}
clouds=$root/grammars/clouds
mkdir -p "$out"
for grammar in "$clouds"/*.l; do
  name=$(basename "$grammar" .l)
  "$simeco" render "$grammar" --size 400x300 -o "$out/$name.png"
done
# One composition, four looks: the library's own (outline, white on sky), toon bands in pastel on paper, lit in
# white, and a paper cut in gold on red.
piece=$clouds/sym-09-m-type.l
"$simeco" render "$piece" --size 400x300 --style toon --colormap "$clouds/palettes/pastel.map" \
  -o "$out/look-toon-pastel.png"
"$simeco" render "$piece" --size 400x300 --style lit -o "$out/look-lit-white.png"
"$simeco" render "$piece" --size 400x300 --style paper-cut --colormap "$clouds/palettes/gold-on-red.map" \
  -o "$out/look-paper-cut-gold-on-red.png"
# Head C1-B growing over its 25 steps, its tubes lengthening between them.
frames=$(mktemp -d)
trap 'rm -rf "$frames"' EXIT
"$simeco" render "$clouds/head-c1b.l" --size 400x300 --frames 50 -o "$frames/clouds.png"
"$root/tools/make_video.sh" "$frames/clouds" "$out/growth.gif" 12
