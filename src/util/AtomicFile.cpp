#include "util/AtomicFile.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>

#include "mms/Errors.h"

namespace mms {

void writeFileAtomically(const std::string& path, const std::string& content) {
  const std::string tmp = path + ".tmp." + std::to_string(::getpid());
  auto fail = [&](const char* what) {
    const std::string reason = std::strerror(errno);
    std::remove(tmp.c_str());
    throw InputError(path + ": (output): cannot " + what + ": " + reason);
  };
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) fail("create");
  const bool written = std::fwrite(content.data(), 1, content.size(), f) == content.size();
  if (std::fclose(f) != 0 || !written) fail("write");
  if (std::rename(tmp.c_str(), path.c_str()) != 0) fail("rename into place");
}

void checkWritable(const std::string& path, const std::string& option) {
  if (path.empty()) return;
  const std::filesystem::path p(path);
  const std::filesystem::path folder = p.parent_path().empty() ? "." : p.parent_path();
  std::error_code ec;
  auto fail = [&](const std::string& why) {
    throw InputError(path + ": (" + option + "): cannot write here: " + why);
  };
  if (!std::filesystem::exists(folder, ec)) fail("folder " + folder.string() + " does not exist");
  if (!std::filesystem::is_directory(folder, ec)) fail(folder.string() + " is not a folder");
  if (std::filesystem::is_directory(p, ec)) fail("it is a folder");
  if (::access(folder.c_str(), W_OK) != 0) fail("folder " + folder.string() + " is not writable");
}

}  // namespace mms
