#include "gl_renderer.h"

#include <algorithm>
#include <cstdlib>

#include <GL/gl.h>
#include <OgreRenderSystem.h>
#include <OgreRenderSystemCapabilities.h>
#include <OgreRoot.h>

namespace dressed_human {

std::size_t vertexUniformVectors(std::string* problem) {
  GLint components = 0;
  glGetIntegerv(GL_MAX_VERTEX_UNIFORM_COMPONENTS, &components);
  const Ogre::RenderSystemCapabilities* capabilities = Ogre::Root::getSingleton().getRenderSystem()->getCapabilities();
  const std::size_t vectors = components > 0 ? static_cast<std::size_t>(components) / 4
                              : capabilities ? capabilities->getVertexProgramConstantFloatCount()
                                             : 0;
  const char* limit = std::getenv("DRESSED_HUMAN_MAX_VERTEX_UNIFORM_VECTORS");
  if (limit == nullptr) return vectors;
  char* end = nullptr;
  const long value = std::strtol(limit, &end, 10);
  if (end == limit || *end != '\0' || value <= 0) {
    if (problem)
      *problem = "DRESSED_HUMAN_MAX_VERTEX_UNIFORM_VECTORS='" + std::string(limit) + "' is not a positive integer";
    return vectors;
  }
  return std::min(vectors, static_cast<std::size_t>(value));
}

std::string softwareRendererName() {
  const GLubyte* text = glGetString(GL_RENDERER);
  const std::string renderer = text ? reinterpret_cast<const char*>(text) : "";
  for (const char* software : {"llvmpipe", "softpipe", "swrast", "Software Rasterizer", "SwiftShader"}) {
    if (renderer.find(software) != std::string::npos) return renderer;
  }
  return "";
}

}  // namespace dressed_human
