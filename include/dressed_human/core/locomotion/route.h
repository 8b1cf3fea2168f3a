#pragma once
// A walking route in the fixed frame's ground plane, and the pure-pursuit follower that steers
// along it: the heading turns at a bounded rate toward a point a lookahead ahead on the route,
// which rounds the corners, and the speed drops before sharp corners and the end of an open route
// as a person's does.

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Geometry>

namespace dressed_human {

struct LocomotionError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Route {
  std::vector<Eigen::Vector2d> waypoints;  // x, y in the fixed frame (REP-103: x forward, y left)
  bool closed = true;                      // false: stop and stand at the last waypoint
};

// Physical ranges of a route: where a map holds places, and what a person can walk.
struct RouteLimits {
  static constexpr double kMaxCoordinate = 1e5;  // m, the DressedHuman display's drawable range
  static constexpr double kMinLeg = 0.05;        // m: closer waypoints are one place
};

// Throws LocomotionError naming `what` (e.g. "parameter ~waypoints") and the first bad waypoint:
// none at all, a non-finite or out-of-range coordinate, a closed route with fewer than two
// distinct places.
void validateRoute(const Route& route, const std::string& what);

// The route a human walks when none is given: a rounded rectangle around `centre` (x, y), its long
// side along `yaw`, small enough to stay in view of the demo's camera.
Route defaultLoop(const Eigen::Vector2d& centre, double yaw);

struct RouteFollowerSettings {
  double max_turn_rate = 2.0;      // rad/s: a walking person turns 90 degrees in under a step
  double lookahead_time = 0.35;    // s of walking ahead on the route the heading aims at...
  double min_lookahead = 0.3;      // m ... but never nearer than this
  double corner_radius = 0.4;      // m: sharp corners are walked at max_turn_rate * corner_radius
  double deceleration = 1.0;       // m/s^2 when slowing for a corner or the end
  double arrival_distance = 0.05;  // m from an open route's last waypoint (or past it): arrived
};

class RouteFollower {
 public:
  explicit RouteFollower(RouteFollowerSettings settings = {});

  // Starts `route` (validated by the caller) from its first waypoint.
  void setRoute(Route route);
  bool hasRoute() const { return !route_.waypoints.empty(); }
  const Route& route() const { return route_; }

  struct Steering {
    double turn_rate = 0.0;    // rad/s, within max_turn_rate
    double speed_limit = 0.0;  // m/s: at most this fast here (corners, arrival)
  };
  // The steering at `position` with `heading` (rad) when walking at `speed`; advances past the
  // waypoints reached. Allocation-free.
  Steering steer(const Eigen::Vector2d& position, double heading, double speed);

  bool arrived() const { return arrived_; }       // an open route's end reached
  std::size_t target() const { return target_; }  // index of the waypoint walked toward
  std::size_t laps() const { return laps_; }      // closed routes: times waypoint 0 was passed again

 private:
  const Eigen::Vector2d& waypoint(std::size_t i) const { return route_.waypoints[i % route_.waypoints.size()]; }
  std::size_t count() const { return route_.waypoints.size(); }
  bool isLastLeg() const { return !route_.closed && target_ + 1 == count(); }
  Eigen::Vector2d carrot(const Eigen::Vector2d& position, double lookahead) const;
  double cornerSpeed(std::size_t corner) const;

  RouteFollowerSettings settings_;
  Route route_;
  std::size_t target_ = 0;
  std::size_t laps_ = 0;
  bool arrived_ = false;
};

}  // namespace dressed_human
