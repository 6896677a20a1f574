#!/bin/bash
# A gmsh that fails says how: stand-ins for gmsh first in PATH make it
#   1. killed by a signal (as the kernel's OOM killer does): the message must
#      say "killed by a signal", since gmsh's log is empty then;
#   2. exit with status 3 and no log: the message must give the status.
# Each run must exit non-zero with the "gmsh failed on <mesh file>" message.
# Usage: gmsh_failures.sh SOFTOPT_EXECUTABLE SOURCE_DIR
softopt=$1
source=$2
source "${BASH_SOURCE%/*}/script_test.sh"

cp "$source/meshes/sphere_octant.geo" sphere.geo
source "$source/tests/sphere_case.sh"
mkdir bin

probe() { # $1: name, $2: stand-in's body, $3: expected text
  printf '#!/bin/sh\n%s\n' "$2" > bin/gmsh && chmod +x bin/gmsh
  sphere_case sphere.geo "results-$1" "" 100 1 0 > case.prm
  PATH="$PWD/bin:$PATH" "$softopt" analyze case.prm > log 2>&1
  code=$?
  if [ $code -eq 0 ]; then
    fail "$1: exit code 0"
  elif ! grep -q "gmsh failed on <.*sphere.geo>" log || ! grep -qF -- "$3" log; then
    fail "$1: the message does not contain \"$3\":"; cat log
  else
    echo "ok   $1: \"$3\" (exit code $code)"
  fi
}

probe killed 'kill -9 $$' "gmsh was killed by a signal"
probe status 'exit 3' "gmsh exited with status 3"
exit $failures
