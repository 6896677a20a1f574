#!/bin/bash
# OpenBLAS's kernels (source/base/blas_kernels.cc). OPENBLAS_VERBOSE=2 makes
# OpenBLAS print "Core: NAME" each time it is loaded:
#   1. where OpenBLAS took the CPU for a Prescott although it has AVX-512
#      (or AVX2), softopt starts once more with SkylakeX's (Haswell's)
#      kernels; elsewhere it starts once, with OpenBLAS's choice;
#   2. the same for each rank under mpirun;
#   3. OPENBLAS_CORETYPE set by the user is kept: one start, those kernels.
# Usage: blas_kernels.sh SOFTOPT_EXECUTABLE
softopt=$1
source "${BASH_SOURCE%/*}/script_test.sh"

has() { grep -q -w "$1" /proc/cpuinfo; }
better=""
if has avx512f && has avx512cd && has avx512bw && has avx512dq && has avx512vl; then
  better=SkylakeX
elif has avx2 && has fma; then
  better=Haswell
fi

cores() { grep -o 'Core: [A-Za-z0-9]*' | cut -d' ' -f2 | tr '\n' ' ' | sed 's/ $//'; }
expect() { # NAME CORES_SEEN CORES_EXPECTED
  if [ "$2" = "$3" ]; then
    echo "$1: $2 (expected $3)"
  else
    fail "$1: OpenBLAS loaded with \"$2\", expected \"$3\""
  fi
}

seen=$(OPENBLAS_VERBOSE=2 "$softopt" print-parameters 2>&1 | cores)
if [ -z "$seen" ]; then
  echo "the BLAS is not OpenBLAS: nothing to check"
  exit 0
fi
# What OpenBLAS chose on its own is the first start's core.
chosen=${seen%% *}
if [ "$chosen" = Prescott ] && [ -n "$better" ]; then
  wanted="Prescott $better"
else
  wanted="$chosen"
fi
expect "one rank" "$seen" "$wanted"

# Each kernel set with the number of loads, "Prescottx2 SkylakeXx2".
tally() { tr ' ' '\n' | sort | uniq -c | awk '{print $2 "x" $1}' | tr '\n' ' ' | sed 's/ $//'; }
mpi_flags="--oversubscribe"
[ "$(id -u)" = 0 ] && mpi_flags="$mpi_flags --allow-run-as-root"
seen=$(mpirun $mpi_flags -np 2 -x OPENBLAS_VERBOSE=2 "$softopt" print-parameters 2>&1 | cores | tally)
wanted_mpi=$(echo "$wanted $wanted" | tally)
expect "two ranks" "$seen" "$wanted_mpi"

seen=$(OPENBLAS_CORETYPE=Prescott OPENBLAS_VERBOSE=2 "$softopt" print-parameters 2>&1 | cores)
expect "OPENBLAS_CORETYPE=Prescott kept" "$seen" "Prescott"

echo "failed checks: $failures (= 0)"
exit $failures
