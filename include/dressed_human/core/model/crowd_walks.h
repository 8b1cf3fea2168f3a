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
  std::string id;          // frames body_<id>, ...
  Route route;             // in the crowd's fixed frame
  double speed = 1.2;      // m/s
  double stature = 1.0;    // times the skeleton's size
  double start_phase = 0;  // gait cycles
};

// `count` humans with ids 0..count-1 on nested rectangles, four per ring starting at its four
// corners, rings 0.7 m apart, alternate rings the other way round and 0.15 m/s faster: distinct
// loops in one area that never cross. Statures spread over 0.92 to 1.08.
std::vector<CrowdWalk> defaultCrowdWalks(std::size_t count);

// The humans of a crowd file (crowd_appearance.h), in the file's order, with the walking keys
//   "3": {route: [[0, 0], [4, 0], [4, 3]], route_end: loop, speed: 1.1, stature: 1.05, start_phase: 0.3}
// each optional: a human without a route walks the default layout's loop of its place in the
// file. Throws CrowdFileError naming the file, line and key.
std::vector<CrowdWalk> loadCrowdWalks(const std::string& path);

}  // namespace dressed_human
