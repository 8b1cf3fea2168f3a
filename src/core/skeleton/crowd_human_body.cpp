#include "dressed_human/core/skeleton/crowd_human_body.h"

#include "dressed_human/core/skeleton/urdf_body_shape.h"

namespace dressed_human {

CrowdHumanBody crowdHumanBody(const Skeleton& skeleton, const BodyDescription& body, const BodyShape& shape,
                              const std::string& suffix, double stature) {
  CrowdHumanBody human{skeletonAtStature(skeleton, stature).withSuffix(suffix), body};
  human.description.shape = shape;
  const double drawn = drawnStature(skeleton, stature);
  for (Eigen::Vector3d& scale : human.description.shape.scale) scale *= drawn;
  return human;
}

}  // namespace dressed_human
