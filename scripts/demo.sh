#!/usr/bin/env bash
# Installs what is missing, builds, and starts the demo: the walking human in rviz.
# With a display ($DISPLAY set) rviz opens a window. Without one, rviz runs on a virtual X server
# (Xvfb) and a screenshot is written to build/demo_screenshot.png every 5 seconds; stop with Ctrl-C.
# Extra arguments go to roslaunch, e.g.  scripts/demo.sh rviz:=false
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"

scripts/install_deps.sh
export PATH="/usr/bin:$PATH"
export ROS_HOSTNAME=${ROS_HOSTNAME:-localhost}
grep -qE '^127\.0\.0\.1[[:space:]].*\blocalhost\b' /etc/hosts 2>/dev/null || echo "127.0.0.1 localhost" >> /etc/hosts
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc 2>/dev/null || echo 2)"
# shellcheck disable=SC1091
set +u  # catkin's setup scripts read unset variables
source build/devel/setup.bash
set -u

if [ -n "${DISPLAY:-}" ]; then
  exec roslaunch dressed_human demo.launch "$@"
fi

echo "demo: no DISPLAY: running rviz under Xvfb; screenshots go to $root/build/demo_screenshot.png"
# xvfb-run is a /bin/sh (dash) script, and dash drops exported bash functions from the
# environment: the screenshot loop is written out inside the command instead. It stops when
# roslaunch (which replaces the inner bash, so has its PID) exits.
exec xvfb-run -a -s "-screen 0 1280x1024x24" bash -c '
  shot=$1; shift
  (while sleep 5 && kill -0 $$ 2>/dev/null; do
     import -window root "$shot.tmp.png" 2>/dev/null && mv "$shot.tmp.png" "$shot"
   done) &
  exec roslaunch dressed_human demo.launch rviz_args:=--disable-anti-aliasing "$@"' \
  demo "$root/build/demo_screenshot.png" "$@"
