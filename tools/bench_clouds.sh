#!/usr/bin/env bash
# The oriental clouds' growth animation against the thesis's table 12 (L-studio: average frames per second while
# the cloud grows, and the total time): each of the table's grammars from the cloud library animated with
# `simeco render FILE --frames 30` (about the frames of each of the thesis's animations: its total time times its
# frame rate), in the library's own look, REPEAT times; the median of simeco's own timing (from the simulation's
# start to the last frame written; the Vulkan device's start is left out). Writes OUT.json and OUT.md (the table) and
# OUT.png (frames per second, simeco's and the thesis's, log scale).
# Usage: tools/bench_clouds.sh OUT [REPEAT] [SIMECO] [extra simeco render options...]
# Needs gnuplot (Debian package gnuplot-nox, installed here with apt-get when missing) and python3.
set -euo pipefail
if [ $# -lt 1 ]; then
  echo "usage: $0 OUT [REPEAT] [SIMECO] [render options...]" >&2
  exit 2
fi
root=$(cd "$(dirname "$0")/.." && pwd)
out=$1
repeat=${2:-3}
simeco=${3:-$root/build/src/app/simeco}
shift $(($# < 3 ? $# : 3))
frames=30
size=640x480
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

source "$(dirname "$0")/require_command.sh"
require_command gnuplot gnuplot-nox

# Row: the table's group, its column, the library's file, the thesis's frames/s and total seconds.
rows="Cloud|C1|head-c1a|19.67|1.50
Cloud|C2|head-c2|23.25|1.27
Cloud|C3|head-c3|18.00|14.71
C1-A with tail|level 1|c1a-tail-1|21.00|1.55
C1-A with tail|level 2|c1a-tail-2|15.33|2.20
C1-A with tail|level 3|c1a-tail-3|14.00|2.53
SYM (C1-A, no tail)|SYM 2|sym-02-180-degrees|14.85|2.04
SYM (C1-A, no tail)|SYM 4|sym-04-90-degrees|9.67|3.09
SYM (C1-A, no tail)|SYM 8|sym-08-square-pyramid|9.75|3.61
Cloud1 (SYM 3, C1-A, no tail)|once|cloud1-once|13.33|2.55
Cloud1 (SYM 3, C1-A, no tail)|twice|cloud1-twice|4.29|6.76
Cloud1 (SYM 3, C1-A, no tail)|3 times|cloud1-3-times|2.69|14.67
Cloud2 (SYM 3 and SYM 2, C1-A, no tail)|twice|cloud2-twice|6.50|5.57
Cloud2 (SYM 3 and SYM 2, C1-A, no tail)|4 times|cloud2-4-times|1.45|21.91
Cloud2 (SYM 3 and SYM 2, C1-A, no tail)|6 times|cloud2-6-times|0.40|72.54"

echo "$rows" | while IFS='|' read -r group column file fps total; do
  for r in $(seq "$repeat"); do
    line=$("$simeco" render "$root/grammars/clouds/$file.l" --frames "$frames" --size "$size" \
      -o "$work/$file.png" "$@")
    # "...: 1 plants grown for 75.0 s in 30 frames, 228 modules, 640x480, 4.12 s (7.28 frames/s) -> ..."
    seconds=$(echo "$line" | sed -n 's/.*, \([0-9.]*\) s (.*/\1/p')
    modules=$(echo "$line" | sed -n 's/.* frames, \([0-9]*\) modules.*/\1/p')
    echo "$group|$column|$file|$fps|$total|$seconds|$modules"
  done
done >"$work/runs.txt"

device=$("$simeco" devices 2>/dev/null | sed -n 's/^\* *[0-9]*: *//p' | head -1 || true)
python3 - "$work/runs.txt" "$out" "$frames" "$size" "$repeat" "$device" <<'PY'
import json, statistics, sys
runs_file, out, frames, size, repeat, device = sys.argv[1:7]
frames = int(frames)
rows = {}
for line in open(runs_file):
    group, column, file, fps, total, seconds, modules = line.rstrip("\n").split("|")
    r = rows.setdefault(file, {"group": group, "column": column, "file": f"grammars/clouds/{file}.l",
                               "thesis_fps": float(fps), "thesis_seconds": float(total), "seconds": [],
                               "modules": int(modules)})
    r["seconds"].append(float(seconds))
entries = []
for r in rows.values():
    median = statistics.median(r["seconds"])
    r["median_seconds"] = median
    r["fps"] = frames / median
    entries.append(r)
report = {"tool": "tools/bench_clouds.sh", "frames": frames, "size": size, "repeat": int(repeat),
          "device": device, "entries": entries}
json.dump(report, open(out + ".json", "w"), indent=2)
with open(out + ".md", "w") as md:
    md.write(f"| group | part | modules | thesis fps | thesis s | simeco fps | simeco s ({frames} frames) |\n")
    md.write("|---|---|---:|---:|---:|---:|---:|\n")
    for r in entries:
        md.write(f"| {r['group']} | {r['column']} | {r['modules']} | {r['thesis_fps']:.2f} | {r['thesis_seconds']:.2f} | "
                 f"{r['fps']:.2f} | {r['median_seconds']:.2f} |\n")
with open(out + ".dat", "w") as dat:
    for i, r in enumerate(entries):
        group = r["group"].split(" ")[0]
        label = r["column"] if r["column"].startswith(group) else f"{group} {r['column']}"
        dat.write(f"{i} \"{label}\" {r['thesis_fps']} {r['fps']}\n")
print(open(out + ".md").read(), end="")
PY
gnuplot <<GP
set terminal pngcairo size 1100,500 noenhanced
set output "$out.png"
set title "Oriental clouds growing, $frames frames at $size: simeco ($device) against L-studio (thesis table 12)"
set style data histograms
set style histogram clustered gap 1
set style fill solid 0.8
set logscale y
set ylabel "frames per second (median of $repeat)"
set xtics rotate by -40 font ",9"
set key top right
plot "$out.dat" using 3:xtic(2) title "L-studio (thesis)" lc rgb "#999999", "" using 4 title "simeco" lc rgb "#d62728"
GP
rm -f "$out.dat"
