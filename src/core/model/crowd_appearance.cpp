#include "dressed_human/core/model/crowd_appearance.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>

#include "dressed_human/core/io/text_file.h"
#include "dressed_human/core/io/yaml_reader.h"

namespace dressed_human {
namespace {

// Skin tones from light to dark, and garment colours a street crowd wears: muted, a few bright.
constexpr std::array<std::array<float, 3>, 6> kSkinTones = {{{0.93f, 0.78f, 0.67f},
                                                             {0.87f, 0.72f, 0.62f},
                                                             {0.78f, 0.60f, 0.47f},
                                                             {0.64f, 0.46f, 0.33f},
                                                             {0.48f, 0.33f, 0.23f},
                                                             {0.33f, 0.22f, 0.16f}}};
constexpr std::array<std::array<float, 3>, 10> kGarmentColours = {{{0.22f, 0.32f, 0.58f},
                                                                   {0.72f, 0.22f, 0.30f},
                                                                   {0.20f, 0.20f, 0.22f},
                                                                   {0.55f, 0.55f, 0.52f},
                                                                   {0.30f, 0.45f, 0.30f},
                                                                   {0.80f, 0.65f, 0.30f},
                                                                   {0.45f, 0.30f, 0.20f},
                                                                   {0.85f, 0.85f, 0.82f},
                                                                   {0.25f, 0.50f, 0.65f},
                                                                   {0.50f, 0.25f, 0.50f}}};
constexpr std::array<Outfit, 3> kDressedOutfits = {Outfit::kJacketSkirt, Outfit::kJacketPants, Outfit::kOnePiece};

Eigen::Vector4f rgba(const std::array<float, 3>& rgb) { return {rgb[0], rgb[1], rgb[2], 1.0f}; }

// FNV-1a, then a final mix: short ids ("1", "2") must land far apart.
std::uint64_t idHash(const std::string& id) {
  std::uint64_t hash = 1469598103934665603ull;
  for (const unsigned char c : id) hash = (hash ^ c) * 1099511628211ull;
  hash ^= hash >> 33;
  hash *= 0xff51afd7ed558ccdull;
  hash ^= hash >> 33;
  return hash;
}

}  // namespace

void HumanAppearance::applyTo(HumanModelSettings& settings) const {
  if (outfit) settings.outfit = *outfit;
  if (skin_colour) settings.skin_colour = *skin_colour;
  if (upper_colour) {
    for (const char* upper : {"jacket", "one_piece"}) settings.garment_colours[upper] = *upper_colour;
  }
  if (lower_colour) {
    for (const char* lower : {"skirt", "pants"}) settings.garment_colours[lower] = *lower_colour;
  }
}

HumanAppearance variedAppearance(const std::string& id) {
  std::uint64_t hash = idHash(id);
  const auto pick = [&hash](std::size_t count) {
    const std::size_t choice = static_cast<std::size_t>(hash % count);
    hash /= count;
    return choice;
  };
  HumanAppearance appearance;
  appearance.outfit = kDressedOutfits[pick(kDressedOutfits.size())];
  appearance.skin_colour = rgba(kSkinTones[pick(kSkinTones.size())]);
  const std::size_t upper = pick(kGarmentColours.size());
  // The lower garment in another colour than the upper one.
  const std::size_t lower = (upper + 1 + pick(kGarmentColours.size() - 1)) % kGarmentColours.size();
  appearance.upper_colour = rgba(kGarmentColours[upper]);
  appearance.lower_colour = rgba(kGarmentColours[lower]);
  return appearance;
}

std::map<std::string, HumanAppearance> loadCrowdFile(const std::string& path) {
  const std::string text = readWholeFileOrThrow<CrowdFileError>(path, "the crowd file");
  const YamlReader<CrowdFileError> reader(path);
  const YAML::Node document = reader.load(text, "the crowd file");
  reader.rejectUnknownKeys(document, "", {"humans"});
  const YAML::Node humans = reader.require(document, "humans", "");
  reader.requireMap(humans, "humans");
  std::map<std::string, HumanAppearance> crowd;
  for (const auto& entry : humans) {
    const std::string id = entry.first.Scalar();
    const std::string key = "humans." + id;
    if (!isHumanId(id))
      reader.fail(entry.first, key, "a human id is the letters and digits after 'body_' in its frames");
    const YAML::Node& fields = entry.second;
    reader.requireMap(fields, key);
    // How the human walks is the crowd publisher's (crowd_walks.h): one file describes the crowd.
    reader.rejectUnknownKeys(fields, key,
                             {"outfit", "skin_colour", "upper_colour", "lower_colour", "route", "route_end", "speed",
                              "stature", "start_phase", "treadmill"});
    HumanAppearance appearance;
    if (fields["outfit"]) {
      try {
        appearance.outfit = outfitFromName(reader.text(fields["outfit"], key + ".outfit"));
      } catch (const std::invalid_argument& error) {
        reader.fail(fields["outfit"], key + ".outfit", error.what());
      }
    }
    const auto colour = [&](const char* name, std::optional<Eigen::Vector4f>& target) {
      if (!fields[name]) return;
      const std::string colour_key = key + "." + name;
      const std::vector<double> rgb = reader.numbers(fields[name], colour_key, 3, "(red, green, blue)");
      for (std::size_t i = 0; i < 3; ++i) {
        if (rgb[i] < 0.0 || rgb[i] > 1.0) {
          reader.fail(fields[name][i], colour_key + "[" + std::to_string(i) + "]",
                      "must lie in [0, 1], got " + fields[name][i].Scalar());
        }
      }
      target =
          Eigen::Vector4f(static_cast<float>(rgb[0]), static_cast<float>(rgb[1]), static_cast<float>(rgb[2]), 1.0f);
    };
    colour("skin_colour", appearance.skin_colour);
    colour("upper_colour", appearance.upper_colour);
    colour("lower_colour", appearance.lower_colour);
    crowd[id] = appearance;
  }
  return crowd;
}

}  // namespace dressed_human
