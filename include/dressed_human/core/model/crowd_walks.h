#pragma once
// How each human of a crowd walks, for the crowd publisher: its route, speed, stature and start
// phase, from the crowd file (the same file a DressedHuman display reads outfits from) or from
// the default layout of `crowd.launch count:=N`.

#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "dressed_human/core/locomotion/route.h"

namespace dressed_human {

struct CrowdWalk {
  std::string id;                                   // frames body_<id>, ...
  Route route;                                      // in the crowd's fixed frame
  Eigen::Vector2d start = Eigen::Vector2d::Zero();  // where it starts, facing the route's first waypoint
  double speed = 1.2;                               // m/s
  double stature = 1.0;                             // times the skeleton's size
  double start_phase = 0;                           // gait cycles
  // Walks at `speed` without travelling, as on a treadmill: at the route's first waypoint,
  // facing its second (benchmarks keep every human in one place in view).
  bool treadmill = false;
};

// `count` humans with ids 0..count-1 on nested rectangular loops 0.7 m apart, the innermost
// 3.2 m x 2 m: each loop holds a human per 2.5 m of its length (at least four), spread evenly
// along it, alternate loops walked the other way round and 0.15 m/s faster; distinct loops in one
// area that never cross (40 humans within 8.8 m x 7.6 m). Statures spread over 0.92 to 1.08.
std::vector<CrowdWalk> defaultCrowdWalks(std::size_t count);

// The humans of a crowd file (crowd_appearance.h), in the file's order, with the walking keys
//   "3": {route: [[0, 0], [4, 0], [4, 3]], route_end: loop, speed: 1.1, stature: 1.05, start_phase: 0.3,
//         treadmill: false}
// each optional: a human without a route walks the default layout's loop of its place in the
// file. A human with a route starts at its last waypoint (a loop) or its first (route_end stand). Throws CrowdFileError
// naming the file, line and key.
std::vector<CrowdWalk> loadCrowdWalks(const std::string& path);

}  // namespace dressed_human
