# Sourced by the command-line tests: a scratch folder that goes when the test ends, generated kernels kept out of
# the user's cache, and named checks counted.
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export SIMECO_KERNEL_CACHE="$work/kernels"
passed=0
failed=0

# check NAME STATUS. A name with a command substitution sets $? before STATUS is expanded: such a check
# takes the status into a variable first.
check() {
  if [ "$2" -eq 0 ]; then passed=$((passed + 1)); else failed=$((failed + 1)); echo "FAILED: $1"; fi
}

# The count of checks; fails the test when one failed.
finish_checks() {
  echo "$passed passed, $failed failed"
  [ "$failed" -eq 0 ]
}
