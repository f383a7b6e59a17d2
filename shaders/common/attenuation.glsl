// Point-light falloff: inverse-square times a smooth window that is exactly zero
// at the light's radius. Twin of src/render/lighting/light_falloff.cpp; the two
// are compared by tests/render/lighting/light_falloff_test.cpp.
const float kMinLightDistance = 0.01;

float light_attenuation(float distance, float radius) {
  if (!(radius > 0.0)) return 0.0;
  float d = max(distance, kMinLightDistance);
  float ratio = distance / radius;
  float ratio4 = ratio * ratio * ratio * ratio;
  float window = clamp(1.0 - ratio4, 0.0, 1.0);
  return window * window / (d * d);
}
