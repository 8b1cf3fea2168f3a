#version 120
// Tangent-space bump mapping (Blinn 1978) on the Bezier surfaces: the tangent is dF/du from the
// patch derivatives, so the relief follows the cloth and skin as they move.

attribute vec4 vertex;
attribute vec3 normal;
attribute vec3 tangent;
attribute vec4 uv0;
attribute vec4 uv1;                 // x: how much of the relief shows here (wrinkles follow compression)

uniform mat4 worldViewProj;
uniform vec4 lightPositionObject;   // w = 0 for rviz's directional light
uniform vec4 cameraPositionObject;
uniform float reliefTiling;

varying vec2 reliefUv;
varying float reliefWeight;
varying vec3 lightTangent;
varying vec3 viewTangent;
varying vec3 lightObject;
varying vec3 viewObject;
varying vec3 normalObject;

void main() {
  gl_Position = worldViewProj * vertex;
  reliefUv = uv0.xy * reliefTiling;
  reliefWeight = uv1.x;

  vec3 n = normalize(normal);
  // A collapsed patch edge (a pole) has dF/du = 0: pick any tangent orthogonal to the normal.
  vec3 t = tangent - dot(tangent, n) * n;
  if (dot(t, t) < 1e-12) t = abs(n.x) < 0.9 ? cross(n, vec3(1.0, 0.0, 0.0)) : cross(n, vec3(0.0, 1.0, 0.0));
  t = normalize(t);
  vec3 b = cross(n, t);
  mat3 objectToTangent = mat3(t.x, b.x, n.x, t.y, b.y, n.y, t.z, b.z, n.z);

  lightObject = lightPositionObject.xyz - vertex.xyz * lightPositionObject.w;
  viewObject = cameraPositionObject.xyz - vertex.xyz;
  normalObject = n;
  lightTangent = objectToTangent * lightObject;
  viewTangent = objectToTangent * viewObject;
}
