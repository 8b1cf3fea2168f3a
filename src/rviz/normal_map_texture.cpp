#include "normal_map_texture.h"

#include <algorithm>
#include <cstdlib>
#include <map>
#include <stdexcept>

#include <OgreHardwarePixelBuffer.h>
#include <OgreTextureManager.h>

namespace dressed_human {
namespace {

std::map<const void*, std::weak_ptr<NormalMapTexture>> shared_textures;  // rviz's thread only
std::size_t texture_count = 0;                                           // for unique Ogre names

// Which mip levels the normal-map textures get: the maps' own (EncodedNormalMap's, the default),
// none (DRESSED_HUMAN_RELIEF_MIPMAPS=0), or the GPU's, averaged from level 0 (=gpu): the last
// two for bench/relief_flicker.py, which measures what the chain is worth.
enum class MipSource { kOwn, kNone, kGpu };
MipSource normalMapMipmaps() {
  const char* setting = std::getenv("DRESSED_HUMAN_RELIEF_MIPMAPS");
  if (setting == nullptr || std::string(setting) == "1") return MipSource::kOwn;
  if (std::string(setting) == "0") return MipSource::kNone;
  if (std::string(setting) == "gpu") return MipSource::kGpu;
  throw std::invalid_argument(
      "DRESSED_HUMAN_RELIEF_MIPMAPS='" + std::string(setting) +
      "' must be 1 (the default: the maps' own chain), 0 (no mipmaps) or gpu (the GPU's chain)");
}

// The map's levels, each checked against the size it must have.
Ogre::TexturePtr uploadNormalMap(const EncodedNormalMap& map, const std::string& name, const std::string& group) {
  if (map.channels != 3 && map.channels != 4) {
    throw std::invalid_argument("normal map " + name + ": " + std::to_string(map.channels) + " channels (3 or 4)");
  }
  if (map.width <= 0 || map.height <= 0 || map.levels.empty()) {
    throw std::invalid_argument("normal map " + name + ": " + std::to_string(map.width) + " x " +
                                std::to_string(map.height) + " pixels, " + std::to_string(map.levels.size()) +
                                " levels");
  }
  const MipSource source = normalMapMipmaps();
  const std::size_t levels = source == MipSource::kOwn ? map.levels.size() : 1;
  const Ogre::PixelFormat format = map.channels == 4 ? Ogre::PF_BYTE_RGBA : Ogre::PF_BYTE_RGB;
  for (std::size_t level = 0; level < levels; ++level) {
    const std::size_t expected = static_cast<std::size_t>(std::max(1, map.width >> level)) *
                                 static_cast<std::size_t>(std::max(1, map.height >> level)) *
                                 static_cast<std::size_t>(map.channels);
    if (map.levels[level].size() != expected) {
      throw std::invalid_argument("normal map " + name + ": level " + std::to_string(level) + " has " +
                                  std::to_string(map.levels[level].size()) + " bytes, not " + std::to_string(expected));
    }
  }
  // No TU_AUTOMIPMAP by default: the GPU would average the encoded normals (EncodedNormalMap).
  const bool gpu = source == MipSource::kGpu;
  Ogre::TexturePtr texture = Ogre::TextureManager::getSingleton().createManual(
      name, group, Ogre::TEX_TYPE_2D, static_cast<Ogre::uint>(map.width), static_cast<Ogre::uint>(map.height),
      gpu ? static_cast<int>(Ogre::MIP_UNLIMITED) : static_cast<int>(levels) - 1, format,
      gpu ? Ogre::TU_STATIC_WRITE_ONLY | Ogre::TU_AUTOMIPMAP : Ogre::TU_STATIC_WRITE_ONLY);
  for (std::size_t level = 0; level < levels; ++level) {
    const Ogre::PixelBox box(static_cast<Ogre::uint32>(std::max(1, map.width >> level)),
                             static_cast<Ogre::uint32>(std::max(1, map.height >> level)), 1, format,
                             const_cast<std::uint8_t*>(map.levels[level].data()));
    texture->getBuffer(0, level)->blitFromMemory(box);
  }
  return texture;
}

}  // namespace

std::shared_ptr<NormalMapTexture> NormalMapTexture::of(const std::shared_ptr<const EncodedNormalMap>& map,
                                                       const std::string& group) {
  std::shared_ptr<NormalMapTexture> shared = shared_textures[map.get()].lock();
  if (shared) return shared;
  const std::string texture_name = "dressed_human/normal_map_" + std::to_string(++texture_count);
  shared.reset(new NormalMapTexture);
  shared->map_ = map;
  try {
    shared->texture_ = uploadNormalMap(*map, texture_name, group);
  } catch (...) {
    if (Ogre::TextureManager::getSingleton().resourceExists(texture_name, group)) {
      Ogre::TextureManager::getSingleton().remove(texture_name, group);
    }
    shared_textures.erase(map.get());
    throw;
  }
  for (auto entry = shared_textures.begin(); entry != shared_textures.end();) {
    entry = entry->second.expired() && entry->first != map.get() ? shared_textures.erase(entry) : std::next(entry);
  }
  shared_textures[map.get()] = shared;
  return shared;
}

NormalMapTexture::~NormalMapTexture() {
  if (texture_) Ogre::TextureManager::getSingleton().remove(texture_);
}

}  // namespace dressed_human
