#pragma once
// What both publishers' ticks share: a loop at a fixed rate that waits for simulated time, and
// the ROS time between ticks, which starts over when time jumps back (a bag loop, /clock reset).

#include <functional>
#include <string>

#include <ros/time.h>

namespace dressed_human {

// Calls `tick`, then the node's callbacks, at `rate_hz` (ros::Rate: simulated time aware) until
// ROS shuts down. In the calling thread: a ros::Timer would hand every tick from the timer thread
// to the spinner thread, and those context switches cost more than the tick itself.
void runAtRate(double rate_hz, const std::function<void()>& tick);

class TickClock {
 public:
  // `what_restarts`: what a jump back starts again, for the log ("restarting the motion").
  TickClock(std::string node_name, std::string what_restarts)
      : node_name_(std::move(node_name)), what_restarts_(std::move(what_restarts)) {}

  enum class Tick { kNoTime, kFirst, kNext };
  // kNoTime while simulated time has not started; kFirst at the first tick and after time
  // jumped back (logged); kNext otherwise, with `dt` the ROS seconds since the last tick.
  Tick advance(const ros::Time& now, double& dt);

 private:
  std::string node_name_;
  std::string what_restarts_;
  ros::Time last_;
  bool started_ = false;
};

}  // namespace dressed_human
