#!/usr/bin/env bash
# simeco next to a peer: the npm package `lindenmayer` derives the same D0L (ABOP 1.24d) and context-sensitive
# (ABOP 1.31a) grammars in node, and simeco derives them with its CPU reference and its GPU backend, in the same
# run. Prints the median time of each and the modules per second. See README.md here.
# Usage: tools/peer/compare.sh [SIMECO]   (default: build/src/app/simeco)
# Environment: REPEAT (runs per tool, default 3), STEPS_D0L (default 12), STEPS_CS (default 30).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
simeco=${1:-$root/build/src/app/simeco}
repeat=${REPEAT:-3}
steps_d0l=${STEPS_D0L:-12}
steps_cs=${STEPS_CS:-30}

[ -x "$simeco" ] || { echo "compare.sh: no simeco at $simeco (build it, or pass its path)" >&2; exit 2; }
command -v node >/dev/null || { echo "compare.sh: needs node and npm (Debian: nodejs npm)" >&2; exit 2; }
if [ ! -d "$here/node_modules/lindenmayer" ]; then
  echo "compare.sh: installing lindenmayer into $here/node_modules" >&2
  npm ci --prefix "$here" --no-audit --no-fund >&2
fi

# The median of `repeat` runs of a command that prints {"modules": M, "seconds": S, ...}: prints "M S".
median_run() {
  local outputs=()
  for _ in $(seq "$repeat"); do
    outputs+=("$("$@" | tr -d '\n')") || return 1
  done
  printf '%s\n' "${outputs[@]}" | node -e '
    const runs = require("fs").readFileSync(0, "utf8").trim().split("\n").map(JSON.parse);
    runs.sort((a, b) => a.seconds - b.seconds);
    const m = runs[Math.floor(runs.length / 2)];
    console.log(m.modules, m.seconds);'
}

row() { # grammar steps tool "modules seconds" reference-rate
  node -e '
    const [grammar, steps, tool, modules, seconds, reference] = process.argv.slice(1);
    const rate = Number(modules) / Number(seconds);
    const ratio = reference ? (rate / Number(reference)).toFixed(2) + "x" : "";
    const fmt = r => r >= 1e6 ? (r / 1e6).toFixed(2) + " M" : (r / 1e3).toFixed(1) + " k";
    console.log([grammar.padEnd(11), steps.padStart(5), tool.padEnd(22), modules.padStart(9),
                 Number(seconds).toFixed(4).padStart(9), fmt(rate).padStart(10), ratio.padStart(8)].join("  "));
    ' "$@"
}

printf '%-11s  %5s  %-22s  %9s  %9s  %10s  %8s\n' grammar steps tool modules seconds modules/s "vs peer"
for entry in "abop-1.24d fig1.24d.l $steps_d0l" "abop-1.31a fig1.31a.l $steps_cs"; do
  read -r name file steps <<<"$entry"
  peer=$(median_run node "$here/derive.js" "$name" "$steps")
  peer_rate=$(node -e 'const [m, s] = process.argv.slice(1).map(Number); console.log(m / s)' $peer)
  row "$name" "$steps" "lindenmayer (node)" $peer ""
  for backend in cpu gpu; do
    if result=$(median_run "$simeco" derive "$root/grammars/abop/$file" -n "$steps" --format json --backend "$backend" 2>/dev/null); then
      row "$name" "$steps" "simeco $backend" $result "$peer_rate"
    else
      printf '%-11s  %5s  %-22s  %s\n' "$name" "$steps" "simeco $backend" "failed (run it by hand to see why)"
    fi
  done
done
echo "repeat: $repeat runs per tool, median; simeco's seconds are its own timer (GPU: without kernel compilation)."
echo "lindenmayer's right context runs past the end of a branch, cpfg's (and simeco's) stops there, so their"
echo "context-sensitive strings differ from step 5 on; each tool's rate is over its own string."
