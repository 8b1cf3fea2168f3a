#pragma once
// One Ogre texture per normal map of the process, shared by every material given that map and
// alive while one uses it (rviz's thread only).

#include <memory>
#include <string>

#include <OgreTexture.h>

#include "dressed_human/core/relief/relief_map.h"

namespace dressed_human {

class NormalMapTexture {
 public:
  // The texture of `map` in resource group `group`, uploaded on first use: its mip levels as
  // given (EncodedNormalMap's; DRESSED_HUMAN_RELIEF_MIPMAPS=0 none, =gpu the GPU's, for
  // bench/relief_flicker.py). Throws std::invalid_argument for a map whose channels or level
  // sizes do not fit, or a malformed setting.
  static std::shared_ptr<NormalMapTexture> of(const std::shared_ptr<const EncodedNormalMap>& map,
                                              const std::string& group);
  ~NormalMapTexture();
  NormalMapTexture(const NormalMapTexture&) = delete;
  NormalMapTexture& operator=(const NormalMapTexture&) = delete;

  const Ogre::TexturePtr& texture() const { return texture_; }

 private:
  NormalMapTexture() = default;
  std::shared_ptr<const EncodedNormalMap> map_;  // kept so that its address, the cache's key, stays unique
  Ogre::TexturePtr texture_;
};

}  // namespace dressed_human
