#pragma once
// The skeleton and body a crowd human of some stature is drawn with: the description's skeleton
// scaled so that it puts the fixed bones where that human's TF (or crowd message) does, and the
// body with the display's shape times the stature. A stature within 0.5 % of 1, or a description
// that records proportions of its own, gives them unscaled (drawnStature).

#include <string>

#include "dressed_human/core/skeleton/body_description.h"
#include "dressed_human/core/skeleton/skeleton.h"

namespace dressed_human {

struct CrowdHumanBody {
  Skeleton skeleton;            // with the human's frame suffix
  BodyDescription description;  // its shape: `shape` times the drawn stature
};
CrowdHumanBody crowdHumanBody(const Skeleton& skeleton, const BodyDescription& body, const BodyShape& shape,
                              const std::string& suffix, double stature);

}  // namespace dressed_human
