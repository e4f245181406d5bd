#!/bin/sh
# The long parameter-file fuzz: hundreds of seeded mutations of the step
# files and scene of tests/fuzz/, each run of step-1, step-3 or step-4
# classified as refused, accepted, crash, hang, garbage or unclear (see
# tests/fuzz_parameters.cc). Exits non-zero if any run is one of the last
# four; their inputs are kept in <work>/failures/.
#
#   tests/fuzz_long.sh <build folder> [cases (500)] [seed (1)] [work folder]
#
# The build folder must hold step-1, step-3, step-4 and fuzz_parameters
# (cmake --build <build> --target step-1 step-3 step-4 fuzz_parameters).
# 500 cases take about 15 minutes on 2 cores.
set -eu
build=${1:?usage: tests/fuzz_long.sh <build folder> [cases] [seed] [work folder]}
cases=${2:-500}
seed=${3:-1}
work=${4:-$build/fuzz-long}
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work"
mkdir -p "$work"
exec "$build/tests/fuzz_parameters" --bin "$build" --base "$here/fuzz" \
  --work "$work" --cases "$cases" --seed "$seed" --timeout 120 --jobs 2 \
  --log "$work/fuzz.log"
