#!/bin/bash
# Regenerates every benchmark figure and chart in docs/ and docs/EVALUATION.md (issue 8):
# builds in build/ (Release), runs the core tools and Google Benchmarks, the ROS-side benchmarks
# (node vs robot_state_publisher, display vs RobotModel, relief modes; under Xvfb), then
# scripts/make_evaluation.py, which also writes the README's Speed section from the same run.
# Raw results go to build/evaluation/. About 20 minutes on 2 cores.
#
# Usage: [PEER_MIRROR=<bare clone of spencer_people_tracking>] scripts/evaluate.sh
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$(pwd)
RESULTS=$ROOT/build/evaluation
BIN=$ROOT/build/devel/lib/dressed_human
PY=/usr/bin/python3   # Debian's, with numpy and matplotlib (scripts/install_deps.sh)

step() { echo; echo "==== $(date +%H:%M:%S) $*"; }

step "build (Release)"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DDRESSED_HUMAN_BENCHMARKS=ON >/dev/null
cmake --build build -j2
mkdir -p "$RESULTS"
{
  echo -n "$(lscpu | sed -n 's/^Model name: *//p' | head -1), $(nproc) cores, "
  echo -n "$(free -g | awk '/^Mem:/ {print $2}') GiB, $(. /etc/os-release && echo "$PRETTY_NAME"), "
  echo "commit $(git rev-parse --short HEAD 2>/dev/null || echo unknown), $(date -u +%Y-%m-%d)."
} > "$RESULTS/machine.txt"

step "Fourier order sweep (fit_motion) and chart"
"$BIN/fit_motion" data/motion/cmu_02_01_walk.bvh -o "$RESULTS/walk_fit.yaml" --tolerance-deg 1.5 \
  --tolerance-mm 10 --max-order 6 --name cmu_02_01_walk --sweep-csv docs/fourier_order_sweep_cmu_02_01.csv
$PY scripts/chart_fourier_order.py docs/fourier_order_sweep_cmu_02_01.csv
$PY scripts/chart_body_fit.py "$BIN/fit_motion"
$PY scripts/chart_walk_speed.py "$BIN/walk_speed_table"

step "tessellation accuracy and chart"
$PY scripts/chart_tessellation.py --tool "$BIN/tessellation_accuracy"

step "core benchmarks (Google Benchmark, 5 repetitions, medians)"
for bench in bench_skeleton_update bench_bezier bench_skin bench_relief; do
  "$BIN/$bench" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
    --benchmark_format=json --benchmark_out="$RESULTS/$bench.json" --benchmark_out_format=json >/dev/null
done

step "scene budget"
"$BIN/scene_budget" "$ROOT" > "$RESULTS/scene_budget.csv"

step "relief, garment and stability figures"
$PY scripts/make_relief_figures.py "$BIN"
$PY scripts/make_garment_figures.py "$BIN"
$PY scripts/make_stability_figures.py --tool "$BIN/stability_cases"

step "ROS side: node vs robot_state_publisher, display vs RobotModel, relief modes (Xvfb)"
set +u
source build/devel/setup.bash
set -u
$PY bench/node_cpu.py --markdown docs/node_cpu.md
rm -rf docs/rviz_scaling
# The crowd peer (spencer's walking-man meshes) is measured alongside when PEER_MIRROR names a bare
# git clone of spencer-project/spencer_people_tracking (../shared/peers/spencer/build.sh builds it).
peer=()
if [ -n "${PEER_MIRROR:-}" ]; then
  bash "$ROOT/../shared/peers/spencer/build.sh" "$PEER_MIRROR" "$RESULTS/spencer_ws"
  peer=(--peer-workspace "$RESULTS/spencer_ws")
else
  echo "PEER_MIRROR not set: the crowd peer is not measured"
fi
$PY bench/rviz_scaling.py --counts 1 5 10 20 30 --distances 12 18 30 --markdown docs/rviz_scaling.md \
  --csv "$RESULTS/rviz_scaling.csv" \
  --chart docs/rviz_scaling.png --screenshots docs/rviz_scaling "${peer[@]}"
$PY bench/rviz_memory.py --markdown docs/rviz_memory.md
rm -rf docs/crowd_scaling
$PY bench/crowd_scaling.py --markdown docs/crowd_scaling.md --csv "$RESULTS/crowd_scaling.csv" \
  --chart docs/crowd_scaling.png --screenshots docs/crowd_scaling "${peer[@]}"
$PY bench/track_following.py --tool "$BIN/track_following" --markdown docs/track_following.md \
  --csv docs/track_following.csv --chart docs/track_following.png
$PY bench/relief_modes.py --csv "$RESULTS/relief_modes.csv" --images docs/relief_modes --markdown docs/relief_modes.md
rm -rf docs/relief_switch
$PY bench/relief_switch.py --chart docs/relief_switch.png --images docs/relief_switch --markdown docs/relief_switch.md
$PY bench/relief_flicker.py --markdown docs/relief_flicker.md
$PY bench/skin_distance.py --chart docs/relief/skin_distance.png --closeup docs/relief/skin_closeup.png \
  --markdown docs/skin_distance.md

step "docs/EVALUATION.md and the README's Speed section"
$PY scripts/make_evaluation.py "$RESULTS"
