#!/usr/bin/env bash
# Turns frames into a time-lapse: an MP4 (H.264) or an animated GIF, chosen by the output's extension. The frames
# are a `simeco run --frames N` folder's (RUN_DIR/frame-00001.png, ...) or a `simeco render --frames N -o OUT.png`
# animation's (OUT-00001.png, ...: give OUT, the output without its extension).
# Usage: tools/make_video.sh RUN_DIR|OUT OUT.mp4|OUT.gif [FRAMES_PER_SECOND]
# Needs ffmpeg (Debian package ffmpeg, installed here with apt-get when missing).
set -euo pipefail
if [ $# -lt 2 ] || [ $# -gt 3 ]; then
  echo "usage: $0 RUN_DIR|OUT OUT.mp4|OUT.gif [FRAMES_PER_SECOND]" >&2
  exit 2
fi
source=$1
out=$2
fps=${3:-12}
if [ -d "$source" ]; then
  frames=$(find "$source" -maxdepth 1 -name 'frame-*.png' | sort)
else
  frames=$(find "$(dirname "$source")" -maxdepth 1 -name "$(basename "$source")-[0-9]*.png" | sort)
fi
[ -n "$frames" ] || {
  echo "$0: no frames: neither $source/frame-*.png (simeco run --frames N)" \
    "nor $source-00001.png ... (simeco render --frames N)" >&2
  exit 2
}
case "$out" in
  *.mp4 | *.gif) ;;
  *) echo "$0: $out: the video is written as .mp4 or .gif" >&2; exit 2 ;;
esac

source "$(dirname "$0")/require_command.sh"
require_command ffmpeg ffmpeg

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# The frames numbered from 1 without gaps, whatever N the run wrote them every.
k=0
for f in $frames; do
  k=$((k + 1))
  ln -s "$(realpath "$f")" "$(printf '%s/%06d.png' "$work" "$k")"
done
# Written under a temporary name next to the output, then renamed: no partial video is left behind.
temporary="$(dirname "$out")/.$(basename "$out").partial.${out##*.}"
trap 'rm -rf "$work" "$temporary"' EXIT
if [[ "$out" == *.gif ]]; then
  ffmpeg -loglevel error -y -framerate "$fps" -i "$work/%06d.png" \
    -vf "split[a][b];[a]palettegen[p];[b][p]paletteuse" "$temporary"
else
  # H.264 needs even sizes; yuv420p plays everywhere.
  ffmpeg -loglevel error -y -framerate "$fps" -i "$work/%06d.png" -vf "scale=trunc(iw/2)*2:trunc(ih/2)*2" \
    -c:v libx264 -pix_fmt yuv420p "$temporary"
fi
mv "$temporary" "$out"
echo "$out: $k frames at $fps frames/s"
