#include "dressed_human/core/locomotion/route.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace dressed_human {
namespace {

double wrapAngle(double angle) { return std::remainder(angle, 2.0 * M_PI); }

// Below this turn at a waypoint a walker keeps its speed; above it, the sharper, the slower.
constexpr double kGentleTurn = 0.5;  // rad
// Heading error (rad) that the turn rate closes per second before it saturates.
constexpr double kHeadingGain = 4.0;  // 1/s

}  // namespace

void validateRoute(const Route& route, const std::string& what) {
  if (route.waypoints.empty()) throw LocomotionError(what + " has no waypoints");
  for (std::size_t i = 0; i < route.waypoints.size(); ++i) {
    const Eigen::Vector2d& p = route.waypoints[i];
    if (!p.allFinite() || p.cwiseAbs().maxCoeff() > RouteLimits::kMaxCoordinate) {
      std::ostringstream message;
      message << what << ": waypoint " << i << " is [" << p.x() << ", " << p.y() << "]; coordinates must be finite "
              << "metres within +-" << RouteLimits::kMaxCoordinate;
      throw LocomotionError(message.str());
    }
  }
  if (route.closed) {
    std::size_t distinct = 0;
    for (std::size_t i = 0; i < route.waypoints.size(); ++i) {
      const Eigen::Vector2d& next = route.waypoints[(i + 1) % route.waypoints.size()];
      if ((next - route.waypoints[i]).norm() >= RouteLimits::kMinLeg) ++distinct;
    }
    if (distinct < 2) {
      throw LocomotionError(what + " is a closed route with fewer than two distinct places (" +
                            std::to_string(route.waypoints.size()) + " waypoint(s)): give two or more, or let it end");
    }
  }
}

Route defaultLoop(const Eigen::Vector2d& centre, double yaw) {
  const Eigen::Rotation2Dd turn(yaw);
  Route route;
  for (const Eigen::Vector2d& corner : {Eigen::Vector2d(2.0, -1.0), Eigen::Vector2d(2.0, 1.0),
                                        Eigen::Vector2d(-2.0, 1.0), Eigen::Vector2d(-2.0, -1.0)}) {
    route.waypoints.push_back(centre + turn * corner);
  }
  route.closed = true;
  return route;
}

RouteFollower::RouteFollower(RouteFollowerSettings settings) : settings_(settings) {}

void RouteFollower::setRoute(Route route) {
  route_ = std::move(route);
  target_ = 0;
  laps_ = 0;
  arrived_ = false;
}

// The point `lookahead` metres further along the route than `position`'s projection on the leg
// into the target waypoint; on the first leg of an open route, the target itself.
Eigen::Vector2d RouteFollower::carrot(const Eigen::Vector2d& position, double lookahead) const {
  const Eigen::Vector2d& to = waypoint(target_);
  if (!route_.closed && target_ == 0) return to;
  const Eigen::Vector2d& from = waypoint(target_ + count() - 1);
  const Eigen::Vector2d leg = to - from;
  const double length = leg.norm();
  if (length < RouteLimits::kMinLeg) return to;
  const double along = std::clamp((position - from).dot(leg) / length, 0.0, length);
  const double beyond = along + lookahead - length;
  if (beyond <= 0.0) return from + leg * ((along + lookahead) / length);
  if (isLastLeg()) return to;
  const Eigen::Vector2d next = waypoint(target_ + 1) - to;
  const double next_length = next.norm();
  if (next_length < RouteLimits::kMinLeg) return to;
  return to + next * (std::min(beyond, next_length) / next_length);
}

double RouteFollower::cornerSpeed(std::size_t corner) const {
  if (!route_.closed && (corner == 0 || corner + 1 >= count())) return std::numeric_limits<double>::infinity();
  const Eigen::Vector2d in = waypoint(corner) - waypoint(corner + count() - 1);
  const Eigen::Vector2d out = waypoint(corner + 1) - waypoint(corner);
  if (in.norm() < RouteLimits::kMinLeg || out.norm() < RouteLimits::kMinLeg)
    return std::numeric_limits<double>::infinity();
  const double turn = std::abs(wrapAngle(std::atan2(out.y(), out.x()) - std::atan2(in.y(), in.x())));
  if (turn < kGentleTurn) return std::numeric_limits<double>::infinity();
  return settings_.max_turn_rate * settings_.corner_radius * (0.5 * M_PI) / turn;
}

RouteFollower::Steering RouteFollower::steer(const Eigen::Vector2d& position, double heading, double speed) {
  Steering steering;
  if (!hasRoute() || arrived_) return steering;
  const double lookahead = std::max(settings_.min_lookahead, settings_.lookahead_time * speed);
  // Reached: within the lookahead of a corner (the carrot is on the next leg by then), or, at an
  // open route's end, within the arrival distance.
  for (std::size_t guard = 0; guard < count(); ++guard) {
    const double distance = (waypoint(target_) - position).norm();
    if (isLastLeg() || (!route_.closed && count() == 1)) {
      // Arrived: near the end, or past it (the leg's direction points back).
      const Eigen::Vector2d leg = waypoint(target_) - (target_ > 0 ? waypoint(target_ - 1) : position);
      if (distance < settings_.arrival_distance || (target_ > 0 && leg.dot(waypoint(target_) - position) < 0.0)) {
        arrived_ = true;
        return steering;
      }
      break;
    }
    if (distance >= lookahead) break;
    target_ = (target_ + 1) % count();
    if (route_.closed && target_ == 0) ++laps_;
    if (!route_.closed && target_ == 0) target_ = count() - 1;  // never wraps
  }
  const Eigen::Vector2d aim = carrot(position, lookahead) - position;
  const double error = aim.squaredNorm() > 1e-12 ? wrapAngle(std::atan2(aim.y(), aim.x()) - heading) : 0.0;
  steering.turn_rate = std::clamp(kHeadingGain * error, -settings_.max_turn_rate, settings_.max_turn_rate);

  // Slow for what is ahead: the corner at the target (or the end), reached after decelerating.
  const double distance = (waypoint(target_) - position).norm();
  const double end_speed = isLastLeg() ? 0.0 : cornerSpeed(target_);
  steering.speed_limit =
      std::sqrt(end_speed * end_speed + 2.0 * settings_.deceleration * std::max(0.0, distance - lookahead));
  if (isLastLeg()) steering.speed_limit = std::sqrt(2.0 * settings_.deceleration * std::max(0.0, distance));
  // Facing well away from the route (a start, a sharp corner): turn almost on the spot.
  if (std::abs(error) > M_PI / 3.0) {
    steering.speed_limit = std::min(steering.speed_limit, settings_.max_turn_rate * settings_.corner_radius * 0.5);
  }
  return steering;
}

}  // namespace dressed_human
