#!/usr/bin/env bash
# `simeco bench --quick` end to end: exit code, the JSON report's fields and that every figure is positive.
# Never compares timings with thresholds (benchmarks are tools, not tests). Usage: bench_smoke_test.sh SIMECO
set -u
simeco=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export SIMECO_KERNEL_CACHE="$work/kernels" # generated kernels stay out of the user's cache

. "$(dirname "$0")/report_checks.sh"
run_report "simeco bench --quick" "$work/bench.json" "GPU modules/s" \
  "$simeco" bench --quick --repeat 2 --warm-up 1 --json "$work/bench.json"

PYTHONPATH="$(dirname "$0")" python3 - "$work/bench.json" <<'PY'
import json, sys

from report_checks import check, finish, positive

report = json.load(open(sys.argv[1]))

for key in ("tool", "settings", "device", "copy_bandwidth", "scaled_down", "notes", "entries"):
    check(key in report, f"missing top-level field {key}")
check(report.get("settings", {}).get("quick") is True, "settings.quick is not true")
check(report.get("settings", {}).get("repeat") == 2, "settings.repeat is not 2")

copy = report.get("copy_bandwidth")
check(isinstance(copy, dict), "no copy bandwidth measured (is there a Vulkan device?)")
if isinstance(copy, dict):
    for key in ("buffer_bytes", "median_ms", "bytes_per_second"):
        positive(copy, key, "copy_bandwidth")
    check(len(copy.get("run_ms", [])) == 2, "copy_bandwidth.run_ms does not hold 2 runs")
    check(copy.get("kernel") in ("storage buffer", "texel buffer"), "copy_bandwidth.kernel names no copy kernel")
    check(copy.get("bytes_per_second", 0) >= copy.get("other_kernel_bytes_per_second", -1),
          "copy_bandwidth is not the faster kernel's")

entries = report.get("entries", [])
names = sorted({e.get("name") for e in entries})
check(names == ["abop-1.24d", "abop-1.27", "abop-1.31a", "abop-2.6", "lantana"], f"suite grammars: {names}")
check(len(entries) == 10, f"{len(entries)} entries, expected 10 (5 grammars x 1 and 10 plants)")
gpu_ok = 0
for e in entries:
    where = f"{e.get('name')} x{e.get('plants')}"
    for key in ("file", "kind", "plants", "steps", "stride", "expected_modules", "string_traffic_bytes",
                "target_reached", "cpu", "gpu"):
        check(key in e, f"{where}: missing field {key}")
    cpu = e.get("cpu", {})
    check(cpu.get("status") == "ok", f"{where}: cpu status {cpu.get('status')!r} ({cpu.get('reason', '')})")
    if cpu.get("status") == "ok":
        for key in ("modules", "median_seconds", "modules_per_second", "bytes_moved", "bytes_per_second"):
            positive(cpu, key, where + " cpu")
        check(len(cpu.get("run_seconds", [])) == 2, f"{where}: cpu run_seconds does not hold 2 runs")
    gpu = e.get("gpu", {})
    check(gpu.get("status") in ("ok", "unsupported"), f"{where}: gpu status {gpu.get('status')!r} ({gpu.get('reason', '')})")
    if gpu.get("status") == "unsupported":
        check(bool(gpu.get("reason")), f"{where}: gpu unsupported without a reason")
    if gpu.get("status") == "ok":
        gpu_ok += 1
        for key in ("modules", "median_seconds", "modules_per_second", "bytes_moved", "bytes_per_second",
                    "copy_bandwidth_fraction", "waits"):
            positive(gpu, key, where + " gpu")
        check(gpu.get("modules") == cpu.get("modules"), f"{where}: gpu modules {gpu.get('modules')} != cpu {cpu.get('modules')}")
        check(len(gpu.get("pass_ms", [])) in (0, e.get("steps")), f"{where}: pass_ms has neither 0 nor one time per step")
        check("gpu_speedup_vs_cpu" in e, f"{where}: no gpu_speedup_vs_cpu")
check(gpu_ok > 0, "no entry ran on the GPU")

finish(f"bench smoke test: {len(entries)} entries, {gpu_ok} on the GPU")
PY
