#!/usr/bin/env bash
# `simeco bench --sim` end to end on two small fields (`--fields`): exit code, the JSON report's fields and positive
# figures, and that the stages add up to no more than the ticks they are part of. Never compares timings with
# thresholds.
# Usage: sim_bench_smoke_test.sh SIMECO
set -u
simeco=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export SIMECO_KERNEL_CACHE="$work/kernels" # generated kernels stay out of the user's cache

. "$(dirname "$0")/report_checks.sh"
run_report "simeco bench --sim --fields 10,40 --msaa 4" "$work/sim.json" "ticks/s" \
  "$simeco" bench --sim --fields 10,40 --repeat 2 --warm-up 1 --size 96x72 --msaa 4 --json "$work/sim.json"

PYTHONPATH="$(dirname "$0")" python3 - "$work/sim.json" <<'PY'
import json, sys

from report_checks import check, finish, positive

report = json.load(open(sys.argv[1]))

check(report.get("tool") == "simeco bench --sim", "tool is not 'simeco bench --sim'")
check(report.get("settings", {}).get("samples") == 4, f"settings.samples {report.get('settings', {}).get('samples')}")
check(report.get("bytes_per_particle") == 64,  # 16 floats (compute/shared/particle_layout.h)
       f"bytes_per_particle {report.get('bytes_per_particle')}")
positive(report.get("copy_bandwidth", {}), "bytes_per_second", "copy_bandwidth")
entries = report.get("entries", [])
check([e.get("plants") for e in entries] == [10, 40], f"plant counts {[e.get('plants') for e in entries]}")
for e in entries:
    where = f"{e.get('plants')} plants"
    check(e.get("status") == "ok", f"{where}: status {e.get('status')}: {e.get('reason')}")
    for key in ("particles", "organs", "simulated_time", "ticks_per_second", "particles_per_second",
                "grow_copy_bandwidth_fraction", "median_tick_seconds"):
        positive(e, key, where)
    check(len(e.get("tick_seconds", [])) == 2, f"{where}: tick_seconds does not hold 2 ticks")
    stages = e.get("stage_median_seconds", {})
    for stage in ("derive", "grow", "interpret", "light", "statistics", "draw"):
        check(stage in stages and stages[stage] >= 0, f"{where}: stage {stage} missing")
    check(sum(stages.values()) <= 1.5 * max(e.get("tick_seconds", [0])), f"{where}: stages outlast the ticks")
    for key in ("frame_median_seconds", "growing_frames_per_second", "real_time_frames_per_second"):
        for shadows in ("shadow_volumes", "no_shadows"):
            positive(e.get(key, {}), shadows, f"{where}: {key}")
    drawn = e.get("drawn_organs", {})
    counts = [n for level in ("near", "far") for n in drawn.get(level, {}).values()]
    check(len(counts) == 10 and 0 < sum(counts) <= e.get("organs", 0),
          f"{where}: drawn_organs {drawn} against {e.get('organs')} organs")
    positive(e, "shadow_volumes", where)
finish(f"sim bench smoke test: {len(entries)} fields")
PY
