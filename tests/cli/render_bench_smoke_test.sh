#!/usr/bin/env bash
# `simeco bench --render --quick` end to end: exit code, the JSON report's fields, positive figures, and that
# every field's organs match between the turtles' entries. Never compares timings with thresholds.
# Usage: render_bench_smoke_test.sh SIMECO
set -u
simeco=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

. "$(dirname "$0")/report_checks.sh"
run_report "simeco bench --render --quick" "$work/render.json" "GPU turtle/s" \
  "$simeco" bench --render --quick --repeat 2 --warm-up 1 --size 160x120 --json "$work/render.json"

PYTHONPATH="$(dirname "$0")" python3 - "$work/render.json" <<'PY'
import json, sys

from report_checks import check, finish, positive

report = json.load(open(sys.argv[1]))

check(report.get("tool") == "simeco bench --render", "tool is not 'simeco bench --render'")
check(report.get("settings", {}).get("width") == 160, "settings.width is not 160")
# By default the frames' samples are the viewer's: one a pixel on a CPU device.
samples = report.get("settings", {}).get("samples")
check(samples == (1 if report.get("device", {}).get("type") == "CPU" else 4), f"settings.samples {samples}")
positive(report.get("copy_bandwidth", {}), "bytes_per_second", "copy_bandwidth")
entries = report.get("entries", [])
check([e.get("plants") for e in entries] == [1, 10], f"plant counts {[e.get('plants') for e in entries]}")
for e in entries:
    where = f"{e.get('plants')} plants"
    check(e.get("status") == "ok", f"{where}: status {e.get('status')}: {e.get('reason')}")
    for key in ("modules", "organs"):
        positive(e, key, where)
    for part in ("gpu_turtle", "cpu_turtle", "frame_shadow_volumes", "frame_no_shadows", "tick", "ticks_in_flight"):
        timed = e.get(part, {})
        positive(timed, "median_seconds", f"{where} {part}")
        positive(timed, "instances_per_second", f"{where} {part}")
        check(len(timed.get("run_seconds", [])) == 2, f"{where} {part}: run_seconds does not hold 2 runs")
    positive(e.get("gpu_turtle", {}), "bytes_moved", where)
    positive(e.get("gpu_turtle", {}), "copy_bandwidth_fraction", where)
    positive(e, "gpu_turtle_speedup_vs_cpu", where)
finish(f"render bench smoke test: {len(entries)} fields")
PY
