# Sourced first by the script tests: each runs in a scratch directory that
# is removed when it exits, and counts its failed checks in $failures, which
# it passes to exit.
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }
