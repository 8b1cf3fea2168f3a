#!/bin/sh
# Builds the libFuzzer targets of the file parsers (motion capture BVH and .mot, OpenSim models,
# motion YAML, body YAML, pedestrian trajectories) with clang (outside the CMake build) and runs each for the given number of seconds.
#   fuzz/run_fuzzers.sh [seconds=60] [build-dir=build_fuzz]
# Seeds: data/motion/*.bvh|mot, fuzz/seeds/*.osim (a leg of gait2392), config/motions/*.yaml, config/bodies/*.yaml and fuzz/seeds/
# (*.trajectories: an options byte, then a Jülich or obsmat file);
# inputs are capped at 16 KB (large ones only slow the mutations down; the shipped walk is 13 KB).
# Crashes land in <build-dir>/<target>/crash-*; the script exits non-zero when a target fails.
# Needs clang++ (apt-get install clang).
set -eu
seconds="${1:-60}"
here="$(cd "$(dirname "$0")/.." && pwd)"
build="${2:-$here/build_fuzz}"
mkdir -p "$build/bin"
cxx="${CXX_FUZZ:-clang++}"
flags="-std=c++17 -O1 -g -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined -I$here/include \
  -isystem /usr/include/eigen3 -DDRESSED_HUMAN_SOURCE_DIR=\"$here\""

build_target() {  # name, core sources (below src/core), then libraries
  name=$1; shift
  sources=""; libraries=""
  for item in "$@"; do
    case "$item" in -l*) libraries="$libraries $item" ;; *) sources="$sources $here/src/core/$item" ;; esac
  done
  "$cxx" $flags "$here/fuzz/$name.cpp" $sources -o "$build/bin/$name" $libraries
}
# In two groups side by side: clang and each fuzzer use one core, CI has two.
skeleton="skeleton/body_description.cpp skeleton/skeleton.cpp skeleton/forward_kinematics.cpp skeleton/urdf_body_shape.cpp"
(
  build_target fuzz_bvh_parser motion/bvh_file.cpp io/text_file.cpp
  build_target fuzz_mot_parser motion/opensim_motion_file.cpp io/text_file.cpp
  build_target fuzz_opensim_model motion/opensim_model.cpp io/text_file.cpp -ltinyxml2
) & first=$!
(
  build_target fuzz_motion_yaml motion/motion_file.cpp motion/motion.cpp motion/motion_evaluator.cpp io/text_file.cpp \
    $skeleton -lyaml-cpp -lurdfdom_model -ltinyxml2
  build_target fuzz_body_yaml $skeleton \
    surfaces/skin.cpp surfaces/bezier_patch.cpp surfaces/tessellation.cpp surfaces/tessellation_error.cpp \
    io/text_file.cpp -lyaml-cpp -lurdfdom_model -ltinyxml2
  build_target fuzz_pedestrian_trajectories io/pedestrian_trajectories.cpp model/recorded_crowd.cpp io/text_file.cpp
) & second=$!
built=0
wait $first || built=1
wait $second || built=1
[ "$built" -eq 0 ] || { echo "run_fuzzers.sh: a fuzz target did not build" >&2; exit 1; }

run_target() {  # name, seed files...
  name=$1; shift
  corpus="$build/$name/corpus"
  mkdir -p "$corpus"
  for seed in "$@"; do cp "$seed" "$corpus"/ 2>/dev/null || true; done
  set -- "$name"
  status=0
  (cd "$build/$1" && "$build/bin/$1" -max_total_time="$seconds" -max_len=16384 -timeout=10 -rss_limit_mb=2048 \
      -print_final_stats=1 "$corpus") > "$build/$1.log" 2>&1 || status=$?
  grep -E "stat::number_of_executed_units|Done [0-9]+ runs|ERROR|SUMMARY" "$build/$1.log" | sed "s/^/$1: /" || true
  return $status
}
failed=0
for target in fuzz_bvh_parser fuzz_mot_parser fuzz_opensim_model fuzz_motion_yaml fuzz_body_yaml fuzz_pedestrian_trajectories; do mkdir -p "$build/$target"; done
(
  status=0
  run_target fuzz_bvh_parser "$here"/data/motion/*.bvh "$here"/fuzz/seeds/*.bvh || status=1
  run_target fuzz_mot_parser "$here"/data/motion/*.mot "$here"/fuzz/seeds/*.mot || status=1
  run_target fuzz_opensim_model "$here"/fuzz/seeds/*.osim || status=1
  exit $status
) & first=$!
(
  status=0
  run_target fuzz_motion_yaml "$here"/config/motions/*.yaml || status=1
  run_target fuzz_body_yaml "$here"/config/bodies/*.yaml || status=1
  run_target fuzz_pedestrian_trajectories "$here"/fuzz/seeds/*.trajectories || status=1
  exit $status
) & second=$!
wait $first || failed=1
wait $second || failed=1
if [ -n "$(ls "$build"/fuzz_*/crash-* "$build"/fuzz_*/timeout-* 2>/dev/null)" ]; then failed=1; fi
exit $failed
