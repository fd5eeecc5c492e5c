// mms bench and mms bench-merge: the command line over the library's benchmark runner.
#include <cstdio>
#include <filesystem>

#include "Commands.h"
#include "bench/Runner.h"
#include "util/Interrupt.h"

namespace mms::cli {

namespace {

std::string selfExe() {
  std::error_code ec;
  const std::filesystem::path p = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) throw std::runtime_error("cannot find the mms executable: " + ec.message());
  return p.string();
}

}  // namespace

int bench(const BenchArgs& a) {
  if (a.reportOnly) {
    std::filesystem::create_directories(a.output);
    writeBenchReports(a.output);
    std::printf("%s: reports written\n", a.output.c_str());
    return 0;
  }
  BenchSettings s = a;
  s.executable = selfExe();
  const BenchOutcome o = runBenchmark(s, sigintFlag());
  if (o.interrupted) {
    std::fprintf(stderr, "mms bench: interrupted; %zu runs recorded in %s (run again to resume)\n",
                 o.finished, o.runsFile.c_str());
    return 130;
  }
  std::printf("%s: %zu runs (%zu already recorded", a.output.c_str(), o.finished, o.skipped);
  if (o.notRun) std::printf(", %zu not run: their median was decided", o.notRun);
  std::printf("); report in %s/report.md\n", a.output.c_str());
  return 0;
}

int benchMerge(const std::vector<std::string>& dirs, const std::string& output) {
  const size_t n = mergeBenchmarks(dirs, output);
  std::printf("%s: merged %zu runs from %zu folders\n", output.c_str(), n, dirs.size());
  return 0;
}

}  // namespace mms::cli
