// How closely walkers follow real pedestrians (issue 36): recorded trajectories (Jülich/PeTrack or
// ETH/UCY obsmat) resampled at an input rate, fed to TrackedCrowd as a tracker's messages would
// come (every person present, one message per sample), the walkers ticking at 30 Hz between;
// each walker compared with the recording at the render time. One CSV row per file, input rate
// and smoothing window: how many tracks got a human, how late they left, root error, heading
// error while walking, foot slide per stance, the lowest sole, and the CPU per tick.
// bench/track_following.py runs it on the shared recordings and charts it.
//
// Usage: track_following <source_directory> <trajectory_file>... [--rates R...] [--smoothing S...]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <iostream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "dressed_human/core/skeleton/body_description.h"
#include "dressed_human/core/io/pedestrian_trajectories.h"
#include "dressed_human/core/locomotion/normative_gait.h"
#include "dressed_human/core/locomotion/stance_slide.h"
#include "dressed_human/core/locomotion/tracked_crowd.h"
#include "dressed_human/core/motion/motion_file.h"

namespace {

using namespace dressed_human;

constexpr double kTick = 1.0 / 30.0;      // s: the crowd publisher's default rate
constexpr double kMinTrackSeconds = 1.0;  // tracks at least this long must get a human
constexpr double kWalkingSpeed = 0.5;     // m/s: heading judged only above this
// s each side: the recording's direction of travel over a whole stride, not the head's sway
// from step to step (PeTrack tracks a head).
constexpr double kTravelWindow = 0.5;

// A recorded person's position at `time` (s), linearly between its frames; none outside them.
struct Recorded {
  std::vector<double> times;
  std::vector<Eigen::Vector2d> positions;
  bool covers(double time) const { return !times.empty() && time >= times.front() && time <= times.back(); }
  Eigen::Vector2d at(double time) const {
    const auto after = std::upper_bound(times.begin(), times.end(), time);
    if (after == times.begin()) return positions.front();
    if (after == times.end()) return positions.back();
    const std::size_t b = static_cast<std::size_t>(after - times.begin());
    const double s = (time - times[b - 1]) / (times[b] - times[b - 1]);
    return positions[b - 1] + s * (positions[b] - positions[b - 1]);
  }
};

double percentile(std::vector<double> values, double fraction) {
  if (values.empty()) return NAN;
  const std::size_t at =
      std::min(values.size() - 1, static_cast<std::size_t>(fraction * static_cast<double>(values.size())));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(at), values.end());
  return values[at];
}

struct Scene {
  const Skeleton& skeleton;
  const SpeedGait& gait;
};

