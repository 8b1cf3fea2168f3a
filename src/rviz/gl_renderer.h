#pragma once
// What the GL renderer behind rviz can do, asked of the GL itself (rviz's context is current on
// its thread): how many vertex-shader uniform vectors it offers, and whether it rasterizes on the
// CPU.

#include <cstddef>
#include <string>

namespace dressed_human {

// The vertex shader's uniform vectors: the GL's own figure (Ogre 1.9+ reports a fixed 2048
// registers for GLSL), Ogre's if the GL gives none, at most DRESSED_HUMAN_MAX_VERTEX_UNIFORM_VECTORS
// if that is set (to see this GPU behave like a smaller one, or keep a driver that misreports its
// limit off the Bezier shader). A malformed setting is ignored with `problem` saying so.
std::size_t vertexUniformVectors(std::string* problem);

// The GL renderer's name if it rasterizes on the CPU (Mesa llvmpipe, softpipe, swrast), else empty.
std::string softwareRendererName();

}  // namespace dressed_human
