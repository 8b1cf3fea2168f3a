#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test: the core's gtests, the rostests, and the
# core's gtests again under AddressSanitizer + UndefinedBehaviorSanitizer. Exits non-zero if any
# test fails. Usage: scripts/test.sh   (from anywhere; CI runs it through .ci/run)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
jobs=$(nproc 2>/dev/null || echo 2)
# Each step says when it began (UTC): where CI's time goes.
section() { echo "== $* [$(date -u +%H:%M:%S)]"; }

section "installing Debian packages (if missing)"
scripts/install_deps.sh

# Debian's python must come first: a pyenv/conda python3 breaks catkin and rostest.
export PATH="/usr/bin:$PATH"
export ROS_HOSTNAME=localhost ROSCONSOLE_STDOUT_LINE_BUFFERED=1 PYTHONUNBUFFERED=1
# Containers and chroots sometimes lack a resolvable localhost, which the ROS master needs.
grep -qE '^127\.0\.0\.1[[:space:]].*\blocalhost\b' /etc/hosts 2>/dev/null || echo "127.0.0.1 localhost" >> /etc/hosts

section "building (build/)"
# No benchmarks, nor the tools that only draw figures: no test runs them (scripts/evaluate.sh
# builds and runs them).
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DDRESSED_HUMAN_BENCHMARKS=OFF
cmake --build build -j"$jobs"

section "building the core with ASan+UBSan (build_sanitize/)"
cmake -S . -B build_sanitize -DDRESSED_HUMAN_CORE_ONLY=ON -DDRESSED_HUMAN_SANITIZE=ON \
      -DDRESSED_HUMAN_BENCHMARKS=OFF -DCMAKE_BUILD_TYPE=Debug
cmake --build build_sanitize -j"$jobs"

status=0
# A failure list left by an earlier run would be digested again at the end.
rm -f build/Testing/Temporary/LastTestsFailed.log build_sanitize/Testing/Temporary/LastTestsFailed.log
section "core tests under ASan+UBSan"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir build_sanitize --output-on-failure -j"$jobs" || status=1

section "fuzzing the file parsers: BVH, .mot, OpenSim model, motion YAML, body YAML (short run; fuzz/run_fuzzers.sh 600 for the long one)"
fuzz/run_fuzzers.sh "${FUZZ_SECONDS:-20}" "$root/build_fuzz" || status=1

section "core gtests, layout and tool tests (Release)"
# Each ctest run rewrites the failure list: the digest of this run's failures comes right after it.
ctest --test-dir build --output-on-failure -E '^ros\.' -j"$jobs" || { status=1; scripts/failure_digest.py build || true; }
# One at a time: each starts rviz under Xvfb and checks what it draws against TF in real time.
# Last, so that ctest's summary closes the output.
section "rostests"
ctest --test-dir build --output-on-failure -R '^ros\.' || { status=1; rostests_failed=1; }

if [ "$status" -ne 0 ]; then
  scripts/failure_digest.py build_sanitize || true
  [ -z "${rostests_failed:-}" ] || scripts/failure_digest.py build || true
  echo "scripts/test.sh: SOME TESTS FAILED" >&2
fi
section "done"
exit "$status"
