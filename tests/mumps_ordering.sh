#!/bin/bash
# "MUMPS ordering = METIS" on a MUMPS built without METIS (Debian's: it falls
# back to another ordering silently) must say so; on one built with METIS it
# must not.
# Whether this MUMPS has METIS is read off its library, independently of
# softopt: a MUMPS built with METIS calls METIS_NodeND.
# Usage: mumps_ordering.sh SOFTOPT_EXECUTABLE SOURCE_DIR
softopt=$1
source=$2
source "${BASH_SOURCE%/*}/script_test.sh"

library=$(ls /usr/lib/x86_64-linux-gnu/libmumps_common*.so* /lib/x86_64-linux-gnu/libmumps_common*.so* 2>/dev/null | head -n 1)
if [ -z "$library" ]; then
  echo "FAIL: no libmumps_common found to tell whether MUMPS has METIS"; exit 1
fi
if nm -D "$library" | grep -q ' U METIS_NodeND'; then has_metis=yes; else has_metis=no; fi

cat > case.prm <<PRM
set Output directory = results
set Print timings = false
subsection Output
  set VTU output = none
end
subsection Geometry
  set Mesh file = $source/meshes/sphere_octant.geo
  set Mesh size = 0.5
  set Dirichlet boundaries = 1: x; 2: y; 3: z
  set Pressure boundary ids = 4
  set Design boundary ids = 5
end
subsection Linear solver
  set MUMPS ordering = METIS
end
PRM
"$softopt" analyze case.prm > log 2>&1 || { echo "FAIL: the run failed"; cat log; exit 1; }
if grep -q 'cannot use METIS and uses' log; then warned=yes; else warned=no; fi
if [ $has_metis = $warned ]; then
  echo "FAIL: MUMPS has METIS: $has_metis ($library), the run warned: $warned"; cat log; exit 1
fi
echo "ok   MUMPS has METIS: $has_metis, and the run warned: $warned"
