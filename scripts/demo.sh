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
screenshot_loop() {
  while sleep 5; do
    import -window root "$root/build/demo_screenshot.png.tmp.png" 2>/dev/null &&
      mv "$root/build/demo_screenshot.png.tmp.png" "$root/build/demo_screenshot.png"
  done
}
export -f screenshot_loop
export root
exec xvfb-run -a -s "-screen 0 1280x1024x24" bash -c \
  'screenshot_loop & exec roslaunch dressed_human demo.launch rviz_args:=--disable-anti-aliasing "$@"' demo "$@"
