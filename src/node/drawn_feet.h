#pragma once
// The feet the walkers plant are the ones the display draws: the soles of the body description
// (FootSoles), read from ~body_file (default: the package's config/bodies/default.yaml, the
// DressedHuman display's default "Body Description").

#include <string>

#include "dressed_human/core/skeleton/body_description.h"
#include "dressed_human/core/skeleton/foot_sole.h"

namespace dressed_human {

class Parameters;

// ~body_file, or the package's default body; throws ParameterError when neither is known.
std::string bodyFileParameter(const Parameters& parameters, const std::string& package);
// The body `body_file` describes on `skeleton`, with a foot on each foot bone; throws
// ParameterError naming the parameter and what is wrong with the file.
BodyDescription drawnBody(const std::string& body_file, const Skeleton& skeleton, const Parameters& parameters);

}  // namespace dressed_human
