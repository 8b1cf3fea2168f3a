#include "relief_material.h"

#include <stdexcept>

#include <OgreGpuProgramManager.h>
#include <OgreHardwarePixelBuffer.h>
#include <OgreMaterialManager.h>
#include <OgrePass.h>
#include <OgreResourceGroupManager.h>
#include <OgreTechnique.h>
#include <OgreTextureManager.h>
#include <ros/package.h>

namespace dressed_human {
namespace {

const char* const kGroup = "dressed_human";
const char* const kBaseMaterial = "dressed_human/ReliefSurface";

std::string mediaDirectory() {
  const std::string package = ros::package::getPath("dressed_human");
  return package.empty() ? std::string(DRESSED_HUMAN_MEDIA_DIR) : package + "/media/materials";
}

Ogre::GpuProgramParametersSharedPtr fragmentParameters(const Ogre::MaterialPtr& material) {
  return material->getTechnique(0)->getPass(0)->getFragmentProgramParameters();
}

}  // namespace

void ReliefMaterial::loadMediaOnce() {
  auto& groups = Ogre::ResourceGroupManager::getSingleton();
  if (groups.resourceGroupExists(kGroup) && groups.isResourceGroupInitialised(kGroup)) return;
  try {
    const std::string media = mediaDirectory();
    groups.createResourceGroup(kGroup);
    groups.addResourceLocation(media + "/scripts", "FileSystem", kGroup);
    groups.addResourceLocation(media + "/glsl", "FileSystem", kGroup);
    groups.initialiseResourceGroup(kGroup);
    groups.loadResourceGroup(kGroup);
    Ogre::MaterialPtr base = Ogre::MaterialManager::getSingleton().getByName(kBaseMaterial, kGroup);
    if (!base) throw std::runtime_error(std::string("material ") + kBaseMaterial + " not found in " + media);
    base->load();
    const Ogre::Pass* pass = base->getTechnique(0)->getPass(0);
    for (const Ogre::GpuProgramPtr& program : {pass->getVertexProgram(), pass->getFragmentProgram()}) {
      if (!program || program->hasCompileError() || !program->isSupported()) {
        throw std::runtime_error("GLSL program " + (program ? program->getName() : std::string("(missing)")) +
                                 " failed to compile (see the Ogre log)");
      }
    }
  } catch (const Ogre::Exception& error) {
    throw std::runtime_error(error.getFullDescription());
  }
}

ReliefMaterial::ReliefMaterial(const std::string& unique_name) : name_(unique_name) {
  loadMediaOnce();
  material_ = Ogre::MaterialManager::getSingleton().getByName(kBaseMaterial, kGroup)->clone(name_);
  setNormalMap({128, 128, 255}, 1, 1);  // flat until a relief map arrives
}

ReliefMaterial::~ReliefMaterial() {
  if (material_) Ogre::MaterialManager::getSingleton().remove(material_);
  if (texture_) Ogre::TextureManager::getSingleton().remove(texture_);
}

void ReliefMaterial::setColour(float r, float g, float b, float a) {
  fragmentParameters(material_)->setNamedConstant("diffuseColour", Ogre::ColourValue(r, g, b, a));
  Ogre::Pass* pass = material_->getTechnique(0)->getPass(0);
  if (a < 1.0f) {
    pass->setSceneBlending(Ogre::SBT_TRANSPARENT_ALPHA);
    pass->setDepthWriteEnabled(false);
  } else {
    pass->setSceneBlending(Ogre::SBT_REPLACE);
    pass->setDepthWriteEnabled(true);
  }
}

void ReliefMaterial::setReliefStrength(float strength) {
  fragmentParameters(material_)->setNamedConstant("reliefStrength", strength);
}

void ReliefMaterial::setReliefTiling(float repeats_per_patch) {
  material_->getTechnique(0)->getPass(0)->getVertexProgramParameters()->setNamedConstant("reliefTiling",
                                                                                       repeats_per_patch);
}

void ReliefMaterial::setNormalMap(const std::vector<std::uint8_t>& rgb, int width, int height) {
  if (width <= 0 || height <= 0 || rgb.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3) {
    throw std::invalid_argument("normal map of " + std::to_string(rgb.size()) + " bytes does not match " +
                                std::to_string(width) + " x " + std::to_string(height) + " RGB");
  }
  if (texture_) Ogre::TextureManager::getSingleton().remove(texture_);
  Ogre::Image image;
  image.loadDynamicImage(const_cast<Ogre::uchar*>(rgb.data()), static_cast<Ogre::uint32>(width),
                         static_cast<Ogre::uint32>(height), Ogre::PF_BYTE_RGB);
  texture_ = Ogre::TextureManager::getSingleton().loadImage(name_ + "/normal_map", kGroup, image,
                                                             Ogre::TEX_TYPE_2D, Ogre::MIP_DEFAULT);
  material_->getTechnique(0)->getPass(0)->getTextureUnitState(0)->setTexture(texture_);
}

}  // namespace dressed_human
