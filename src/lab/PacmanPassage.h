#pragma once
// A sampled proxy of the k-clearance (Definition 4.2) on the paper's Pacman scene, whose
// passage the paper argues is four-dimensional in the six-dimensional C-space: plan with MMS,
// find the path's configuration of least clearance, move it within the path's normal
// hyperplane to the widest point nearby (the passage's cross-section), and estimate there the
// largest k-disk for k = 6..1. Coordinates (x, y, theta * radius) per robot, so every
// coordinate moves robot points by about as much.
#include <cstdint>
#include <vector>

#include "lab/KClearance.h"
#include "mms/Scene.h"

namespace mms::lab {

struct PacmanPassageSettings {
  uint64_t seed = 1;
  double timeLimit = 60;     // for planning
  size_t pathSamples = 120;  // configurations scanned along the path
  size_t climbSteps = 40;    // random steps in the normal hyperplane
  double climbRadius = 0.3;  // how far (scene units) the climb may move the configuration
  double cap = 0;            // longest ray; 0: half the larger robot's radius
  DiskSearch disk;
};

struct PacmanPassage {
  bool found = false;
  double planSeconds = 0;
  Config tightest;               // (x, y, theta) per robot, after the climb
  std::vector<double> sequence;  // k = 6, 5, ..., 1
};

PacmanPassage measurePacmanPassage(double tightness, const PacmanPassageSettings& settings);

}  // namespace mms::lab
