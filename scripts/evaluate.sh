#!/bin/bash
# Regenerates every benchmark figure and chart in docs/, docs/EVALUATION.md and the README's Speed
# section from one run (issues 8, 37): builds in build/ (Release), runs the core tools and Google
# Benchmarks, the ROS-side benchmarks (node vs robot_state_publisher, display vs RobotModel, the
# crowd against spencer's meshes, relief modes; under Xvfb), each writing into this run's own
# results folder, build/evaluation/<UTC start>_<commit>/ (docs/ mirrored under its docs/). Then
# scripts/make_evaluation.py checks that the folder is one whole run of one clean commit and only
# then publishes it to docs/ and the README. How long the run took is written with its figures.
#
# Usage: [PEER_MIRROR=<bare clone of spencer_people_tracking>] [RELIEF_BEFORE_DEVEL=<devel space of an
#        earlier build, e.g. a worktree of the commit before issue 40 built with the targets
#        dressed_human_rviz and skeleton_publisher>] [BANDAI_MIRROR=<bare clone of
#        Bandai-Namco-Research-Motiondataset: its walks join the body-fit table>] [LAFAN_MIRROR=<bare
#        clone of karstm/motion-matching: two LAFAN1 walks from its history join it too>] [MIXAMO_MIRROR=<bare
#        clone of jerech33/haze: its Mixamo walk cycle joins it too>] scripts/evaluate.sh
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$(pwd)
BIN=$ROOT/build/devel/lib/dressed_human
PY=/usr/bin/python3   # Debian's, with numpy and matplotlib (scripts/install_deps.sh)

# A run measures one commit: local changes would be measured under a commit that lacks them.
if [ -n "$(git status --porcelain --untracked-files=no)" ]; then
  echo "evaluate.sh: the work tree has uncommitted changes; commit them first (the figures name a commit)" >&2
  exit 1
fi
COMMIT=$(git rev-parse HEAD)
STARTED=$(date +%s)
RESULTS=$ROOT/build/evaluation/$(date -u +%Y%m%dT%H%M%SZ)_${COMMIT:0:7}
OUT=$RESULTS/docs
mkdir -p "$ROOT/build/evaluation"
mkdir "$RESULTS" "$OUT"   # never an existing folder: nothing from another run can be in it
export DRESSED_HUMAN_DOCS=$OUT   # where the chart scripts write what belongs in docs/
{
  echo "command: scripts/evaluate.sh${PEER_MIRROR:+ with PEER_MIRROR=$PEER_MIRROR}${RELIEF_BEFORE_DEVEL:+ RELIEF_BEFORE_DEVEL=$RELIEF_BEFORE_DEVEL}${BANDAI_MIRROR:+ BANDAI_MIRROR=$BANDAI_MIRROR}${LAFAN_MIRROR:+ LAFAN_MIRROR=$LAFAN_MIRROR}${MIXAMO_MIRROR:+ MIXAMO_MIRROR=$MIXAMO_MIRROR}"
  echo "commit: $COMMIT"
  echo "started: $(date -u +%Y-%m-%dT%H:%M:%SZ)"
  echo -n "host: $(hostname), $(lscpu | sed -n 's/^Model name: *//p' | head -1), $(nproc) cores, "
  echo "$(free -g | awk '/^Mem:/ {print $2}') GiB, $(. /etc/os-release && echo "$PRETTY_NAME")"
} > "$RESULTS/run.txt"

step() { echo; echo "==== $(date +%H:%M:%S) $*"; echo "$(date -u +%H:%M:%SZ) $*" >> "$RESULTS/steps.txt"; }

step "build (Release)"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DDRESSED_HUMAN_BENCHMARKS=ON >/dev/null
cmake --build build -j2
if [ "$(git rev-parse HEAD)" != "$COMMIT" ] || [ -n "$(git status --porcelain --untracked-files=no)" ]; then
  echo "evaluate.sh: the work tree changed during the build" >&2
  exit 1
fi

step "Fourier order sweep (fit_motion) and chart"
"$BIN/fit_motion" data/motion/cmu_02_01_walk.bvh -o "$RESULTS/walk_fit.yaml" --tolerance-deg 1.5 \
  --tolerance-mm 10 --max-order 6 --name cmu_02_01_walk --sweep-csv "$OUT/fourier_order_sweep_cmu_02_01.csv"
$PY scripts/chart_fourier_order.py "$OUT/fourier_order_sweep_cmu_02_01.csv" "$OUT/fourier_order_speed_vs_accuracy.png"
$PY scripts/chart_body_fit.py "$BIN/fit_motion"
$PY scripts/chart_walk_speed.py "$BIN/walk_speed_table"

