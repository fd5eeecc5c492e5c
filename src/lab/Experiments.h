#pragma once
// The lab's two experiments (mms lab completeness, mms lab passages): each runs its trials,
// then returns the files of its report (SVG plots, CSV, a Markdown summary) for the caller to
// write. Trials run in parallel; each has its own seed, so the files do not depend on the
// thread count.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace mms::lab {

struct LabOptions {
  uint64_t seed = 1;
  size_t trials = 0;  // 0: the experiment's default
  unsigned threads = 1;
  bool quick = false;  // a few small settings: a smoke run in seconds
  bool pacman = true;  // passages: also the Pacman proxy (two-robot planning)
  std::function<void(const std::string&)> progress;  // one line per finished step
};

struct LabFile {
  std::string name, content;
};

/// Theorem 3.3 measured: failure rate of MMS (two perpendicular families of affine subspaces)
/// and of OMPL's PRM against the number of samples, on a wall with a hole of clearance rho in
/// R^d, d = 2..6.
std::vector<LabFile> completenessLab(const LabOptions& options);

/// Section IV measured: PRM and MMS (lines and planes) through a flume and a tunnel of equal
/// volume as eps shrinks; the estimated k-clearance sequences of both; and a proxy of it on
/// the Pacman scene at rising tightness.
std::vector<LabFile> passagesLab(const LabOptions& options);

}  // namespace mms::lab
