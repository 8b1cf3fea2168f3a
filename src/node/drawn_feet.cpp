#include "drawn_feet.h"

#include <stdexcept>

#include "parameters.h"

namespace dressed_human {

std::string bodyFileParameter(const Parameters& parameters, const std::string& package) {
  const std::string file = parameters.text("body_file", package.empty() ? "" : package + "/config/bodies/default.yaml");
  if (file.empty()) {
    throw ParameterError("parameter " + parameters.fullName("body_file") +
                         " is not set and the dressed_human package path is unknown");
  }
  return file;
}

BodyDescription drawnBody(const std::string& body_file, const Skeleton& skeleton, const Parameters& parameters) {
  try {
    BodyDescription body = loadBodyDescriptionFile(body_file, skeleton);
    FootSoles(skeleton, BodyShape(), body);  // a body without feet is refused here, by name
    return body;
  } catch (const std::exception& error) {  // BodyDescriptionError (unreadable too), no foot
    throw ParameterError("parameter " + parameters.fullName("body_file") +
                         " (the body whose feet walk): " + error.what());
  }
}

}  // namespace dressed_human
