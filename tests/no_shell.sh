#!/bin/bash
# A parameter file is data: no entry of it may reach a shell. Each probe
# plants a command that would create a file if a shell read the entry, runs
# softopt, and fails if the file exists afterwards.
#   1. Output directory o'$(touch X)'x, read by the plotting call at the end
#      of "optimize" (one design iteration on the coarse sphere octant);
#   2. a Mesh file named inj"$(touch X)".geo, read by the gmsh call; a legal
#      file name, so the run must also succeed;
#   3. Mesh parameters r$(touch X): 10, refused before gmsh runs because the
#      .geo declares no such number.
# Usage: no_shell.sh SOFTOPT_EXECUTABLE SOURCE_DIR
softopt=$1
source=$2
source "${BASH_SOURCE%/*}/script_test.sh"

# The sphere octant's geometry beside the parameter files.
cp "$source/meshes/sphere_octant.geo" sphere.geo
source "$source/tests/sphere_case.sh"
common() { # $1: mesh file, $2: output directory, $3: mesh parameters
  sphere_case "$1" "$2" "$3" 100 1 0
}

check() { # $1: probe name, $2: planted file, $3: exit code, $4: expected ("ok" or "refused")
  if [ -e "$2" ]; then
    fail "$1: the planted command ran (it created $2)"
  elif [ "$4" = ok ] && [ "$3" -ne 0 ]; then
    fail "$1: exit code $3 (expected 0)"; cat log
  elif [ "$4" = refused ] && [ "$3" -eq 0 ]; then
    fail "$1: exit code 0 (expected a refusal)"
  else
    echo "ok   $1: nothing ran (exit code $3)"
  fi
}

# 1. The output directory through the plotting call.
common sphere.geo "o'\$(touch planted_1)'x" "" > output.prm
"$softopt" optimize output.prm > log 2>&1
code=$?
check "Output directory" planted_1 $code ok
if [ $code -eq 0 ] && ! grep -q "Wrote history.png" log; then
  fail "Output directory: the plots were not made"
fi

# 2. The mesh file's name through the gmsh call.
cp sphere.geo 'inj"$(touch planted_2)".geo'
common 'inj"$(touch planted_2)".geo' results-2 "" > mesh.prm
"$softopt" analyze mesh.prm > log 2>&1
check "Mesh file" planted_2 $? ok

# 3. A mesh parameter's name: refused, with the names the .geo declares.
common sphere.geo results-3 'r$(touch planted_3): 10' > parameters.prm
"$softopt" analyze parameters.prm > log 2>&1
code=$?
check "Mesh parameters" planted_3 $code refused
if [ $code -ne 0 ] && ! grep -q 'is not declared by DefineConstant' log; then
  fail "Mesh parameters: the message does not name the undeclared number:"
  cat log
fi
exit $failures
