#!/usr/bin/env bash
# `simeco bench --render --quick` end to end: exit code, the JSON report's fields, positive figures, and that
# every field's organs match between the turtles' entries. Never compares timings with thresholds.
# Usage: render_bench_smoke_test.sh SIMECO
set -u
simeco=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$simeco" bench --render --quick --repeat 2 --warm-up 1 --size 160x120 --json "$work/render.json" \
  >"$work/table.txt" 2>"$work/err.txt"
code=$?
if [ $code -ne 0 ]; then
  echo "FAILED: simeco bench --render --quick exited $code"
  cat "$work/err.txt"
  exit 1
fi
if grep -q "vulkan validation" "$work/err.txt"; then
  echo "FAILED: validation messages"
  grep "vulkan validation" "$work/err.txt"
  exit 1
fi
grep -q "GPU turtle/s" "$work/table.txt" || { echo "FAILED: no table on stdout"; cat "$work/table.txt"; exit 1; }

python3 - "$work/render.json" <<'PY'
import json, sys

report = json.load(open(sys.argv[1]))
errors = []

def check(condition, message):
    if not condition:
        errors.append(message)

def positive(obj, key, where):
    value = obj.get(key)
    check(isinstance(value, (int, float)) and value > 0, f"{where}: {key} = {value!r}, expected a positive number")

check(report.get("tool") == "simeco bench --render", "tool is not 'simeco bench --render'")
check(report.get("settings", {}).get("width") == 160, "settings.width is not 160")
positive(report.get("copy_bandwidth", {}), "bytes_per_second", "copy_bandwidth")
entries = report.get("entries", [])
check([e.get("plants") for e in entries] == [1, 10], f"plant counts {[e.get('plants') for e in entries]}")
for e in entries:
    where = f"{e.get('plants')} plants"
    check(e.get("status") == "ok", f"{where}: status {e.get('status')}: {e.get('reason')}")
    for key in ("modules", "organs"):
        positive(e, key, where)
    for part in ("gpu_turtle", "cpu_turtle", "frame_shadow_volumes", "frame_no_shadows"):
        timed = e.get(part, {})
        positive(timed, "median_seconds", f"{where} {part}")
        positive(timed, "instances_per_second", f"{where} {part}")
        check(len(timed.get("run_seconds", [])) == 2, f"{where} {part}: run_seconds does not hold 2 runs")
    positive(e.get("gpu_turtle", {}), "bytes_moved", where)
    positive(e.get("gpu_turtle", {}), "copy_bandwidth_fraction", where)
    positive(e, "gpu_turtle_speedup_vs_cpu", where)
for message in errors:
    print("FAILED:", message)
sys.exit(1 if errors else 0)
PY
