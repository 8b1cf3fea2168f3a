// Garment topology (SPEC §3): pants are a hips ring on two tubes (boundary loops of the
// tessellated mesh: waist + two cuffs = 3; each leg, two patch rows joined at the knee, alone is
// a tube with 2), a skirt is one tube (2 loops); the link structure of every outfit.
#include <gtest/gtest.h>

#include "dressed_human/core/surfaces/mesh_boundary.h"
#include "garment_test_support.h"

#include <map>
#include <set>

namespace dressed_human {
namespace {

using namespace garment_test;

std::size_t loopsOf(const std::vector<BezierPatch>& patches, const PatchTopology& topology) {
  Tessellator tessellator;
  return boundaryLoops(tessellator.tessellateUniform(patches, topology, 6)).size();
}

// Components of a patch subset joined by topology links (not by a shared corner only).
std::size_t linkedComponents(const PatchTopology& topology, const std::set<std::uint32_t>& patches) {
  std::map<std::uint32_t, std::uint32_t> parent;
  for (std::uint32_t p : patches) parent[p] = p;
  std::function<std::uint32_t(std::uint32_t)> find = [&](std::uint32_t x) {
    return parent[x] == x ? x : parent[x] = find(parent[x]);
  };
  for (const EdgeLink& l : topology.links()) {
    if (patches.count(l.patch_a) && patches.count(l.patch_b)) parent[find(l.patch_a)] = find(l.patch_b);
  }
  std::set<std::uint32_t> roots;
  for (std::uint32_t p : patches) roots.insert(find(p));
  return roots.size();
}

TEST(GarmentTopology, PantsAreAHipsRingOnTwoTubes) {
  Garment pants(garmentFile("pants"), skeleton(), body().shape);
  for (const SkeletonPose& pose : walkPoses(4, body().shape)) {
    pants.pose(pose);
    EXPECT_EQ(loopsOf(pants.patches(), pants.topology()), 3u);  // waist + two cuffs
  }
  std::set<std::uint32_t> legs;
  for (std::uint32_t p = 0; p < pants.patches().size(); ++p) {
    const std::string& piece = pants.net().patchPiece(p);
    if (piece == "l_leg" || piece == "r_leg") legs.insert(p);
  }
  ASSERT_EQ(legs.size(), 8u);                               // per leg: thigh row and shank row, front and back each
  EXPECT_EQ(linkedComponents(pants.topology(), legs), 2u);  // left and right are not joined
  // Each tube alone: an annulus (its rim at the crotch and its cuff), its two rows joined at the knee.
  for (const std::string side : {"l_leg", "r_leg"}) {
    std::vector<BezierPatch> tube;
    for (std::uint32_t p : legs) {
      if (pants.net().patchPiece(p) == side) tube.push_back(pants.patches()[p]);
    }
    EXPECT_EQ(loopsOf(tube, PatchTopology::fromCoincidentEdges(tube, 1e-12)), 2u) << side;
  }
  // 4 hips ring + per tube 2 rows x 2 (side seam, inseam) + 2 at the knee + 4 rim links.
  EXPECT_EQ(pants.topology().links().size(), 4u + 2u * (4u + 2u) + 4u);
}

TEST(GarmentTopology, SkirtIsOneTubeAndTheJacketHasSleeves) {
  Garment skirt(garmentFile("skirt"), skeleton(), body().shape);
  EXPECT_EQ(loopsOf(skirt.patches(), skirt.topology()), 2u);
  EXPECT_EQ(skirt.topology().links().size(), 12u);  // 2 rows x 4 around + 4 between the rows
  Garment jacket(garmentFile("jacket"), skeleton(), body().shape);
  // Torso (neck + hem) and two sleeves (shoulder + cuff each): 6 loops.
  EXPECT_EQ(loopsOf(jacket.patches(), jacket.topology()), 6u);
  Garment dress(garmentFile("one_piece"), skeleton(), body().shape);
  EXPECT_EQ(loopsOf(dress.patches(), dress.topology()), 6u);
}

}  // namespace
}  // namespace dressed_human
