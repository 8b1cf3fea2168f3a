#include "dressed_human/core/model/relief_map_jobs.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <stdexcept>
#include <string>
#include <utility>

namespace dressed_human {

struct ReliefMapJobs::SharedBuild {
  ReliefKind kind;
  SkinReliefParameters skin;  // the key, with kind: the skin's parameters, the cloth's softness
  double fold_softness = 0.0;
  std::shared_future<FinishedReliefMap> result;
};

namespace {

// Every build of the process that someone still holds, by kind and parameters.
std::mutex registry_mutex;
std::vector<std::weak_ptr<ReliefMapJobs::SharedBuild>> registry;
std::atomic<std::size_t> builds{0};

// The build of (kind, skin) in the registry, or a new one running `build` on its own thread;
// what it throws comes back as the result's error.
template <typename Build>
std::shared_ptr<ReliefMapJobs::SharedBuild> obtain(ReliefKind kind, const SkinReliefParameters& skin,
                                                   double fold_softness, Build build) {
  std::lock_guard<std::mutex> lock(registry_mutex);
  registry.erase(std::remove_if(registry.begin(), registry.end(), [](const auto& entry) { return entry.expired(); }),
                 registry.end());
  for (const std::weak_ptr<ReliefMapJobs::SharedBuild>& entry : registry) {
    std::shared_ptr<ReliefMapJobs::SharedBuild> shared = entry.lock();
    const bool same = kind == ReliefKind::kCloth ? shared && shared->fold_softness == fold_softness
                                                 : shared && sameSkinParameters(shared->skin, skin);
    if (shared && shared->kind == kind && same) {
      return shared;
    }
  }
  auto shared = std::make_shared<ReliefMapJobs::SharedBuild>();
  shared->kind = kind;
  shared->skin = skin;
  shared->fold_softness = fold_softness;
  shared->result = std::async(std::launch::async, [kind, build] {
                     FinishedReliefMap done;
                     done.kind = kind;
                     try {
                       done = build();
                       done.kind = kind;
                     } catch (const std::exception& error) {
                       done.error = error.what();
                     }
                     return done;
                   }).share();
  ++builds;
  registry.push_back(shared);
  return shared;
}

}  // namespace

bool sameSkinParameters(const SkinReliefParameters& a, const SkinReliefParameters& b) {
  return a.levels == b.levels && a.cell_size == b.cell_size && a.seed == b.seed &&
         a.direction_angle == b.direction_angle && a.direction_stretch == b.direction_stretch && a.wobble == b.wobble &&
         a.jitter == b.jitter && a.roundness == b.roundness && a.profile.first_inner == b.profile.first_inner &&
         a.profile.second_inner == b.profile.second_inner;
}

ReliefMap transposed(const ReliefMap& map) {
  ReliefMap out(map.height, map.width);
  for (int row = 0; row < map.height; ++row) {
    for (int column = 0; column < map.width; ++column) {
      const std::size_t from = map.index(column, row), to = out.index(row, column);
      out.heights[to] = map.heights[from];
      out.slope_u[to] = map.slope_v[from];
      out.slope_v[to] = map.slope_u[from];
    }
  }
  return out;
}

WrinkleMapSpec garmentWrinkleMapSpec(double fold_softness) {
  if (!(fold_softness >= 0.0 && fold_softness <= kMaxFoldSoftness)) {
    throw std::invalid_argument("fold softness " + std::to_string(fold_softness) + " is outside [0, " +
                                std::to_string(kMaxFoldSoftness) + "] buckling cells");
  }
  // Y-Y chains (SPEC §4), the pattern wrinkle placement picks for the default garments' patches
  // (their surfaces turn about half a bend angle per cell; wrinkle_placement.h), at a strong
  // compression; a few large cells per patch, as cloth buckles at the scale of a hand, not of a
  // knit. The per-vertex wrinkle strength and fold axis from the posed garment (HumanModel)
  // decide where, how much and which way it shows (oriented_folds.h). The map compresses along
  // its rows (v); knees and elbows compress garments along the limb, patch u: hence the
  // transpose (garmentFoldTiles).
  WrinkleMapSpec spec;
  spec.chain = "YY";
  spec.cells_around = 2;
  spec.rows = 2;
  spec.alpha = {0.8};
  // Cells square once compressed (2 L_x = 2 alpha L_y): the tile is square in space as in
  // pixels, so its slopes turn with the lookups of oriented_folds.h.
  spec.cell.half_length_y = spec.cell.half_width_x / spec.alpha[0];
  // Soft folds (issue 40): the exact tile blurred through its own Fourier series, as far as the
  // cloth's softness says; 0 keeps the exact creases.
  if (fold_softness > 0.0) {
    spec.surface = WrinkleSurface::smoothFolds;
    spec.smooth_harmonics_per_cell = smoothHarmonicsForBlur(fold_softness);
    spec.smooth_harmonics_along_folds = smoothHarmonicsForBlur(kAlongFoldsBlur * fold_softness);
    spec.keep_depth = true;
  } else {
    spec.surface = WrinkleSurface::exactFolds;
  }
  return spec;
}

FoldTiles garmentFoldTiles(int pixels, double fold_softness) {
  WrinkleMapSpec strong = garmentWrinkleMapSpec(fold_softness);
  strong.width_pixels = strong.height_pixels = pixels;
  WrinkleMapSpec slight = strong;
  slight.chain = "I";
  return FoldTiles(transposed(makeWrinkleMap(slight)), transposed(makeWrinkleMap(strong)));
}

// A build another ReliefMapJobs shares goes on for it; the last holder of a build waits for its
// thread when it lets go (the shared state of std::async), so no thread outlives its users.
ReliefMapJobs::~ReliefMapJobs() = default;

std::size_t ReliefMapJobs::buildCount() { return builds.load(); }

bool ReliefMapJobs::busy(ReliefKind kind) const {
  const Job& job = jobs_[kind];
  return job.running && job.running->result.wait_for(std::chrono::seconds(0)) != std::future_status::ready;
}

void ReliefMapJobs::requestSkin(const SkinReliefParameters& parameters) {
  skin_requested_ = parameters;
  if (!busy(ReliefKind::kSkin)) startSkin(parameters);
}

void ReliefMapJobs::startSkin(const SkinReliefParameters& parameters) {
  // A 512^2 map takes a noticeable fraction of a second; a bad parameter throws inside the job.
  jobs_[ReliefKind::kSkin].running = obtain(ReliefKind::kSkin, parameters, 0.0, [parameters] {
    FinishedReliefMap done;
    auto map = std::make_shared<const ReliefMap>(SkinRelief(parameters).render(kSkinMapSize, kSkinMapSize));
    done.normal_map = std::make_shared<const EncodedNormalMap>(encodeNormalMapMips(*map));
    done.map = std::move(map);
    return done;
  });
  skin_started_ = parameters;
}

void ReliefMapJobs::requestCloth(double fold_softness) {
  cloth_requested_ = fold_softness;
  if (!busy(ReliefKind::kCloth)) startCloth(fold_softness);
}

void ReliefMapJobs::startCloth(double fold_softness) {
  jobs_[ReliefKind::kCloth].running =
      obtain(ReliefKind::kCloth, SkinReliefParameters(), fold_softness, [fold_softness] {
        FinishedReliefMap done;
        auto tiles = std::make_shared<const FoldTiles>(garmentFoldTiles(512, fold_softness));
        done.normal_map = std::make_shared<const EncodedNormalMap>(encodeFoldTilesMips(*tiles));
        done.map = std::shared_ptr<const ReliefMap>(tiles, &tiles->strong);
        done.fold_tiles = std::move(tiles);
        return done;
      });
  cloth_started_ = fold_softness;
}

float ReliefMapJobs::clothHeightToTile() {
  // A tile spans cells_around cells of 2 L_x each (wrinkle_map.h): heights in L_x units.
  const WrinkleMapSpec spec = garmentWrinkleMapSpec();
  return static_cast<float>(1.0 / (2.0 * spec.cell.half_width_x * spec.cells_around));
}

std::vector<FinishedReliefMap> ReliefMapJobs::poll() {
  std::vector<FinishedReliefMap> finished;
  for (const ReliefKind kind : {ReliefKind::kSkin, ReliefKind::kCloth}) {
    Job& job = jobs_[kind];
    if (!job.running || busy(kind)) continue;
    finished.push_back(job.running->result.get());
    if (finished.back().map) {
      job.map = finished.back().map;
      job.fold_tiles = finished.back().fold_tiles;
      job.held = job.running;
    }
    job.running.reset();
    if (kind == ReliefKind::kSkin && !sameSkinParameters(skin_requested_, skin_started_)) startSkin(skin_requested_);
    if (kind == ReliefKind::kCloth && cloth_requested_ != cloth_started_) startCloth(cloth_requested_);
  }
  return finished;
}

}  // namespace dressed_human
