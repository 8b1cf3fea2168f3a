#version 120
// Tangent-space bump mapping (Blinn 1978) on the Bezier surfaces: the tangent is dF/du from the
// patch derivatives, so the relief follows the cloth and skin as they move.
//
// Two builds of this file (dressed_human.material):
//  * the CPU evaluated the surface: each vertex brings position, normal, dF/du, its (u, v) and
//    relief weight; SHADING_ONLY (lit per vertex, the relief not drawn): position and normal only;
//  * EVALUATE_BEZIER: each vertex brings only (u, v, patch), the (u, v) it has in the patch of its
//    triangles (for the relief, patch_corner_split.h) and, on garments, its rest metric;
//    the vertex evaluates the bicubic Bezier patch (SPEC §2 Eq. 2-3) from the posed control
//    points and the wrinkle strength from the posed metric (wrinkle_placement.h,
//    VertexCompression) itself. The CPU then only poses 16 control points per patch per frame.

attribute vec4 vertex;              // Bezier: (u, v, patch index, 1)
attribute vec3 normal;
attribute vec3 tangent;
attribute vec4 uv0;                 // Bezier: the rest metric (a, b, c, det) of G_rest^-1 (garments)
attribute vec4 uv1;                 // x: how much of the relief shows here (wrinkles follow compression),
                                    // yz: which way garment folds run (their signed direction,
                                    // FoldCoordinates); Bezier: xy the vertex's (u, v) in the
                                    // patch of its triangles (patch_corner_split.h; `vertex` has
                                    // its owner patch's), or a garment's fold tile coordinate
attribute vec4 uv2;                 // Bezier garments with their wrinkles: xy the folds' signed
                                    // direction (FoldCoordinates); absent (0, 0) otherwise

uniform mat4 worldViewProj;
uniform vec4 lightPositionObject;   // w = 0 for rviz's directional light
uniform vec4 cameraPositionObject;

#ifdef VERTEX_LIGHTING
// A small human with its relief hidden: the plain lighting per vertex (the fragment program only
// passes it on), since its triangles are a few pixels at most.
uniform vec4 diffuseColour;
uniform vec4 ambientColour;
uniform float specularStrength;
varying vec4 litColour;
#endif

#ifdef EVALUATE_BEZIER
// P_ij of patch p at 16 p + 4 j + i (i along u). 192 patches: relief_material.h kMaxPatches.
uniform vec4 controlPoints[3072];
uniform float wrinkleWeighting;     // 1: garments, relief scaled by the compression; 0: skin
uniform float wrinkleInverseThreshold;
uniform float wrinkleInverseSaturation;
#endif

varying vec2 reliefUv;
varying float reliefWeight;
varying vec2 foldAxis;
varying vec3 lightTangent;
varying vec3 viewTangent;
varying vec3 lightObject;
varying vec3 viewObject;
varying vec3 normalObject;

#ifdef EVALUATE_BEZIER
void bernstein(float t, out vec4 value, out vec4 derivative) {
  float s = 1.0 - t;
  value = vec4(s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t);
  derivative = vec4(-3.0 * s * s, 3.0 * s * s - 6.0 * t * s, 6.0 * t * s - 3.0 * t * t, 3.0 * t * t);
}

vec3 row(int first, vec4 w) {
  return w.x * controlPoints[first].xyz + w.y * controlPoints[first + 1].xyz + w.z * controlPoints[first + 2].xyz +
         w.w * controlPoints[first + 3].xyz;
}

void evaluatePatch(int base, vec2 uv, out vec3 position, out vec3 du, out vec3 dv) {
  vec4 bu, dbu, bv, dbv;
  bernstein(uv.x, bu, dbu);
  bernstein(uv.y, bv, dbv);
  vec3 r0 = row(base, bu), r1 = row(base + 4, bu), r2 = row(base + 8, bu), r3 = row(base + 12, bu);
  position = bv.x * r0 + bv.y * r1 + bv.z * r2 + bv.w * r3;
  dv = dbv.x * r0 + dbv.y * r1 + dbv.z * r2 + dbv.w * r3;
  du = bv.x * row(base, dbu) + bv.y * row(base + 4, dbu) + bv.z * row(base + 8, dbu) + bv.w * row(base + 12, dbu);
}