void follow(const Scene& scene, const std::string& file, const std::map<std::string, Recorded>& people, double rate,
            double smoothing) {
  TrackedCrowdSettings settings;
  settings.track.smoothing = smoothing;
  TrackedCrowd crowd(
      [&](const std::string&, const WalkerSettings& walker) {
        return std::make_unique<Walker>(scene.skeleton, BodyShape(), scene.gait, walker);
      },
      settings);
  double start = 1e300, end = -1e300;
  for (const auto& [id, person] : people)
    start = std::min(start, person.times.front()), end = std::max(end, person.times.back());

  std::map<std::string, StanceSlideMeter> ground;
  std::map<std::string, double> first_seen, last_seen, drawn_at, left_at;
  std::vector<double> root_errors, heading_errors;
  double cpu_seconds = 0.0, human_ticks = 0.0, delay_sum = 0.0;
  std::size_t ticks = 0, most_humans = 0;
  std::vector<PersonSighting> sightings;
  long message = static_cast<long>(std::ceil(start * rate));
  for (double now = start; now <= end + 2.0; now += kTick) {
    const auto cpu_start = std::chrono::steady_clock::now();
    for (; message / rate <= now && message / rate <= end; ++message) {
      const double time = message / rate;
      sightings.clear();
      for (const auto& [id, person] : people) {
        if (!person.covers(time)) continue;
        PersonSighting sighting;
        sighting.id = id;
        sighting.observation.time = time;
        sighting.observation.position = person.at(time);
        sightings.push_back(sighting);
        if (!first_seen.count(id)) first_seen[id] = time;
        last_seen[id] = time;
      }
      for (const std::string& warning : crowd.observe(time, sightings)) std::cerr << file << ": " << warning << "\n";
    }
    crowd.advance(now, kTick);
    cpu_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - cpu_start).count();
    ++ticks;
    delay_sum += crowd.delay();
    most_humans = std::max(most_humans, crowd.humans().size());
    human_ticks += static_cast<double>(crowd.humans().size());
    const double render = now - crowd.delay();
    for (const auto& [id, human] : crowd.humans()) {
      if (!human.posed) continue;
      if (!drawn_at.count(id)) drawn_at[id] = now;
      ground[id].add(human.walker->feet(), human.pose, static_cast<int>(human.walker->feet().carryingPoint()));
      const Recorded& person = people.at(id);
      if (!person.covers(render)) continue;
      root_errors.push_back((human.walker->position() - person.at(render)).norm());
      const Eigen::Vector2d travel = person.at(render + kTravelWindow) - person.at(render - kTravelWindow);
      if (person.covers(render - kTravelWindow) && person.covers(render + kTravelWindow) &&
          travel.norm() > kWalkingSpeed * 2.0 * kTravelWindow) {
        heading_errors.push_back(
            std::abs(std::remainder(human.walker->heading() - std::atan2(travel.y(), travel.x()), 2.0 * M_PI)) * 180.0 /
            M_PI);
      }
    }
    for (const auto& [id, seen] : last_seen) {
      if (!left_at.count(id) && drawn_at.count(id) && !crowd.humans().count(id)) left_at[id] = now;
    }
  }
  std::size_t long_tracks = 0, drawn_long = 0;
  double latest_leave = 0.0, latest_appearance = 0.0;
  for (const auto& [id, first] : first_seen) {
    if (last_seen[id] - first >= kMinTrackSeconds) {
      ++long_tracks;
      drawn_long += drawn_at.count(id);
    }
    if (drawn_at.count(id)) latest_appearance = std::max(latest_appearance, drawn_at[id] - first);
    if (left_at.count(id)) latest_leave = std::max(latest_leave, left_at[id] - last_seen[id]);
  }
  std::vector<double> slides;
  double lowest = 1e9;
  for (const auto& [id, meter] : ground) {
    slides.insert(slides.end(), meter.slides.begin(), meter.slides.end());
    lowest = std::min(lowest, meter.lowest);
  }
  std::printf("%s,%g,%g,%.3f,%zu,%zu,%.2f,%.2f,%.4f,%.4f,%.1f,%.2f,%.2f,%.2f,%zu,%.4f\n", file.c_str(), rate, smoothing,
              delay_sum / static_cast<double>(ticks), long_tracks, drawn_long, latest_appearance, latest_leave,
              percentile(root_errors, 0.5), percentile(root_errors, 0.95), percentile(heading_errors, 0.95),
              1000.0 * percentile(slides, 0.5), 1000.0 * percentile(slides, 0.95), 1000.0 * lowest, most_humans,
              1000.0 * cpu_seconds / std::max(1.0, human_ticks));
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "usage: track_following <source_directory> <trajectory_file>... [--rates R...] [--smoothing S...]\n";
    return 2;
  }
  try {
    const std::string source = argv[1];
    std::vector<std::string> files;
    std::vector<double> rates{2.5, 10.0, 25.0}, smoothings{0.0, 0.15, 0.3, 0.5};
    std::vector<double>* list = nullptr;
    for (int a = 2; a < argc; ++a) {
      const std::string argument = argv[a];
      if (argument == "--rates" || argument == "--smoothing") {
        list = argument == "--rates" ? &rates : &smoothings;
        list->clear();
      } else if (list != nullptr) {
        list->push_back(std::stod(argument));
      } else {
        files.push_back(argument);
      }
    }
    const Skeleton skeleton = Skeleton::fromUrdfFile(source + "/urdf/human.urdf");
    const BodyDescription body = loadBodyDescriptionFile(source + "/config/bodies/default.yaml", skeleton);
    const SpeedGait gait(loadMotionFile(source + "/config/motions/walk.yaml"),
                         loadNormativeGaitFile(source + "/config/gait/speed_gaits.yaml"), skeleton, BodyShape(),
                         FootSoles(skeleton, BodyShape(), body));
    std::printf(
        "file,rate_hz,smoothing_s,delay_s,tracks_1s,tracks_1s_drawn,latest_appearance_s,latest_leave_s,"
        "root_median_m,root_p95_m,heading_p95_deg,slide_median_mm,slide_p95_mm,lowest_sole_mm,most_humans,"
        "cpu_ms_per_human_tick\n");
    for (const std::string& path : files) {
      const PedestrianTrajectories trajectories = loadPedestrianTrajectories(path);
      std::map<std::string, Recorded> people;
      for (const PersonTrajectory& trajectory : trajectories.people) {
        Recorded& person = people[std::to_string(trajectory.id)];
        for (const TrajectorySample& sample : trajectory.samples) {
          person.times.push_back(sample.time);
          person.positions.push_back(sample.position.head<2>());
        }
      }
      const std::string name = path.substr(path.find_last_of('/') + 1);
      for (const double rate : rates) {
        for (const double smoothing : smoothings) follow({skeleton, gait}, name, people, rate, smoothing);
      }
    }
  } catch (const std::exception& error) {
    std::cerr << "track_following: " << error.what() << "\n";
    return 1;
  }
  return 0;
}
