#version 120
#ifdef VERTEX_LIT
// The lighting came from the vertex program (relief_surface.vert, VERTEX_LIGHTING).
varying vec4 litColour;
void main() { gl_FragColor = litColour; }
#else
// Lambert shading (SPEC Eq. 12) of the bump-mapped normal, plus a mild Blinn-Phong highlight.

// PLAIN_SURFACE: the geometric normal only (no relief map), for reliefs too small to see.
// FOLD_COORDINATES: garments, whose vertices bring fold coordinates (fold_coordinates.h): reliefUv
// is the tile coordinate, foldAxis the folds' signed direction; the map holds the two fold tiles
// (oriented_folds.h, whose foldCoordinateRelief() this transcribes and whose tests hold it).
#ifndef PLAIN_SURFACE
uniform sampler2D normalMap;        // tangent-space normals, encoded n * 0.5 + 0.5 (FOLD_COORDINATES:
                                    // x, y of the I tile's, then of the Y-Y tile's)
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

#ifdef FOLD_COORDINATES
vec2 slopeOf(vec2 encoded_xy) {
  vec2 xy = encoded_xy * 2.0 - 1.0;
  return -xy / sqrt(max(1e-6, 1.0 - dot(xy, xy)));
}
#endif

void main() {
#ifdef PLAIN_SURFACE
  vec3 n = vec3(0.0, 0.0, 1.0);
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
