// mms lab: the paper's theory measured (docs/theory.md).
#include <cstdio>
#include <filesystem>
#include <system_error>

#include "Commands.h"
#include "lab/Experiments.h"
#include "mms/Errors.h"
#include "mms/Termination.h"
#include "util/AtomicFile.h"
#include "util/Parallel.h"

namespace mms::cli {

int lab(const LabArgs& a) {
  std::error_code ec;
  std::filesystem::create_directories(a.output, ec);
  if (ec || !std::filesystem::is_directory(a.output))
    throw InputError(a.output + ": (--output): cannot create the folder" +
                     (ec ? ": " + ec.message() : ""));
  lab::LabOptions o;
  o.seed = a.seed;
  o.trials = a.trials;
  o.threads = a.threads ? a.threads : hardwareThreads();
  o.quick = a.quick;
  o.pacman = !a.noPacman;
  Stopwatch clock;
  if (!a.quiet)
    o.progress = [&](const std::string& line) {
      std::fprintf(stderr, "mms lab: %.1f s: %s\n", clock.seconds(), line.c_str());
    };
  // Everything is computed before anything is written: an interrupted run leaves the old
  // report whole.
  const std::vector<lab::LabFile> files =
      a.experiment == "completeness" ? lab::completenessLab(o) : lab::passagesLab(o);
  for (const lab::LabFile& f : files)
    writeFileAtomically((std::filesystem::path(a.output) / f.name).string(), f.content);
  if (!a.quiet) {
    std::printf("mms lab %s: %zu files in %s (%.1f s)\n", a.experiment.c_str(), files.size(),
                a.output.c_str(), clock.seconds());
    for (const lab::LabFile& f : files) std::printf("  %s\n", f.name.c_str());
  }
  return 0;
}

}  // namespace mms::cli
