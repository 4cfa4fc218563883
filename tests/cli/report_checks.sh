# What the benchmark smoke tests share: running `simeco bench` checked for a clean exit, no validation messages
# and no leftover temporary report (their report checks share report_checks.py). Source it; needs $work (a
# scratch folder).

# run_report NAME JSON TABLE_MARK ARGS...: runs ARGS writing stdout to $work/table.txt and stderr to
# $work/err.txt; fails the test on a non-zero exit, a validation message, a leftover temporary JSON, or a table
# without TABLE_MARK.
run_report() {
  local name=$1 json=$2 mark=$3
  shift 3
  "$@" >"$work/table.txt" 2>"$work/err.txt"
  local code=$?
  if [ $code -ne 0 ]; then
    echo "FAILED: $name exited $code"
    cat "$work/err.txt"
    exit 1
  fi
  if grep -q "vulkan validation" "$work/err.txt"; then
    echo "FAILED: validation messages"
    grep "vulkan validation" "$work/err.txt"
    exit 1
  fi
  if ls "$json".tmp* >/dev/null 2>&1; then
    echo "FAILED: the temporary JSON file was left behind"
    exit 1
  fi
  grep -q "$mark" "$work/table.txt" || { echo "FAILED: no table on stdout"; cat "$work/table.txt"; exit 1; }
}
