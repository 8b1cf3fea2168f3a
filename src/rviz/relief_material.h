#pragma once
// One bump-mapped material per surface part: a clone of dressed_human/ReliefSurface (media/) with
// the part's colour, relief strength and tangent-space normal map.

#include <cstdint>
#include <string>
#include <vector>

#include <OgreMaterial.h>
#include <OgreTexture.h>

namespace dressed_human {

class ReliefMaterial {
 public:
  // Loads media/materials once per process (resource group "dressed_human"). Throws
  // std::runtime_error with Ogre's message when the material or its GLSL programs do not load.
  static void loadMediaOnce();

  explicit ReliefMaterial(const std::string& unique_name);
  ~ReliefMaterial();
  ReliefMaterial(const ReliefMaterial&) = delete;
  ReliefMaterial& operator=(const ReliefMaterial&) = delete;

  const std::string& name() const { return name_; }
  void setColour(float r, float g, float b, float a = 1.0f);
  // 0 shades with the geometric normal only (flat), 1 with the full relief.
  void setReliefStrength(float strength);
  void setReliefTiling(float repeats_per_patch);
  // RGB8 tangent-space normals (n * 0.5 + 0.5), width * height * 3 bytes, with mipmaps.
  void setNormalMap(const std::vector<std::uint8_t>& rgb, int width, int height);

 private:
  std::string name_;
  Ogre::MaterialPtr material_;
  Ogre::TexturePtr texture_;
};

}  // namespace dressed_human
