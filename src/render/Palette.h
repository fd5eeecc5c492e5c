#pragma once
// One colour per robot, the same in the SVG pictures and the HTML viewer, readable on the light
// background and against the blue obstacles. Sixteen chosen by hand, then as many as a fleet
// has, generated: no colour repeats (tested on the first 2000), and the first 64 keep as far
// apart as the hand-chosen sixteen.
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>

namespace mms {

inline constexpr std::array<const char*, 16> kRobotColours = {
    "#e8710a", "#7b1fa2", "#00838f", "#c62828", "#2e7d32", "#f9a825", "#6d4c41", "#d81b60",
    "#1565c0", "#9e9d24", "#5e35b1", "#00695c", "#ef6c00", "#4e342e", "#ad1457", "#37474f"};

/// "#rrggbb" of robot `robot`. Past the sixteen, hue and lightness follow the two-dimensional
/// golden-ratio (R2) sequence, whose points spread evenly however many are taken: hue over the
/// whole circle, lightness 0.28-0.62 (dark enough for white, light enough against the blue),
/// saturation 0.8.
inline std::string robotColour(size_t robot) {
  if (robot < kRobotColours.size()) return kRobotColours[robot];
  const double j = double(robot - kRobotColours.size() + 1);
  const double hue = std::fmod(0.5 + j * 0.7548776662466927, 1.0);
  const double light = 0.28 + 0.34 * std::fmod(0.5 + j * 0.5698402909980532, 1.0), sat = 0.8;
  // HSL to RGB.
  const double q = light < 0.5 ? light * (1 + sat) : light + sat - light * sat, p = 2 * light - q;
  auto channel = [&](double t) {
    t -= std::floor(t);
    const double v = t < 1.0 / 6   ? p + (q - p) * 6 * t
                     : t < 0.5     ? q
                     : t < 2.0 / 3 ? p + (q - p) * (2.0 / 3 - t) * 6
                                   : p;
    return int(std::lround(255 * v));
  };
  char hex[8];
  std::snprintf(hex, sizeof hex, "#%02x%02x%02x", channel(hue + 1.0 / 3), channel(hue),
                channel(hue - 1.0 / 3));
  return hex;
}

}  // namespace mms
