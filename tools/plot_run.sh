#!/usr/bin/env bash
# Plots a `simeco run` folder's stats.jsonl: plants, leaf area and light of each species over simulated time, one
# panel each.
# Usage: tools/plot_run.sh RUN_DIR OUT.png
# Needs gnuplot (Debian package gnuplot-nox, installed here with apt-get when missing) and python3.
set -euo pipefail
if [ $# -ne 2 ]; then
  echo "usage: $0 RUN_DIR OUT.png" >&2
  exit 2
fi
stats=$1/stats.jsonl
out=$2
[ -r "$stats" ] || { echo "$0: cannot read $stats" >&2; exit 2; }

source "$(dirname "$0")/require_command.sh"
require_command gnuplot gnuplot-nox

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# One data file per species (time, plants, leaf area, light), and the plot's series.
python3 - "$stats" "$work" <<'PY'
import json, sys
stats, work = sys.argv[1], sys.argv[2]
series = {}
for line in open(stats):
    tick = json.loads(line)
    for name, s in tick.get("species", {}).items():
        series.setdefault(name, []).append((tick["time"], s["plants"], s["leaf_area"], s["light"]))
names = list(series)
for k, name in enumerate(names):
    with open(f"{work}/species{k}.dat", "w") as f:
        for row in series[name]:
            f.write(" ".join(repr(v) for v in row) + "\n")
def plot(column):
    return ", ".join(f"'{work}/species{k}.dat' using 1:{column} with lines lw 2 title {json.dumps(name)}"
                     for k, name in enumerate(names))
with open(f"{work}/plot.gp", "w") as f:
    f.write(f"plot {plot(2)}\n" if names else "plot 0 notitle\n")
    f.write("set autoscale y\nset ylabel 'leaf area'\n")
    f.write(f"plot {plot(3)}\n" if names else "plot 0 notitle\n")
    f.write("set ylabel 'light caught'\n")
    f.write(f"plot {plot(4)}\n" if names else "plot 0 notitle\n")
PY

gnuplot <<GP
set terminal pngcairo size 900,1000 font ",10"
set output "$out"
set multiplot layout 3,1 title "$(basename "$(dirname "$stats")")/stats.jsonl"
set grid
set key top left
set xlabel 'simulated time (s)'
set ylabel 'plants alive'
set yrange [0:*]
load "$work/plot.gp"
unset multiplot
GP
echo "$out"
