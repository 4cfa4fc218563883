#!/usr/bin/env bash
# Plots a `simeco bench --json` report: modules per second against string size (modules after the last step),
# one line per backend (joining each grammar's sizes), log-log. A `simeco bench --render --json` report: organ
# instances per second against the number of plants, for the turtle kernels, the CPU turtle and frames with and
# without shadow volumes. A `simeco bench --sim --json` report: seconds per tick against the number of plants,
# the whole tick and each of its stages.
# Usage: tools/plot_bench.sh BENCH.json OUT.png
# Needs gnuplot (Debian package gnuplot-nox, installed here with apt-get when missing) and python3.
set -euo pipefail
if [ $# -ne 2 ]; then
  echo "usage: $0 BENCH.json OUT.png" >&2
  exit 2
fi
report=$1
out=$2
[ -r "$report" ] || { echo "$0: cannot read $report" >&2; exit 2; }

source "$(dirname "$0")/require_command.sh"
require_command gnuplot gnuplot-nox

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The render and growth reports: one data file per series against plants, the plot command and the axis labels.
python3 - "$report" "$work" <<'PY'
import json, sys

report = json.load(open(sys.argv[1]))
work = sys.argv[2]

def finish_series(plots, ylabel):
    """The series of a plot against plants, its y label and a title naming the device and its copy bandwidth."""
    with open(f"{work}/series.gp", "w") as f:
        f.write(", ".join(plots))
    with open(f"{work}/ylabel.txt", "w") as f:
        f.write(ylabel)
    device = report.get("device", {}).get("name") or "no GPU"
    copy = report.get("copy_bandwidth") or {}
    title = f"{report['tool']} on {device}"
    if copy:
        title += f" (copy bandwidth {copy['bytes_per_second'] / 1e9:.2f} GB/s)"
    with open(f"{work}/title.txt", "w") as f:
        f.write(title.replace('"', "'"))
    sys.exit(0)
if report.get("tool") == "simeco bench --render":
    series = [("gpu_turtle", "turtle kernels", "#d62728"), ("cpu_turtle", "CPU turtle (1 thread)", "#1f77b4"),
              ("frame_shadow_volumes", "frame, shadow volumes", "#2ca02c"), ("frame_no_shadows", "frame, no shadows", "#9467bd"),
              ("tick", "tick: turtle and frame, one submission", "#8c564b"),
              ("ticks_in_flight", "ticks, two in flight", "#e377c2")]
    plots = []
    for key, title, color in series:
        rows = [(e["plants"], e[key]["instances_per_second"]) for e in report["entries"]
                if e.get("status") == "ok" and e.get(key, {}).get("instances_per_second", 0) > 0]
        if not rows:
            continue
        with open(f"{work}/{key}.dat", "w") as f:
            for plants, rate in rows:
                f.write(f"{plants} {rate}\n")
        plots.append(f"'{work}/{key}.dat' using 1:2 with linespoints lw 2 pt 7 lc rgb '{color}' title '{title}'")
    finish_series(plots, "organ instances per second (median)")

if report.get("tool") == "simeco bench --sim":
    series = [(None, "tick: all its stages", "#000000"), ("derive", "derive", "#1f77b4"), ("grow", "grow", "#2ca02c"),
              ("interpret", "interpret (turtle)", "#d62728"), ("light", "light grid", "#e6a000"),
              ("statistics", "statistics", "#9467bd"),
              ("draw", "draw a frame", "#8c564b")]
    plots = []
    for key, title, color in series:
        rows = []
        for e in report["entries"]:
            # A field not drawn ticks its growth alone: only its derive and grow stages compare with the others'.
            if e.get("status") != "ok" or ("not_drawn" in e and key not in ("derive", "grow")):
                continue
            seconds = e["median_tick_seconds"] if key is None else e["stage_median_seconds"].get(key, 0)
            if seconds > 0:
                rows.append((e["plants"], seconds))
        if not rows:
            continue
        name = key or "tick"
        with open(f"{work}/{name}.dat", "w") as f:
            for plants, seconds in rows:
                f.write(f"{plants} {seconds}\n")
        plots.append(f"'{work}/{name}.dat' using 1:2 with linespoints lw 2 pt 7 lc rgb '{color}' title '{title}'")
    finish_series(plots, "seconds per tick (median)")

# The derivation report: one data file per backend (string size, modules/s, point shape), a block per grammar
# sorted by size, so that a backend's line joins the sizes of one grammar and breaks between grammars; the
# title names the device; the key lists which point shape stands for which grammar.
grammars = []
for e in report["entries"]:
    if e["name"] not in grammars:
        grammars.append(e["name"])
shapes = [7, 5, 9, 11, 13, 15, 4, 6, 8, 10]
for backend in ("cpu", "gpu"):
    rows = []
    for e in report["entries"]:
        r = e.get(backend, {})
        if r.get("status") == "ok" and r.get("modules", 0) > 0 and r.get("modules_per_second", 0) > 0:
            rows.append((grammars.index(e["name"]), r["modules"], r["modules_per_second"]))
    rows.sort()
    with open(f"{work}/{backend}.dat", "w") as f:
        for k, (grammar, modules, rate) in enumerate(rows):
            if k > 0 and rows[k - 1][0] != grammar:
                f.write("\n")  # gnuplot breaks a line at a blank line
            f.write(f"{modules} {rate} {shapes[grammar % len(shapes)]}\n")
with open(f"{work}/grammars.gp", "w") as f:
    keys = [f"NaN with points pt {shapes[i % len(shapes)]} lc rgb 'black' title '{name}'" for i, name in enumerate(grammars)]
    f.write(", ".join(keys))
device = report.get("device", {}).get("name") or "no GPU"
copy = report.get("copy_bandwidth")
title = f"simeco bench on {device}"
if copy:
    title += f" (copy bandwidth {copy['bytes_per_second'] / 1e9:.2f} GB/s)"
with open(f"{work}/title.txt", "w") as f:
    f.write(title.replace('"', "'"))
PY

if [ -f "$work/series.gp" ]; then
  if [ ! -s "$work/series.gp" ]; then
    echo "$0: $report has no successful runs to plot" >&2
    exit 1
  fi
  gnuplot <<GP
set terminal pngcairo size 1000,650 font ",11"
set output "$out"
set title "$(cat "$work/title.txt")"
set logscale xy
set xlabel "plants in the field"
set ylabel "$(cat "$work/ylabel.txt")"
set format y "10^{%L}"
set grid
set key outside right top
plot $(cat "$work/series.gp")
GP
  echo "plot_bench: wrote $out"
  exit 0
fi

series=()
if [ -s "$work/cpu.dat" ]; then
  series+=("'$work/cpu.dat' using 1:2 with lines lw 2 lc rgb '#1f77b4' title 'CPU reference (1 thread)'")
  series+=("'$work/cpu.dat' using 1:2:3 with points pt variable ps 1.5 lc rgb '#1f77b4' notitle")
fi
if [ -s "$work/gpu.dat" ]; then
  series+=("'$work/gpu.dat' using 1:2 with lines lw 2 lc rgb '#d62728' title 'GPU backend'")
  series+=("'$work/gpu.dat' using 1:2:3 with points pt variable ps 1.5 lc rgb '#d62728' notitle")
fi
if [ ${#series[@]} -eq 0 ]; then
  echo "$0: $report has no successful runs to plot" >&2
  exit 1
fi
plot="$(IFS=,; echo "${series[*]}"), $(cat "$work/grammars.gp")"

gnuplot <<GP
set terminal pngcairo size 1000,650 font ",11"
set output "$out"
set title "$(cat "$work/title.txt")"
set logscale xy
set xlabel "string size (modules of all plants after the last step)"
set ylabel "modules per second (median)"
set format x "10^{%L}"
set format y "10^{%L}"
set grid
set key outside right top
plot $plot
GP
echo "plot_bench: wrote $out"
