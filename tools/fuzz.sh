#!/usr/bin/env bash
# Fuzzes the readers of user files (cpfg .l, SimEco .eco, quick .lsys, view .v, .func, .fset, both kinds of .con,
# .s) with libFuzzer, AddressSanitizer and UBSan: builds them with clang into build-fuzz/, seeds each reader with
# the project's grammars and scenes and the shared cpfg corpus, and runs each for a while. Inputs that reach new code
# are kept in build-fuzz/corpus/READER/ for the next run; a crash, sanitizer report, hang (an input over 30 s:
# the sanitizers run about ten times slower than a release build) or runaway memory (> 2 GiB) leaves its input
# in build-fuzz/findings/READER/ and fails the run.
# Usage: tools/fuzz.sh [--seconds N] [READER ...]   (N per reader, default 60; READER default: all of them)
#        tools/fuzz.sh --build-only
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
shared=$(cd .. && pwd)/shared

seconds=60
build_only=0
if [ "${1:-}" = "--build-only" ]; then
  build_only=1
  shift
elif [ "${1:-}" = "--seconds" ]; then
  seconds=$2
  shift 2
fi
readers=("$@")
[ ${#readers[@]} -eq 0 ] &&
  readers=(cpfg eco quick view function function_set contour cylinder_contour surface skeleton skeleton_obj
    three_views)

if ! command -v clang++ >/dev/null; then
  echo "fuzz: clang++ is needed (Debian packages clang and libclang-rt-dev; tools/setup.sh installs them)" >&2
  exit 1
fi
build=build-fuzz
cmake -S . -B "$build" -DSIMECO_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ >/dev/null
cmake --build "$build" -j "$(nproc)" >/dev/null
[ "$build_only" -eq 1 ] && exit 0

# seedFiles READER: the files that seed one reader.
seedFiles() {
  case "$1" in
  cpfg) ls grammars/*/*.l "$shared"/corpus/cpfg-vlab/models/*/*/*.l ;;
  eco) ls scenes/*.eco "$shared"/seed-scripts/*.eco ;;
  quick) ls grammars/*/*.lsys ;;
  view) ls grammars/*/*.v "$shared"/corpus/cpfg-vlab/models/*/*/*.v ;;
  function) ls "$shared"/corpus/cpfg-vlab/models/*/*/*.func ;;
  function_set) ls "$shared"/corpus/cpfg-vlab/models/*/*/*.fset ;;
  contour | cylinder_contour) ls "$shared"/corpus/cpfg-vlab/models/*/*/*.con ;;
  surface) ls grammars/*/*.s "$shared"/corpus/cpfg-vlab/models/*/*/*.s ;;
  skeleton) ls scenes/skeletons/*.json ;;
  skeleton_obj) ls scenes/skeletons/*.obj ;;
  three_views) ls scenes/skeletons/*.svg ;;
  esac 2>/dev/null
}

failed=0
for reader in "${readers[@]}"; do
  target="$build/tests/fuzz/fuzz_$reader"
  [ -x "$target" ] || { echo "fuzz: no target for reader '$reader'" >&2; exit 1; }
  seeds="$build/seeds/$reader" corpus="$build/corpus/$reader" findings="$build/findings/$reader"
  rm -rf "$seeds"
  mkdir -p "$seeds" "$corpus" "$findings"
  count=0
  while read -r file; do
    cp "$file" "$seeds/$count-$(basename "$file")"
    count=$((count + 1))
  done < <(seedFiles "$reader")
  if [ "$count" -eq 0 ]; then
    echo "fuzz: no seeds for reader '$reader' (is ../shared beside the repository?)" >&2
    exit 1
  fi
  scratch=$(mktemp -d)
  log="$build/fuzz-$reader.log"
  set +e
  TMPDIR="$scratch" "$target" "$corpus" "$seeds" -max_total_time="$seconds" -timeout=30 -rss_limit_mb=2048 \
    -max_len=131072 -artifact_prefix="$findings/" -print_final_stats=1 >"$log" 2>&1
  code=$?
  set -e
  rm -rf "$scratch"
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo 0)
  kept=$(ls "$corpus" | wc -l)
  if [ "$code" -ne 0 ]; then
    echo "fuzz $reader: FINDING after $runs executions (exit $code); see $log and $findings/"
    grep -E "ERROR|runtime error|SUMMARY" "$log" | head -5
    failed=1
  else
    echo "fuzz $reader: $runs executions in ${seconds} s from $count seeds, $kept inputs kept, no finding"
  fi
done
exit $failed
