#!/usr/bin/env bash
# Installs every Debian package dressed_human needs to build, run its demo and run its tests.
# Idempotent: packages already present are skipped by apt.
set -euo pipefail

packages=(
  # build
  build-essential cmake pkg-config catkin python3-catkin-pkg python3-empy
  libeigen3-dev libyaml-cpp-dev libboost-dev liburdfdom-dev liburdfdom-tools libtinyxml2-dev
  # ROS 1 (Debian's own packages)
  libroscpp-dev libroslib-dev librosconsole-dev libtf2-ros-dev libtf2-eigen-dev libtf2-msgs-dev
  libtopic-tools-dev  # topic_tools::ShapeShifter: people messages of packages Debian lacks
  libsensor-msgs-dev libnav-msgs-dev libgeometry-msgs-dev libstd-msgs-dev librosbag-dev
  pluginlib-dev librviz-dev rviz qtbase5-dev libgl-dev
  rosout rosbash python3-roslaunch python3-rostopic python3-rosnode python3-rosbag python3-rostest librostest-dev python3-rosgraph
  ros-robot-state-publisher joint-state-publisher tf2-tools python3-tf2-ros
  python3-sensor-msgs python3-nav-msgs python3-tf2-msgs python3-geometry-msgs
  # the crowd message (msg/): generators, and the .msg files it builds on
  ros-message-generation ros-message-runtime python3-genmsg python3-gencpp python3-genpy
  ros-std-msgs ros-geometry-msgs python3-std-msgs libstd-msgs-dev
  # tests and benchmarks
  libgtest-dev googletest libbenchmark-dev clang libclang-rt-14-dev
  # headless rviz and screenshots
  xvfb xauth x11-apps mesa-utils libgl1-mesa-dri imagemagick
  # charts
  python3-numpy python3-matplotlib python3-yaml
)

sudo_cmd=()
if [ "$(id -u)" != 0 ]; then sudo_cmd=(sudo); fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install_deps: all ${#packages[@]} Debian packages already installed"
  exit 0
fi
echo "install_deps: installing ${#missing[@]} Debian packages: ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -q
"${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
