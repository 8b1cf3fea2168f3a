#!/bin/sh
# Builds the libFuzzer targets of the motion capture parsers with clang (outside the CMake build)
# and runs each for the given number of seconds.
#   fuzz/run_fuzzers.sh [seconds=60] [build-dir=build_fuzz]
# Seeds: data/motion/*.bvh|mot and fuzz/seeds/*.bvh|mot; inputs are capped at 16 KB (large ones only
# slow the mutations down). Crashes land in <build-dir>/<target>/crash-*; the script exits non-zero
# when a target fails. Needs clang++ (apt-get install clang).
set -eu
seconds="${1:-60}"
here="$(cd "$(dirname "$0")/.." && pwd)"
build="${2:-$here/build_fuzz}"
mkdir -p "$build/bin"
cxx="${CXX_FUZZ:-clang++}"
flags="-std=c++17 -O1 -g -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined -I$here/include -isystem /usr/include/eigen3"

build_target() {  # name, parser source
  "$cxx" $flags "$here/fuzz/$1.cpp" "$here/src/core/$2" -o "$build/bin/$1"
}
build_target fuzz_bvh_parser motion/bvh_file.cpp
build_target fuzz_mot_parser motion/opensim_motion_file.cpp

run_target() {  # name, seed glob extension
  corpus="$build/$1/corpus"
  mkdir -p "$corpus"
  cp "$here"/data/motion/*."$2" "$here"/fuzz/seeds/*."$2" "$corpus"/ 2>/dev/null || true
  status=0
  (cd "$build/$1" && "$build/bin/$1" -max_total_time="$seconds" -max_len=16384 -timeout=10 -rss_limit_mb=2048 \
      -print_final_stats=1 "$corpus") > "$build/$1.log" 2>&1 || status=$?
  grep -E "stat::number_of_executed_units|Done [0-9]+ runs|ERROR|SUMMARY" "$build/$1.log" || true
  return $status
}
failed=0
mkdir -p "$build/fuzz_bvh_parser" "$build/fuzz_mot_parser"
run_target fuzz_bvh_parser bvh || failed=1
run_target fuzz_mot_parser mot || failed=1
if [ -n "$(ls "$build"/fuzz_*_parser/crash-* "$build"/fuzz_*_parser/timeout-* 2>/dev/null)" ]; then failed=1; fi
exit $failed
