// People from elsewhere walking as humans: a track read between its samples (PersonTrack) and
// walkers steered after it (TrackedCrowd), on synthetic tracks whose truth is known.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "dressed_human/core/locomotion/tracked_crowd.h"
#include "locomotion_test_support.h"

namespace dressed_human {
namespace {

using locomotion_test::GroundRecord;

double median(std::vector<double> values) {
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

TrackObservation at(double time, double x, double y) {
  TrackObservation observation;
  observation.time = time;
  observation.position = {x, y};
  return observation;
}

TEST(PersonTrack, FollowsASteadyWalkWithoutLagAndAveragesJitterOut) {
  PersonTrack track;
  std::mt19937 random(7);
  std::normal_distribution<double> jitter(0.0, 0.03);
  for (int i = 0; i <= 250; ++i) track.add(at(0.04 * i, 1.3 * 0.04 * i + jitter(random), 2.0 + jitter(random)));
  std::vector<double> errors;
  for (double t = 7.5; t < 9.6; t += 0.05) {
    const PersonTrack::Point point = track.at(t);
    errors.push_back((point.position - Eigen::Vector2d(1.3 * t, 2.0)).norm());
    EXPECT_NEAR(point.velocity.x(), 1.3, 0.25) << t;  // a slope fitted to 3 cm jitter: about 0.1 m/s off
  }
  // 3 cm of jitter per sample, a straight fit over +-0.3 s of 25 Hz samples: about 1 cm left.
  EXPECT_LT(median(errors), 0.015);
  EXPECT_LT(*std::max_element(errors.begin(), errors.end()), 0.04);
}

TEST(PersonTrack, ReadsBeforeTheFirstAndPastTheNewestSample) {
  PersonTrack track;
  for (int i = 0; i <= 10; ++i) track.add(at(0.1 * i, 1.0 * 0.1 * i, 0.0));
  EXPECT_TRUE(track.at(-1.0).position.isApprox(Eigen::Vector2d(0.0, 0.0)));
  EXPECT_EQ(track.at(-1.0).velocity, Eigen::Vector2d::Zero()) << "before the first sample it stands";
  EXPECT_NEAR(track.at(1.5).position.x(), 1.5, 1e-9) << "0.5 s past the newest: on along its velocity";
  EXPECT_NEAR(track.at(5.0).position.x(), 2.0, 1e-9) << "predicted for max_prediction (1 s) at most";
  EXPECT_NEAR(track.typicalInterval(), 0.1, 1e-9);
}

TEST(PersonTrack, AJumpNoWalkerCanMakeStartsTheTrackAgain) {
  PersonTrack track;
  for (int i = 0; i <= 10; ++i) EXPECT_NE(track.add(at(0.1 * i, 0.1 * i, 0.0)), PersonTrack::Added::kJumped);
  EXPECT_EQ(track.add(at(1.1, 1.1, 0.0)), PersonTrack::Added::kAppended);
  EXPECT_EQ(track.add(at(1.1, 1.1, 0.0)), PersonTrack::Added::kNotNewer);
  EXPECT_EQ(track.add(at(1.2, 1.2, 1.5)), PersonTrack::Added::kJumped) << "1.5 m sideways in 0.1 s";
  EXPECT_NEAR(track.firstTime(), 1.2, 1e-12);
  EXPECT_EQ(track.add(at(1.3, 1.6, 1.5)), PersonTrack::Added::kJumped) << "0.4 m in 0.1 s: 4 m/s";
  EXPECT_EQ(track.add(at(1.4, 1.65, 1.5)), PersonTrack::Added::kAppended) << "5 cm of jitter is no jump";
}

TEST(PersonTrack, CountsHowLongItHasBeenOccluded) {
  PersonTrack track;
  track.add(at(0.0, 0.0, 0.0));
  TrackObservation hidden = at(0.5, 0.5, 0.0);
  hidden.occluded = true;
  track.add(hidden);
  hidden.time = 1.2;
  track.add(hidden);
  EXPECT_NEAR(track.occludedFor(), 0.7, 1e-12);
  track.add(at(1.3, 1.3, 0.0));
  EXPECT_EQ(track.occludedFor(), 0.0);
}

// A crowd of one track, its walker recorded on the ground.
struct Follow {
  TrackedCrowd crowd{[](const std::string&, const WalkerSettings& settings) {
    return std::make_unique<Walker>(locomotion_test::skeleton(), BodyShape(), locomotion_test::gait(), settings);
  }};
  GroundRecord ground;
  std::vector<double> root_errors, heading_errors;
  double now = 0.0;
  static constexpr double kTick = 1.0 / 30.0;

  // Publishes `path(t)` at `rate` Hz for `seconds` (a message per sample, the walker ticking at
  // 30 Hz between), comparing the walker with the path at the render time.
  template <class Path>
  void run(double seconds, double rate, Path path, const std::string& id = "7", double noise = 0.0) {
    std::mt19937 random(3);
    std::normal_distribution<double> jitter(0.0, noise);
    double next_message = now;
    const double end = now + seconds;
    for (; now < end; now += kTick) {
      while (next_message <= now) {
        const Eigen::Vector2d p = path(next_message);
        crowd.observe(next_message, {{id, at(next_message, p.x() + jitter(random), p.y() + jitter(random))}});
        next_message += 1.0 / rate;
      }
      crowd.advance(now, kTick);
      auto found = crowd.humans().find(id);
      if (found == crowd.humans().end() || !found->second.posed) continue;
      const TrackedCrowd::Human& human = found->second;
      ground.add(*human.walker, human.pose);
      const double render = now - crowd.delay();
      root_errors.push_back((human.walker->position() - path(render)).norm());
      const Eigen::Vector2d travel = path(render + 0.05) - path(render - 0.05);
      if (travel.norm() > 0.05) {
        heading_errors.push_back(
            std::abs(std::remainder(human.walker->heading() - std::atan2(travel.y(), travel.x()), 2 * M_PI)));
      }
    }
  }
};

TEST(TrackedCrowd, AWalkerFollowsANoisyStraightTrackWithPlantedFeet) {
  for (const double rate : {2.5, 10.0, 25.0}) {
    Follow follow;
    const auto path = [](double t) { return Eigen::Vector2d(1.3 * t, 0.0); };
    follow.run(20.0, rate, path, "7", 0.03);
    ASSERT_GT(follow.root_errors.size(), 400u) << rate;
    const std::vector<double> settled(follow.root_errors.begin() + 60, follow.root_errors.end());
    EXPECT_LT(median(settled), 0.10) << rate << " Hz";
    EXPECT_LT(median(follow.heading_errors), 10.0 * M_PI / 180.0) << rate << " Hz";
    EXPECT_LT(median(follow.ground.slides), 0.005) << rate << " Hz";
    EXPECT_GT(follow.ground.lowest, -0.005) << rate << " Hz: a sole below the ground";
  }
}

TEST(TrackedCrowd, AWalkerTurnsACornerStopsAndStandsThenWalksOn) {
  Follow follow;
  // East for 4 s, north for 4 s, 3 s standing, then west.
  const auto path = [](double t) {
    if (t < 4.0) return Eigen::Vector2d(1.2 * t, 0.0);
    if (t < 8.0) return Eigen::Vector2d(4.8, 1.2 * (t - 4.0));
    if (t < 11.0) return Eigen::Vector2d(4.8, 4.8);
    return Eigen::Vector2d(4.8 - 1.2 * (t - 11.0), 4.8);
  };
  follow.run(10.5, 10.0, path);
  const TrackedCrowd::Human& standing = follow.crowd.humans().at("7");
  EXPECT_LT(standing.walker->speed(), TrackedCrowdSettings().standing_speed) << "standing where its track stands";
  EXPECT_LT((standing.walker->position() - Eigen::Vector2d(4.8, 4.8)).norm(), 0.15);
  follow.run(5.0, 10.0, path);
  EXPECT_GT(follow.crowd.humans().at("7").walker->speed(), 0.9) << "walking on";
  std::sort(follow.root_errors.begin(), follow.root_errors.end());
  EXPECT_LT(follow.root_errors[follow.root_errors.size() / 2], 0.10);
  // This track turns and stops from 1.2 m/s at once, which no person does: a walker stopping at
  // 2.5 m/s^2 needs 0.29 m, and turning at 2 rad/s cuts a corner by about 0.25 m; 0.1 m more of
  // tracking. (Real pedestrians: bench/track_following.py.)
  EXPECT_LT(follow.root_errors[follow.root_errors.size() * 95 / 100], 0.29 + 0.10);
}

TEST(TrackedCrowd, TracksComeAndGoAndBadSightingsAreNamed) {
  TrackedCrowd crowd([](const std::string&, const WalkerSettings& settings) {
    return std::make_unique<Walker>(locomotion_test::skeleton(), BodyShape(), locomotion_test::gait(), settings);
  });
  const auto step = [&](double from, double to) {
    for (double t = from; t < to; t += 0.1) crowd.advance(t, 0.1);
  };
  // Both tracks at 10 Hz (the render delay: the smoothing window), then track 2 ends: absent from the messages.
  double t = 0.0;
  for (; t < 0.55; t += 0.1) {
    EXPECT_TRUE(crowd.observe(t, {{"1", at(t, 0.0, 0.0)}, {"2", at(t, 5.0, 0.0)}}).empty());
    crowd.advance(t, 0.1);
    if (t > 0.45) {
      ASSERT_EQ(crowd.humans().size(), 2u);
      EXPECT_TRUE(crowd.humans().at("1").posed) << "a new track's human appears within 0.5 s";
    }
  }
  const double ended = t - 0.1;
  // Its human leaves as soon as it has walked to the last sample (the render delay), not only
  // once the track has been silent for a while.
  for (; t < ended + crowd.delay() + 0.15; t += 0.1) {
    crowd.observe(t, {{"1", at(t, 0.0, 0.0)}});
    crowd.advance(t, 0.1);
  }
  EXPECT_NEAR(crowd.delay(), PersonTrackSettings().smoothing, 1e-9);
  EXPECT_EQ(crowd.humans().count("2"), 0u);
  // Missed in one message and back in the next, before its human left: the same walker goes on.
  const Walker* walker = crowd.humans().at("1").walker.get();
  crowd.observe(t, {});
  crowd.advance(t, 0.1);
  t += 0.1;
  crowd.observe(t, {{"1", at(t, 0.0, 0.0)}});
  crowd.advance(t, 0.1);
  t += 0.1;
  ASSERT_EQ(crowd.humans().count("1"), 1u);
  EXPECT_EQ(crowd.humans().at("1").walker.get(), walker) << "a track missed once started a new walker";
  EXPECT_FALSE(crowd.humans().at("1").ended);
  // Bad sightings are named and left out; the track they belong to keeps walking.
  TrackObservation broken = at(t, NAN, 0.0);
  const std::vector<std::string> warnings =
      crowd.observe(t, {{"1", at(t, 0.0, 0.0)}, {"1", at(t, 0.1, 0.0)}, {"3", broken}});
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[0].find("track 1 appears twice"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[1].find("track 3"), std::string::npos) << warnings[1];
  EXPECT_EQ(crowd.humans().count("3"), 0u);
  EXPECT_EQ(crowd.humans().count("1"), 1u);
  // An empty message: every track ended.
  crowd.observe(t + 0.1, {});
  step(t + 0.1, t + 1.1);
  EXPECT_TRUE(crowd.humans().empty());
  // Time going back (a bag played again): every human starts over, said once.
  crowd.observe(3.0, {{"4", at(3.0, 1.0, 1.0)}});
  const std::vector<std::string> again = crowd.observe(0.5, {{"4", at(0.5, 1.0, 1.0)}});
  ASSERT_EQ(again.size(), 1u);
  EXPECT_NE(again[0].find("time went back"), std::string::npos) << again[0];
  // A source that falls silent: its humans leave once walked past their last sample.
  step(0.5, 2.0);
  EXPECT_TRUE(crowd.humans().empty());
}

TEST(TrackedCrowd, AnOccludedTrackWalksOnItsPredictionForASecondThenLeaves) {
  TrackedCrowd crowd([](const std::string&, const WalkerSettings& settings) {
    return std::make_unique<Walker>(locomotion_test::skeleton(), BodyShape(), locomotion_test::gait(), settings);
  });
  double t = 0.0;
  for (; t < 3.0; t += 0.1) {
    crowd.observe(t, {{"5", at(t, 1.2 * t, 0.0)}});
    crowd.advance(t, 0.1);
  }
  for (; t < 5.0; t += 0.1) {
    TrackObservation predicted = at(t, 1.2 * t, 0.0);
    predicted.occluded = true;
    crowd.observe(t, {{"5", predicted}});
    crowd.advance(t, 0.1);
    if (t < 3.9) {
      EXPECT_EQ(crowd.humans().count("5"), 1u) << t;
    }
  }
  EXPECT_EQ(crowd.humans().count("5"), 0u) << "occluded for 2 s: gone";
}

}  // namespace
}  // namespace dressed_human
