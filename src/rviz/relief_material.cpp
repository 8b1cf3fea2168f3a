#include "relief_material.h"

#include <algorithm>
#include <stdexcept>

#include <OgreGpuProgramManager.h>
#include <OgreMaterialManager.h>
#include <OgrePass.h>
#include <OgreResourceGroupManager.h>
#include <OgreTechnique.h>
#include <ros/package.h>

#include "gl_renderer.h"
#include "normal_map_texture.h"

namespace dressed_human {
namespace {

const char* const kGroup = "dressed_human";
const char* const kBaseMaterial = "dressed_human/ReliefSurface";
const char* const kBezierMaterial = "dressed_human/ReliefBezierSurface";
const char* const kReliefFragment = "dressed_human/ReliefSurfaceFragment";
const char* const kPlainFragment = "dressed_human/PlainSurfaceFragment";
const char* const kFoldCoordinateFragment = "dressed_human/FoldCoordinateFragment";
const char* const kVertexLitFragment = "dressed_human/VertexLitFragment";
const char* const kSurfaceVertex = "dressed_human/ReliefSurfaceVertex";
const char* const kBezierVertex = "dressed_human/ReliefBezierVertex";
const char* const kSurfaceVertexLit = "dressed_human/ReliefSurfaceVertexLit";
const char* const kBezierVertexLit = "dressed_human/ReliefBezierVertexLit";

std::string mediaDirectory() {
  const std::string package = ros::package::getPath("dressed_human");
  return package.empty() ? std::string(DRESSED_HUMAN_MEDIA_DIR) : package + "/media/materials";
}

Ogre::GpuProgramParametersSharedPtr fragmentParameters(const Ogre::MaterialPtr& material) {
  return material->getTechnique(0)->getPass(0)->getFragmentProgramParameters();
}

Ogre::GpuProgramParametersSharedPtr vertexParameters(const Ogre::MaterialPtr& material) {
  return material->getTechnique(0)->getPass(0)->getVertexProgramParameters();
}

// Empty when the material's GLSL programs compiled and are supported; else what went wrong.
std::string programProblem(const std::string& material_name) {
  Ogre::MaterialPtr material = Ogre::MaterialManager::getSingleton().getByName(material_name, kGroup);
  if (!material) return "material " + material_name + " not found";
  material->load();
  const Ogre::Pass* pass = material->getTechnique(0)->getPass(0);
  for (const Ogre::GpuProgramPtr& program : {pass->getVertexProgram(), pass->getFragmentProgram()}) {
    if (!program || program->hasCompileError() || !program->isSupported()) {
      return "GLSL program " + (program ? program->getName() : std::string("(missing)")) +
             " failed to compile (see the Ogre log)";
    }
  }
  return "";
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
    const std::string problem = programProblem(kBaseMaterial);
    if (!problem.empty()) throw std::runtime_error(problem + " (media: " + media + ")");
  } catch (const Ogre::Exception& error) {
    throw std::runtime_error(error.getFullDescription());
  }
}

bool ReliefMaterial::bezierEvaluationAvailable(std::string* why) {
  loadMediaOnce();
  std::string problem;
  try {
    problem = programProblem(kBezierMaterial);
  } catch (const Ogre::Exception& error) {
    problem = error.getFullDescription();
  }
  // The shader's uniform array and its few other uniforms must fit the GL's vertex uniform space.
  std::string setting_problem;
  const std::size_t registers_offered = vertexUniformVectors(&setting_problem);
  if (problem.empty()) problem = setting_problem;
  const std::size_t needed = 16 * kMaxPatches + 16;
  if (problem.empty() && registers_offered < needed) {
    problem = "the GPU offers " + std::to_string(registers_offered) +
              " vertex shader uniform vectors, the Bezier evaluation needs " + std::to_string(needed);
  }
  if (why) *why = problem;
  return problem.empty();
}

ReliefMaterial::ReliefMaterial(const std::string& unique_name, bool gpu_vertices, bool oriented_folds)
    : name_(unique_name),
      gpu_vertices_(gpu_vertices),
      relief_fragment_(oriented_folds ? kFoldCoordinateFragment : kReliefFragment),
      normal_channels_(oriented_folds ? 4 : 3) {
  loadMediaOnce();
  material_ = Ogre::MaterialManager::getSingleton()
                  .getByName(gpu_vertices ? kBezierMaterial : kBaseMaterial, kGroup)
                  ->clone(name_);
  if (oriented_folds) {
    material_->getTechnique(0)->getPass(0)->setFragmentProgram(relief_fragment_);
    applyShadingParameters();
  }
  // Flat until a relief map arrives: normals (0, 0, 1), or both fold tiles' x, y zero.
  static const auto flat_rgb = std::make_shared<const EncodedNormalMap>(EncodedNormalMap{1, 1, 3, {{128, 128, 255}}});
  static const auto flat_folds =
      std::make_shared<const EncodedNormalMap>(EncodedNormalMap{1, 1, 4, {{128, 128, 128, 128}}});
  setNormalMap(oriented_folds ? flat_folds : flat_rgb);
}

ReliefMaterial::~ReliefMaterial() {
  if (material_) Ogre::MaterialManager::getSingleton().remove(material_);
  texture_.reset();
}

void ReliefMaterial::applyShadingParameters() {
  if (litPerVertex()) {
    vertexParameters(material_)->setNamedConstant("diffuseColour", colour_);
    return;
  }
  const Ogre::GpuProgramParametersSharedPtr parameters = fragmentParameters(material_);
  parameters->setNamedConstant("diffuseColour", colour_);
  if (relief_shown_) parameters->setNamedConstant("reliefStrength", relief_strength_);
}

void ReliefMaterial::applyPrograms() {
  Ogre::Pass* pass = material_->getTechnique(0)->getPass(0);
  const bool lit = litPerVertex();
  const char* vertex =
      gpu_vertices_ ? (lit ? kBezierVertexLit : kBezierVertex) : (lit ? kSurfaceVertexLit : kSurfaceVertex);
  pass->setVertexProgram(vertex);
  pass->setFragmentProgram(relief_shown_ ? relief_fragment_ : lit ? kVertexLitFragment : kPlainFragment);
  // New programs come with their default parameters: everything set before is set again (the
  // control points are, every frame).
  wrinkle_strength_set_ = false;
  applyShadingParameters();
}

void ReliefMaterial::setReliefShown(bool shown) {
  if (shown == relief_shown_) return;
  relief_shown_ = shown;
  applyPrograms();
}

void ReliefMaterial::setVertexLit(bool lit) {
  if (lit == vertex_lit_) return;
  vertex_lit_ = lit;
  if (!relief_shown_) applyPrograms();
}

void ReliefMaterial::setColour(float r, float g, float b, float a) {
  colour_ = Ogre::ColourValue(r, g, b, a);
  applyShadingParameters();
  Ogre::Pass* pass = material_->getTechnique(0)->getPass(0);
  if (a < 1.0f) {
    pass->setSceneBlending(Ogre::SBT_TRANSPARENT_ALPHA);
    pass->setDepthWriteEnabled(false);
  } else {
    pass->setSceneBlending(Ogre::SBT_REPLACE);
    pass->setDepthWriteEnabled(true);
  }
}

void ReliefMaterial::setBackFacesCulled(bool culled) {
  material_->getTechnique(0)->getPass(0)->setCullingMode(culled ? Ogre::CULL_CLOCKWISE : Ogre::CULL_NONE);
}

void ReliefMaterial::setReliefStrength(float strength) {
  relief_strength_ = strength;
  applyShadingParameters();
}

void ReliefMaterial::setPatches(const std::vector<BezierPatch>& patches) {
  if (!gpu_vertices_) throw std::logic_error("ReliefMaterial " + name_ + ": patches set on a CPU-vertex material");
  if (patches.size() > kMaxPatches) {
    throw std::invalid_argument(name_ + " has " + std::to_string(patches.size()) +
                                " patches; the Bezier vertex shader holds " + std::to_string(kMaxPatches));
  }
  if (patches.empty()) return;
  // Straight into the parameters' float buffer (which the render system uploads when it binds
  // the pass): a staging copy would double the bytes written per frame.
  const Ogre::GpuProgramParametersSharedPtr parameters = vertexParameters(material_);
  const Ogre::GpuConstantDefinition& definition = parameters->getConstantDefinition("controlPoints");
  if (definition.arraySize * definition.elementSize < patches.size() * 16 * 4) {
    throw std::logic_error(name_ + ": the shader's controlPoints array holds fewer than " +
                           std::to_string(patches.size()) + " patches");
  }
  float* out = parameters->getFloatPointer(definition.physicalIndex);
  for (const BezierPatch& patch : patches) {
    for (const Eigen::Vector3d& point : patch.controlPoints()) {
      const Eigen::Vector3f p = point.cast<float>();
      *out++ = p.x();
      *out++ = p.y();
      *out++ = p.z();
      *out++ = 1.0f;
    }
  }
}

void ReliefMaterial::setWrinkleStrength(const WrinkleStrengthConstants* constants) {
  if (litPerVertex()) return;  // no relief, and the lit program has no wrinkle parameters
  const WrinkleStrengthConstants wanted = constants ? *constants : WrinkleStrengthConstants{0.0f, 0.0f};
  if (wrinkle_strength_set_ && wanted.inverse_threshold == wrinkle_strength_.inverse_threshold &&
      wanted.inverse_saturation == wrinkle_strength_.inverse_saturation) {
    return;  // every frame otherwise: three constant lookups by name
  }
  wrinkle_strength_ = wanted;
  wrinkle_strength_set_ = true;
  const Ogre::GpuProgramParametersSharedPtr parameters = vertexParameters(material_);
  parameters->setNamedConstant("wrinkleWeighting", constants ? 1.0f : 0.0f);
  if (!constants) return;
  parameters->setNamedConstant("wrinkleInverseThreshold", constants->inverse_threshold);
  parameters->setNamedConstant("wrinkleInverseSaturation", constants->inverse_saturation);
}

void ReliefMaterial::setNormalMap(const std::shared_ptr<const EncodedNormalMap>& map) {
  if (!map || map->channels != normal_channels_) {
    throw std::invalid_argument("material " + name_ + " takes a normal map of " + std::to_string(normal_channels_) +
                                " channels, given " + (map ? std::to_string(map->channels) : std::string("none")));
  }
  texture_ = NormalMapTexture::of(map, kGroup);
  material_->getTechnique(0)->getPass(0)->getTextureUnitState(0)->setTexture(texture_->texture());
}

}  // namespace dressed_human