step "tessellation accuracy and chart"
$PY scripts/chart_tessellation.py --tool "$BIN/tessellation_accuracy" --out "$OUT/tessellation_speed_vs_accuracy.png"

step "core benchmarks (Google Benchmark, 5 repetitions, medians)"
for bench in bench_skeleton_update bench_bezier bench_skin bench_relief; do
  "$BIN/$bench" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
    --benchmark_format=json --benchmark_out="$RESULTS/$bench.json" --benchmark_out_format=json >/dev/null
done

step "scene budget"
"$BIN/scene_budget" "$ROOT" > "$RESULTS/scene_budget.csv"

step "relief, garment and stability figures"
$PY scripts/make_relief_figures.py "$BIN"
cp "$BIN/relief_raw/smooth_fold_error.csv" "$RESULTS/"   # the smooth folds' error, for the report's sentence
$PY scripts/make_garment_figures.py "$BIN"
$PY scripts/make_stability_figures.py --tool "$BIN/stability_cases" --out "$OUT/stability"

step "ROS side: node vs robot_state_publisher, display vs RobotModel, crowd vs spencer, relief modes (Xvfb)"
set +u
source build/devel/setup.bash
set -u
$PY bench/node_cpu.py --markdown "$OUT/node_cpu.md"
# The crowd peer (spencer's walking-man meshes) is measured alongside when PEER_MIRROR names a bare
# git clone of spencer-project/spencer_people_tracking (../shared/peers/spencer/build.sh builds it).
peer=()
if [ -n "${PEER_MIRROR:-}" ]; then
  bash "$ROOT/../shared/peers/spencer/build.sh" "$PEER_MIRROR" "$RESULTS/spencer_ws"
  peer=(--peer-workspace "$RESULTS/spencer_ws")
else
  echo "PEER_MIRROR not set: the crowd peer is not measured"
fi
# Three runs per point: which vertex path Automatic picks on this renderer is read off their spread.
$PY bench/rviz_scaling.py --repeats 3 --seconds 10 --counts 1 10 30 --distances 12 30 \
  --markdown "$OUT/rviz_scaling.md" --csv "$RESULTS/rviz_scaling.csv" \
  --chart "$OUT/rviz_scaling.png" --screenshots "$OUT/rviz_scaling"
$PY bench/rviz_memory.py --markdown "$OUT/rviz_memory.md"
$PY bench/crowd_scaling.py --markdown "$OUT/crowd_scaling.md" --csv "$RESULTS/crowd_scaling.csv" \
  --chart "$OUT/crowd_scaling.png" --screenshots "$OUT/crowd_scaling" "${peer[@]}"
$PY bench/track_following.py --tool "$BIN/track_following" --markdown "$OUT/track_following.md" \
  --csv "$OUT/track_following.csv" --chart "$OUT/track_following.png"
$PY bench/relief_modes.py --csv "$RESULTS/relief_modes.csv" --images "$OUT/relief_modes" \
  --markdown "$OUT/relief_modes.md"
$PY bench/relief_switch.py --chart "$OUT/relief_switch.png" --images "$OUT/relief_switch" \
  --markdown "$OUT/relief_switch.md"
$PY bench/relief_flicker.py --markdown "$OUT/relief_flicker.md"
mkdir -p "$OUT/relief"
$PY bench/skin_distance.py --chart "$OUT/relief/skin_distance.png" --closeup "$OUT/relief/skin_closeup.png" \
  --markdown "$OUT/skin_distance.md"
before=()
if [ -n "${RELIEF_BEFORE_DEVEL:-}" ]; then
  before=(--before-devel "$RELIEF_BEFORE_DEVEL")
  echo "relief before: $(git -C "$RELIEF_BEFORE_DEVEL" rev-parse HEAD) ($RELIEF_BEFORE_DEVEL)" >> "$RESULTS/run.txt"
fi
$PY bench/relief_distance.py --figure "$OUT/relief_distance.png" --markdown "$OUT/relief_distance.md" \
  --json "$OUT/relief_distance.json" "${before[@]}"

echo "finished: $(date -u +%Y-%m-%dT%H:%M:%SZ), $(( $(date +%s) - STARTED )) s after it started" >> "$RESULTS/run.txt"

step "docs/EVALUATION.md and the README's Speed section, from this run's folder"
$PY scripts/make_evaluation.py "$RESULTS"
