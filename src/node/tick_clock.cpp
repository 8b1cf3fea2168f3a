#include "tick_clock.h"

#include <ros/console.h>
#include <ros/rate.h>
#include <ros/init.h>

namespace dressed_human {

void runAtRate(double rate_hz, const std::function<void()>& tick) {
  // Under simulated time, sleeping from time zero never returns: wait for the first /clock.
  if (!ros::Time::waitForValid()) return;
  ros::Rate rate(rate_hz);
  while (ros::ok()) {
    tick();
    ros::spinOnce();
    rate.sleep();
  }
}

TickClock::Tick TickClock::advance(const ros::Time& now, double& dt) {
  dt = 0.0;
  if (now.isZero()) return Tick::kNoTime;
  if (started_ && now < last_) {
    ROS_INFO("%s: time jumped back from %.3f to %.3f s (bag loop?): %s", node_name_.c_str(), last_.toSec(), now.toSec(),
             what_restarts_.c_str());
    started_ = false;
  }
  const bool first = !started_;
  dt = first ? 0.0 : (now - last_).toSec();
  started_ = true;
  last_ = now;
  return first ? Tick::kFirst : Tick::kNext;
}

}  // namespace dressed_human
