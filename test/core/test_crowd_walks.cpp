#include "dressed_human/core/model/crowd_walks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "temp_file_path.h"

#include "dressed_human/core/model/crowd_appearance.h"

namespace dressed_human {
namespace {

std::string writeFile(const std::string& name, const std::string& text) {
  const std::string path = tempFilePath(name);
  std::ofstream(path) << text;
  return path;
}

std::string crowdWalksError(const std::string& text) {
  const std::string path = writeFile("crowd_walks_error.yaml", text);
  try {
    loadCrowdWalks(path);
  } catch (const CrowdFileError& error) {
    std::remove(path.c_str());
    return error.what();
  }
  std::remove(path.c_str());
  return "(no error)";
}

// Twice the signed area of a polygon: positive counter-clockwise.
double signedArea(const std::vector<Eigen::Vector2d>& points) {
  double area = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector2d& a = points[i];
    const Eigen::Vector2d& b = points[(i + 1) % points.size()];
    area += a.x() * b.y() - b.x() * a.y();
  }
  return area;
}

TEST(CrowdWalks, TheDefaultLayoutSpreadsHumansOverNestedLoopsThatNeverCross) {
  const std::vector<CrowdWalk> walks = defaultCrowdWalks(40);
  ASSERT_EQ(walks.size(), 40u);
  for (std::size_t i = 0; i < walks.size(); ++i) {
    const CrowdWalk& walk = walks[i];
    EXPECT_EQ(walk.id, std::to_string(i));
    EXPECT_NO_THROW(validateRoute(walk.route, "human " + walk.id));
    EXPECT_TRUE(walk.route.closed);
    ASSERT_EQ(walk.route.waypoints.size(), 4u);
    // Loop r is a rectangle of half sides 1.6 + 0.7 r and 1.0 + 0.7 r: loops 0.7 m apart never cross.
    const double ring = std::round((std::abs(walk.route.waypoints[0].x()) - 1.6) / 0.7);
    for (const Eigen::Vector2d& corner : walk.route.waypoints) {
      EXPECT_NEAR(std::abs(corner.x()), 1.6 + 0.7 * ring, 1e-12);
      EXPECT_NEAR(std::abs(corner.y()), 1.0 + 0.7 * ring, 1e-12);
    }
    // It starts on its loop, on the edge that ends at its first waypoint.
    const Eigen::Vector2d& previous = walk.route.waypoints.back();
    const Eigen::Vector2d& next = walk.route.waypoints.front();
    EXPECT_NEAR((walk.start - previous).norm() + (next - walk.start).norm(), (next - previous).norm(), 1e-9) << i;
    // Alternate loops the other way round, so that neighbours on adjacent loops meet, not follow.
    EXPECT_EQ(signedArea(walk.route.waypoints) > 0.0, static_cast<int>(ring) % 2 == 0) << "human " << i;
    EXPECT_GE(walk.stature, 0.92 - 1e-12);
    EXPECT_LE(walk.stature, 1.08 + 1e-12);
    EXPECT_GE(walk.start_phase, 0.0);
    EXPECT_LT(walk.start_phase, 1.0);
    // Forty fit in 8.8 m x 7.6 m: a view of one area shows them all.
    EXPECT_LE(std::abs(walk.start.x()), 4.4 + 1e-9);
    EXPECT_LE(std::abs(walk.start.y()), 3.8 + 1e-9);
    // Humans of one loop walk at one speed: nobody catches up with the one ahead.
    for (std::size_t j = 0; j < i; ++j) {
      // Neighbours on one loop start a few metres apart, on adjacent loops at least the 0.7 m between loops.
      const bool same_loop = walks[j].route.waypoints[0].cwiseAbs().isApprox(walk.route.waypoints[0].cwiseAbs());
      EXPECT_GT((walk.start - walks[j].start).norm(), same_loop ? 1.5 : 0.7 - 1e-9) << "humans " << j << " and " << i;
      if (same_loop) {
        EXPECT_DOUBLE_EQ(walks[j].speed, walk.speed);
      }
    }
  }
  // Four on the innermost loop (10.4 m long), then a human per 2.5 m: 6 on the next.
  EXPECT_EQ(std::abs(walks[3].route.waypoints[0].x()), 1.6);
  EXPECT_NEAR(std::abs(walks[4].route.waypoints[0].x()), 2.3, 1e-12);
  EXPECT_NEAR(std::abs(walks[9].route.waypoints[0].x()), 2.3, 1e-12);
  EXPECT_NEAR(std::abs(walks[10].route.waypoints[0].x()), 3.0, 1e-12);
  EXPECT_TRUE(defaultCrowdWalks(0).empty());
}

TEST(CrowdWalks, AFileSetsRoutesSpeedsAndStaturesAndTheDisplayReadsTheSameFile) {
  const std::string path = writeFile("crowd_walks.yaml",
                                     "humans:\n"
                                     "  alice: {route: [[0, 0], [4, 0], [4, 3]], route_end: stand, speed: 0.8,\n"
                                     "          stature: 1.1, start_phase: 0.25, outfit: one_piece}\n"
                                     "  bob: {outfit: jacket_pants}\n"
                                     "  carol: {route: [[5, 1], [6, 1]], treadmill: true}\n");
  const std::vector<CrowdWalk> walks = loadCrowdWalks(path);
  ASSERT_EQ(walks.size(), 3u);
  EXPECT_EQ(walks[0].id, "alice");
  EXPECT_FALSE(walks[0].treadmill);
  EXPECT_TRUE(walks[2].treadmill);
  ASSERT_EQ(walks[0].route.waypoints.size(), 3u);
  EXPECT_TRUE(walks[0].route.waypoints[2].isApprox(Eigen::Vector2d(4, 3)));
  EXPECT_FALSE(walks[0].route.closed);
  EXPECT_DOUBLE_EQ(walks[0].speed, 0.8);
  EXPECT_DOUBLE_EQ(walks[0].stature, 1.1);
  EXPECT_DOUBLE_EQ(walks[0].start_phase, 0.25);
  // Without walking keys: the default layout's second place.
  EXPECT_EQ(walks[1].id, "bob");
  EXPECT_EQ(walks[1].route.waypoints, defaultCrowdWalks(2)[1].route.waypoints);
  const auto appearance = loadCrowdFile(path);
  EXPECT_EQ(*appearance.at("alice").outfit, Outfit::kOnePiece);
  std::remove(path.c_str());
}

TEST(CrowdWalks, ABadWalkNamesItsKeyAndLine) {
  const std::string route_error = crowdWalksError("humans:\n  \"3\": {route: [[0, 0]]}\n");
  EXPECT_NE(route_error.find("humans.3.route"), std::string::npos) << route_error;
  const std::string pair_error = crowdWalksError("humans:\n  \"3\": {route: [[0, 0], [1]]}\n");
  EXPECT_NE(pair_error.find("humans.3.route[1]"), std::string::npos) << pair_error;
  EXPECT_NE(pair_error.find(":2:"), std::string::npos) << pair_error;
  const std::string speed_error = crowdWalksError("humans:\n  \"3\": {speed: 7}\n");
  EXPECT_NE(speed_error.find("humans.3.speed"), std::string::npos) << speed_error;
  const std::string stature_error = crowdWalksError("humans:\n  \"3\": {stature: 3}\n");
  EXPECT_NE(stature_error.find("humans.3.stature"), std::string::npos) << stature_error;
  const std::string end_error = crowdWalksError("humans:\n  \"3\": {route_end: bounce}\n");
  EXPECT_NE(end_error.find("loop or stand"), std::string::npos) << end_error;
  const std::string treadmill_error = crowdWalksError("humans:\n  \"3\": {treadmill: often}\n");
  EXPECT_NE(treadmill_error.find("humans.3.treadmill"), std::string::npos) << treadmill_error;
  const std::string short_treadmill =
      crowdWalksError("humans:\n  \"3\": {route: [[0, 0]], route_end: stand, treadmill: true}\n");
  EXPECT_NE(short_treadmill.find("two waypoints"), std::string::npos) << short_treadmill;
  const std::string unknown = crowdWalksError("humans:\n  \"3\": {sped: 1}\n");
  EXPECT_NE(unknown.find("unknown key"), std::string::npos) << unknown;
  EXPECT_EQ(crowdWalksError("humans:\n  \"3\": {route: [[0, 0], [2, 0]], speed: 1.4}\n"), "(no error)");
}

}  // namespace
}  // namespace dressed_human
