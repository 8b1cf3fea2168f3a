#pragma once
// The two relief maps a renderer of HumanModel needs, each built off the caller's thread: the
// skin's Voronoi relief (SkinRelief, rebuilt when its parameters change) and the garments' wrinkle
// map (once). The caller polls without ever waiting; a change requested while a map is building
// starts the next build when that one ends. Builds are shared by the whole process: every
// ReliefMapJobs asking for the same map (kind and parameters) gets the one build, running or
// done, and the same map and normal-map bytes, for as long as any of them holds it -- ten humans
// in one rviz build their maps once, and the tenth appears at once.

#include <array>
#include <cstdint>
#include <future>
#include <memory>
#include <string>
#include <vector>

#include "dressed_human/core/model/human_model.h"
#include "dressed_human/core/relief/oriented_folds.h"
#include "dressed_human/core/relief/relief_map.h"
#include "dressed_human/core/relief/skin_relief.h"
#include "dressed_human/core/relief/wrinkle_map.h"

namespace dressed_human {

// How soft the garments' fold creases are by default: the exact folds blurred across their ridges
// by a Gaussian of this standard deviation, in buckling cells (the fold's width), and along them
// kAlongFoldsBlur times as far. An everyday woven jacket or skirt folds in long, round folds, not
// in the diamonds of the exact profile (docs/relief_distance.md shows both at 0.3-5 m, with how
// sharp the creases still measure); 0 draws the exact, creased profile of the seed (a thin,
// stiff sheet).
constexpr double kDefaultFoldSoftness = 0.2;
// Fabric does not keep the buckling lattice's diamonds along a fold: blurred only as much along
// the folds as across them, the Y-Y chains' junctions outweigh their ridges once the creases are
// round (beyond 0.12 cells) and the folds no longer run across the compression.
constexpr double kAlongFoldsBlur = 2.0;
// Largest fold softness a user may set: blurred further (one harmonic a cell across the folds),
// nothing of the chains' pattern is left (test_oriented_folds.cpp checks the direction at 0, the
// default and this).
constexpr double kMaxFoldSoftness = 0.3;

// One finished build: the map and its texture, or what the build threw.
struct FinishedReliefMap {
  ReliefKind kind = ReliefKind::kSkin;
  // Skin: the Voronoi relief. Cloth: the strong (Y-Y) fold tile of `fold_tiles`. Null: the build
  // failed.
  std::shared_ptr<const ReliefMap> map;
  std::shared_ptr<const FoldTiles> fold_tiles;  // cloth only
  // The texture a renderer samples, with its mip levels, shared like the map (a renderer may key
  // its texture by it): skin encodeNormalMapMips(*map), 3 channels; cloth
  // encodeFoldTilesMips(*fold_tiles), 4.
  std::shared_ptr<const EncodedNormalMap> normal_map;
  std::string error;
};

// The skin-relief fields a user sets: a change in any of them needs a new map.
bool sameSkinParameters(const SkinReliefParameters& a, const SkinReliefParameters& b);

class ReliefMapJobs {
 public:
  static constexpr int kSkinMapSize = 512;

  ReliefMapJobs() = default;
  ~ReliefMapJobs();  // waits for the builds still running
  ReliefMapJobs(const ReliefMapJobs&) = delete;
  ReliefMapJobs& operator=(const ReliefMapJobs&) = delete;

  // Starts building the skin map for `parameters` (kSkinMapSize square); while one is building,
  // the request waits and poll() starts it when that one ends (if the parameters differ).
  void requestSkin(const SkinReliefParameters& parameters);
  // Starts building the garments' fold tiles (garmentFoldTiles(512, fold_softness)); while one
  // is building, the request waits as the skin's does.
  void requestCloth(double fold_softness = kDefaultFoldSoftness);
  // Heights of the wrinkle map per tile width (for HumanModel::setDisplacement).
  static float clothHeightToTile();

  // The builds finished since the last call, skin first; never waits.
  std::vector<FinishedReliefMap> poll();
  // The newest map of `kind` built without an error; null before.
  const std::shared_ptr<const ReliefMap>& map(ReliefKind kind) const { return jobs_[kind].map; }
  // The newest fold tiles built without an error (the wrinkle map's); null before.
  const std::shared_ptr<const FoldTiles>& foldTiles() const { return jobs_[ReliefKind::kCloth].fold_tiles; }

  // Maps built in this process so far (each shared build counts once).
  static std::size_t buildCount();

  struct SharedBuild;  // one build and who waits for it (relief_map_jobs.cpp)

 private:
  struct Job {
    std::shared_ptr<SharedBuild> running;  // null: none since the last poll() delivered it
    std::shared_ptr<SharedBuild> held;     // the build whose map is in use: keeps it shared
    std::shared_ptr<const ReliefMap> map;
    std::shared_ptr<const FoldTiles> fold_tiles;
  };
  bool busy(ReliefKind kind) const;
  void startSkin(const SkinReliefParameters& parameters);
  void startCloth(double fold_softness);

  PerReliefKind<Job> jobs_;
  SkinReliefParameters skin_started_;    // what the running (or last) skin build was started with
  SkinReliefParameters skin_requested_;  // the newest request
  double cloth_started_ = -1.0;          // the fold softness of the running (or last) cloth build
  double cloth_requested_ = -1.0;
};

// The garments' strong fold tile before its transpose: Y-Y chains at a strong compression, cells
// square once compressed (see relief_map_jobs.cpp), drawn with `fold_softness` (cells; 0: exact
// folds). Throws std::invalid_argument for a softness outside [0, kMaxFoldSoftness].
WrinkleMapSpec garmentWrinkleMapSpec(double fold_softness = kDefaultFoldSoftness);
// The garments' two fold tiles (oriented_folds.h): I and garmentWrinkleMapSpec()'s Y-Y, both
// transposed so that they compress along u, `pixels` square (throws std::invalid_argument as
// makeWrinkleMap for a bad size), with `fold_softness` as garmentWrinkleMapSpec. About 0.4 s for
// both at 512.
FoldTiles garmentFoldTiles(int pixels = 512, double fold_softness = kDefaultFoldSoftness);
// The map with u and v swapped (heights and slopes).
ReliefMap transposed(const ReliefMap& map);

}  // namespace dressed_human
