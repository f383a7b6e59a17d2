// An independent CPU evaluation of the engine's shading, written from the
// formulas (not from the GLSL): Cook-Torrance with GGX, height-correlated Smith
// and Schlick, Lambert diffuse, ACES filmic tone mapping and sRGB encoding.
// Light falloff comes from the engine's one C++ definition.
#pragma once

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "render/lighting/light_falloff.hpp"

namespace atrium::testing {

struct ReferenceMaterial {
  glm::vec3 albedo;
  float metallic;
  float roughness;
};

// The response to one light, times N.L, as its diffuse and specular lobes' shares.
inline void reference_brdf_lobes(glm::vec3 n, glm::vec3 v, glm::vec3 l, const ReferenceMaterial& m, glm::vec3& diffuse,
                                 glm::vec3& specular) {
  constexpr double kPi = 3.14159265358979323846;
  diffuse = specular = glm::vec3(0.0f);
  const double n_dot_l = std::max(0.0, static_cast<double>(glm::dot(n, l)));
  if (n_dot_l <= 0.0) return;
  const glm::vec3 h = glm::normalize(v + l);
  const double n_dot_v = std::max(1e-4, static_cast<double>(glm::dot(n, v)));
  const double n_dot_h = std::max(0.0, static_cast<double>(glm::dot(n, h)));
  const double v_dot_h = std::max(0.0, static_cast<double>(glm::dot(v, h)));
  const double alpha = std::max(static_cast<double>(m.roughness) * m.roughness, 2e-3);
  const double a2 = alpha * alpha;
  const double denom = n_dot_h * n_dot_h * (a2 - 1.0) + 1.0;
  const double d = a2 / (kPi * denom * denom);
  const double vis = 0.5 / (n_dot_l * std::sqrt(n_dot_v * n_dot_v * (1.0 - a2) + a2) +
                            n_dot_v * std::sqrt(n_dot_l * n_dot_l * (1.0 - a2) + a2));
  for (int c = 0; c < 3; ++c) {
    const double f0 = 0.04 * (1.0 - m.metallic) + m.albedo[c] * m.metallic;
    const double f = f0 + (1.0 - f0) * std::pow(1.0 - v_dot_h, 5.0);
    diffuse[c] = static_cast<float>((1.0 - f) * (1.0 - m.metallic) * m.albedo[c] / kPi * n_dot_l);
    specular[c] = static_cast<float>(d * vis * f * n_dot_l);
  }
}

inline glm::vec3 reference_brdf(glm::vec3 n, glm::vec3 v, glm::vec3 l, const ReferenceMaterial& m) {
  glm::vec3 diffuse, specular;
  reference_brdf_lobes(n, v, l, m, diffuse, specular);
  return diffuse + specular;
}

inline double reference_tonemap_to_srgb(double x) {
  const double a = 2.51, b = 0.03, c = 2.43, d = 0.59, e = 0.14;
  double y = std::clamp((x * (a * x + b)) / (x * (c * x + d) + e), 0.0, 1.0);
  return y <= 0.0031308 ? 12.92 * y : 1.055 * std::pow(y, 1.0 / 2.4) - 0.055;
}

}  // namespace atrium::testing
