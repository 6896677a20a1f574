#!/bin/bash
# Bad input: every tests/bad_input/*.prm must make softopt exit non-zero with
# a message containing the text after "# expect: " on its first line, and
# must leave the results already in the output directory untouched.
# A run that fails along the load path keeps a valid load_path.csv up to the
# last converged step.
# Usage: bad_input.sh SOFTOPT_EXECUTABLE BAD_INPUT_FOLDER
softopt=$1
folder=$2
source "${BASH_SOURCE%/*}/script_test.sh"

for prm in "$folder"/*.prm; do
  name=$(basename "$prm" .prm)
  expect=$(head -n 1 "$prm" | sed 's/^# expect: //')
  rm -rf output && mkdir output && echo "good results" > output/load_path.csv
  message=$("$softopt" "$prm" 2>&1)
  code=$?
  if [ $code -eq 0 ]; then
    fail "$name: exit code 0"
  elif ! grep -qF -- "$expect" <<< "$message"; then
    fail "$name: the message does not contain \"$expect\":"
    echo "$message"
  elif [ "$(cat output/load_path.csv)" != "good results" ]; then
    fail "$name: overwrote earlier results"
  else
    echo "ok   $name (exit code $code)"
  fi
done

# A refused initial design writes no design.stl.
if [ -e results-first-design/design.stl ]; then
  fail "first_design_refused: design.stl was written for a design never accepted"
else
  echo "ok   first_design_refused writes no design.stl"
fi

# The diverging run: load_path.csv holds its header and the converged rows.
csv=results-divergence/load_path.csv
if [ ! -f $csv ] || ! head -n 1 $csv | grep -q '^step,load_factor' ||
   [ "$(tail -n 1 $csv | cut -d, -f1)" = "step" ]; then
  fail "divergence: $csv is missing or holds no converged row"
else
  echo "ok   divergence keeps $(($(wc -l < $csv) - 1)) converged rows in load_path.csv"
fi
exit $failures
