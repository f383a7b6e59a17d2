// Phases spread by the golden angle, so that the k-th of many moving things
// (animated lights, say) is out of step with its neighbours. Kept within
// [0, 2 pi): a float holding k times the angle would, past a few ten
// thousand, be too coarse for a frame's step, and the thing would jump.
#pragma once

#include <cmath>
#include <cstdint>

#include <glm/gtc/constants.hpp>

namespace atrium {

inline constexpr double kGoldenAngle = 2.39996322972865332;  // radians: pi (3 - sqrt 5)

[[nodiscard]] inline float golden_angle_phase(std::uint64_t k) {
  return static_cast<float>(std::fmod(kGoldenAngle * static_cast<double>(k), glm::two_pi<double>()));
}

}  // namespace atrium
