#version 120
// Lambert shading (SPEC Eq. 12) of the bump-mapped normal, plus a mild Blinn-Phong highlight.

// PLAIN_SURFACE: the geometric normal only (no relief map), for reliefs too small to see.
#ifndef PLAIN_SURFACE
uniform sampler2D normalMap;        // tangent-space normals, encoded n * 0.5 + 0.5
uniform float reliefStrength;       // 0: flat shading with the geometric normal
#endif
uniform vec4 diffuseColour;
uniform vec4 ambientColour;
uniform float specularStrength;

varying vec2 reliefUv;
varying float reliefWeight;
varying vec3 lightTangent;
varying vec3 viewTangent;
varying vec3 lightObject;
varying vec3 viewObject;
varying vec3 normalObject;

void main() {
#ifdef PLAIN_SURFACE
  vec3 n = vec3(0.0, 0.0, 1.0);
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