// vertexStretchAt (wrinkle_placement.cpp) transcribed: alpha = sqrt of the smaller eigenvalue of
// M = G_rest^-1 G_posed, strength from alpha by the threshold and saturation; the fold axis from
// the eigenvector of the larger eigenvalue, as a double angle scaled by the anisotropy.
float wrinkleStrength(vec4 inverse, vec3 du, vec3 dv, out vec2 axis) {
  float e = dot(du, du), f = dot(du, dv), g = dot(dv, dv);
  float m11 = inverse.x * e + inverse.y * f, m12 = inverse.x * f + inverse.y * g;
  float m21 = inverse.y * e + inverse.z * f, m22 = inverse.y * f + inverse.z * g;
  float half_difference = 0.5 * (m11 - m22);
  float lambda_max = 0.5 * (m11 + m22) + sqrt(max(0.0, half_difference * half_difference + m12 * m21));
  float det_posed = e * g - f * f;
  float lambda_min = max(0.0, inverse.w * det_posed / max(lambda_max, 1e-30));
  bool defined = inverse.w > 0.0 && det_posed > 1e-6 * e * g;
  float alpha = defined ? min(1.0, sqrt(lambda_min)) : 1.0;
  vec2 from_first = vec2(m12, lambda_max - m11), from_second = vec2(lambda_max - m22, m21);
  vec2 d = dot(from_first, from_first) >= dot(from_second, from_second) ? from_first : from_second;
  float length2 = dot(d, d), sum = lambda_max + lambda_min;
  axis = defined && length2 > 0.0 && sum > 0.0
             ? vec2(d.x * d.x - d.y * d.y, 2.0 * d.x * d.y) * ((lambda_max - lambda_min) / sum / length2)
             : vec2(0.0);
  float effective = min(1.0, alpha * wrinkleInverseThreshold);
  return min(1.0, sqrt(max(0.0, 1.0 - effective * effective)) * wrinkleInverseSaturation);
}
#endif

void main() {
#ifdef EVALUATE_BEZIER
  int base = 16 * int(vertex.z + 0.5);
  vec3 position, du, dv;
  evaluatePatch(base, vertex.xy, position, du, dv);
  vec3 n = cross(du, dv);
  if (dot(n, n) <= 1e-12 * dot(du, du) * dot(dv, dv) || dot(n, n) < 1e-24) {
    // A pole or degenerate corner: the normal's limit from inside the patch, approximated a
    // hair towards the patch centre (the CPU path computes the exact limit, BezierPatch).
    vec3 p_inside, du_inside, dv_inside;
    evaluatePatch(base, mix(vertex.xy, vec2(0.5), 1e-3), p_inside, du_inside, dv_inside);
    n = cross(du_inside, dv_inside);
  }
  n = normalize(n);
  vec3 tangent_u = du;
  reliefUv = uv1.xy;  // one relief tile per patch
  vec2 axis = vec2(0.0);
  reliefWeight = wrinkleWeighting > 0.5 ? wrinkleStrength(uv0, du, dv, axis) : 1.0;
  foldAxis = uv2.xy;  // the fold coordinates' direction; `axis` (the shader's own) is not signed
#elif defined(SHADING_ONLY)
  // Lit per vertex, without the relief: the vertices bring no tangent and no texture
  // coordinates (SurfaceMeshObject), and the lighting below needs the normal alone.
  vec3 position = vertex.xyz;
  vec3 n = normalize(normal);
  vec3 tangent_u = vec3(0.0);
  reliefUv = vec2(0.0);
  reliefWeight = 1.0;
  foldAxis = vec2(0.0);
#else
  vec3 position = vertex.xyz;
  vec3 n = normalize(normal);
  vec3 tangent_u = tangent;
  reliefUv = uv0.xy;
  reliefWeight = uv1.x;
  foldAxis = uv1.yz;
#endif
  gl_Position = worldViewProj * vec4(position, 1.0);

  // A collapsed patch edge (a pole) has dF/du = 0: pick any tangent orthogonal to the normal.
  vec3 t = tangent_u - dot(tangent_u, n) * n;
  if (dot(t, t) < 1e-12) t = abs(n.x) < 0.9 ? cross(n, vec3(1.0, 0.0, 0.0)) : cross(n, vec3(0.0, 1.0, 0.0));
  t = normalize(t);
  vec3 b = cross(n, t);
  mat3 objectToTangent = mat3(t.x, b.x, n.x, t.y, b.y, n.y, t.z, b.z, n.z);

  lightObject = lightPositionObject.xyz - position * lightPositionObject.w;
  viewObject = cameraPositionObject.xyz - position;
  normalObject = n;
  lightTangent = objectToTangent * lightObject;
  viewTangent = objectToTangent * viewObject;
#ifdef VERTEX_LIGHTING
  // relief_surface.frag's PLAIN_SURFACE lighting, in object space.
  vec3 l = normalize(lightObject);
  vec3 v = normalize(viewObject);
  vec3 lit_normal = dot(n, v) < 0.0 ? -n : n;  // the side facing the viewer (thin cloth)
  float lambert = max(dot(lit_normal, l), 0.0);
  float highlight = pow(max(dot(lit_normal, normalize(l + v)), 0.0), 32.0) * specularStrength;
  litColour = vec4(ambientColour.rgb * diffuseColour.rgb + lambert * diffuseColour.rgb + vec3(highlight),
                   diffuseColour.a);
#endif
}
