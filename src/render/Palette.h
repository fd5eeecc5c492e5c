#pragma once
// One colour per robot, the same in the SVG pictures and the HTML viewer: distinct for up to 16
// robots (a scene holds at most 16), readable on the light background and against the blue
// obstacles.
#include <array>
#include <cstddef>

namespace mms {

inline constexpr std::array<const char*, 16> kRobotColours = {
    "#e8710a", "#7b1fa2", "#00838f", "#c62828", "#2e7d32", "#f9a825", "#6d4c41", "#d81b60",
    "#1565c0", "#9e9d24", "#5e35b1", "#00695c", "#ef6c00", "#4e342e", "#ad1457", "#37474f"};

inline const char* robotColour(size_t robot) { return kRobotColours[robot % kRobotColours.size()]; }

}  // namespace mms
