#version 120
#ifdef VERTEX_LIT
// The lighting came from the vertex program (relief_surface.vert, VERTEX_LIGHTING).
varying vec4 litColour;
void main() { gl_FragColor = litColour; }
#else
#ifdef ORIENTED_FOLDS
// Explicit gradients: each fetch's lookup differs from pixel to pixel where the blend changes
// orientation, so implicit derivatives would pick the wrong mip level there.
#extension GL_ARB_shader_texture_lod : require
#endif
// Lambert shading (SPEC Eq. 12) of the bump-mapped normal, plus a mild Blinn-Phong highlight.

// PLAIN_SURFACE: the geometric normal only (no relief map), for reliefs too small to see.
// ORIENTED_FOLDS: garments; the map holds two fold tiles, turned and blended per fragment
// (oriented_folds.h, whose orientedFolds() this transcribes and whose tests hold it).
// FOLD_COORDINATES: garments whose vertices bring fold coordinates (fold_coordinates.h): reliefUv
// is the tile coordinate, foldAxis the folds' signed direction (foldCoordinateRelief).
#ifndef PLAIN_SURFACE
uniform sampler2D normalMap;        // tangent-space normals, encoded n * 0.5 + 0.5 (ORIENTED_FOLDS:
                                    // and FOLD_COORDINATES: x, y of the I tile's, then of
                                    // the Y-Y tile's)
uniform float reliefStrength;       // 0: flat shading with the geometric normal
#endif
uniform vec4 diffuseColour;
uniform vec4 ambientColour;
uniform float specularStrength;

varying vec2 reliefUv;
varying float reliefWeight;
varying vec2 foldAxis;
varying vec3 lightTangent;
varying vec3 viewTangent;
varying vec3 lightObject;
varying vec3 viewObject;
varying vec3 normalObject;

#if defined(ORIENTED_FOLDS) || defined(FOLD_COORDINATES)
vec2 slopeOf(vec2 encoded_xy) {
  vec2 xy = encoded_xy * 2.0 - 1.0;
  return -xy / sqrt(max(1e-6, 1.0 - dot(xy, xy)));
}
#endif

#ifdef ORIENTED_FOLDS
// foldOrientations(): folds along (p, q), lookup scale k, at degrees from u.
const vec4 kOrientations[12] = vec4[12](
    vec4(1.0, 0.0, 3.0, 0.000000),
    vec4(3.0, 1.0, 1.0, 18.434949),
    vec4(3.0, 2.0, 1.0, 33.690068),
    vec4(1.0, 1.0, 2.0, 45.000000),
    vec4(2.0, 3.0, 1.0, 56.309932),
    vec4(1.0, 3.0, 1.0, 71.565051),
    vec4(0.0, 1.0, 3.0, 90.000000),
    vec4(-1.0, 3.0, 1.0, 108.434949),
    vec4(-2.0, 3.0, 1.0, 123.690068),
    vec4(-1.0, 1.0, 2.0, 135.000000),
    vec4(-3.0, 2.0, 1.0, 146.309932),
    vec4(-3.0, 1.0, 1.0, 161.565051));

// Orientation k's slope at patch coordinate uv: the I and Y-Y tiles blended by `strong`, looked
// up at k [[q, -p], [p, q]] uv and turned back.
vec2 orientedSlope(int k, vec2 uv, vec2 uv_dx, vec2 uv_dy, float strong) {
  vec4 o = kOrientations[k];
  mat2 lookup = o.z * mat2(o.y, o.x, -o.x, o.y);
  vec4 texel = texture2DGradARB(normalMap, lookup * uv, lookup * uv_dx, lookup * uv_dy);
  vec2 g = mix(slopeOf(texel.xy), slopeOf(texel.zw), strong);
  return vec2(o.y * g.x + o.x * g.y, o.y * g.y - o.x * g.x) / length(o.xy);
}
#endif

void main() {
#ifdef PLAIN_SURFACE
  vec3 n = vec3(0.0, 0.0, 1.0);
#elif defined(ORIENTED_FOLDS)
  // The two orientations either side of the folds' angle (foldOrientationBlend).
  vec2 axis = foldAxis + vec2(-0.02, 0.0);  // kFoldAxisBias
  float folds = 0.5 * degrees(atan(axis.y, axis.x));
  if (folds < 0.0) folds += 180.0;
  int first = 0;
  for (int i = 1; i < 12; ++i) {
    if (kOrientations[i].w <= folds) first = i;
  }
  int second = first == 11 ? 0 : first + 1;
  float t = smoothstep(kOrientations[first].w, first == 11 ? 180.0 : kOrientations[second].w, folds);
  float strong = smoothstep(0.4, 0.8, reliefWeight);  // strongPatternWeight
  vec2 uv_dx = dFdx(reliefUv), uv_dy = dFdy(reliefUv);
  vec2 slope = (1.0 - t) * orientedSlope(first, reliefUv, uv_dx, uv_dy, strong) +
               t * orientedSlope(second, reliefUv, uv_dx, uv_dy, strong);
  vec3 n = normalize(vec3(-slope * (reliefStrength * reliefWeight), 1.0));
#elif defined(FOLD_COORDINATES)
  // One lookup where the coordinates put it; the tile's x runs across the folds, its y along them.
  vec2 along = foldAxis / max(length(foldAxis), 1e-6);
  vec4 texel = texture2D(normalMap, reliefUv);  // continuous coordinates: the implicit mip level holds
  vec2 g = mix(slopeOf(texel.xy), slopeOf(texel.zw), smoothstep(0.4, 0.8, reliefWeight));  // strongPatternWeight
  vec2 slope = g.x * vec2(along.y, -along.x) + g.y * along;
  vec3 n = normalize(vec3(-slope * (reliefStrength * reliefWeight), 1.0));
#else
  vec3 relief = texture2D(normalMap, reliefUv).xyz * 2.0 - 1.0;
  vec3 n = normalize(vec3(relief.xy * (reliefStrength * reliefWeight), max(relief.z, 1e-3)));
#endif
  vec3 l = normalize(lightTangent);
  vec3 v = normalize(viewTangent);
  // Both sides of thin cloth are visible (skirt hems, sleeves): light the side facing the viewer.
  if (dot(normalize(normalObject), normalize(viewObject)) < 0.0) {
    n = vec3(-n.xy, -n.z);
  }
  float lambert = max(dot(n, l), 0.0);
  float highlight = pow(max(dot(n, normalize(l + v)), 0.0), 32.0) * specularStrength;
  gl_FragColor = vec4(ambientColour.rgb * diffuseColour.rgb + lambert * diffuseColour.rgb + vec3(highlight),
                      diffuseColour.a);
}
#endif
