#pragma once
// What each human of a crowd wears, for a display drawing every human in TF: per human id (the
// "<id>" of its frames "body_<id>"), an outfit and colours, from a crowd file or picked from the
// id. A crowd of identical figures reads as one figure copied; crowd tools (pedsim_ros,
// spencer_tracking_rviz_plugin) colour each person by id for the same reason.

#include <map>
#include <optional>
#include <stdexcept>
#include <string>

#include <Eigen/Core>

#include "dressed_human/core/model/human_model.h"

namespace dressed_human {

struct CrowdFileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Each given field replaces the display's own setting; an empty one keeps it.
struct HumanAppearance {
  std::optional<Outfit> outfit;
  std::optional<Eigen::Vector4f> skin_colour;   // RGBA, 0..1
  std::optional<Eigen::Vector4f> upper_colour;  // jacket or one-piece
  std::optional<Eigen::Vector4f> lower_colour;  // skirt or pants

  void applyTo(HumanModelSettings& settings) const;
};

// An outfit, a skin tone and garment colours picked from `id` by a hash: the same human looks the
// same in every run and every rviz, and neighbouring ids differ.
HumanAppearance variedAppearance(const std::string& id);

// The crowd file (config/crowds/example.yaml):
//   humans:
//     "3": {outfit: jacket_pants, skin_colour: [0.55, 0.38, 0.28], upper_colour: [...], lower_colour: [...]}
// Every field optional; colours RGB in [0, 1]; the walking keys (route, speed, ...) are the crowd
// publisher's (crowd_walks.h). Throws CrowdFileError naming the file, line and key.
std::map<std::string, HumanAppearance> loadCrowdFile(const std::string& path);

}  // namespace dressed_human
