#include "util/AtomicFile.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "mms/Errors.h"

namespace mms {

namespace {

namespace fs = std::filesystem;

int dataDescriptor = STDOUT_FILENO;  // where "-" writes (keepStandardOutputForData)

[[noreturn]] void failWriting(const std::string& path, const char* what, int error) {
  throw InputError(path + ": (output): cannot " + what + ": " + std::strerror(error));
}

// Writes all of `content` to an open descriptor; false with errno set when it cannot.
bool writeAll(int fd, const std::string& content) {
  for (size_t done = 0; done < content.size();) {
    const ssize_t n = ::write(fd, content.data() + done, content.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += size_t(n);
  }
  return true;
}

// The paths a chain of symbolic links passes through, `path` first and the file it ends at
// (which need not exist yet) last: writing replaces the file the user means and keeps the link.
std::vector<fs::path> linkChain(const std::string& path) {
  std::vector<fs::path> chain{path};
  for (;;) {
    const fs::path& p = chain.back();
    std::error_code ec;
    if (!fs::is_symlink(fs::symlink_status(p, ec))) return chain;
    if (chain.size() > 40) throw InputError(path + ": (output): too many levels of symbolic links");
    const fs::path to = fs::read_symlink(p, ec);
    if (ec) throw InputError(path + ": (output): cannot read the link: " + ec.message());
    chain.push_back(to.is_absolute() ? to : p.parent_path() / to);
  }
}

// A path that names something that is not a regular file (a pipe, a terminal, a device), or
// an open descriptor (/dev/stdout, /proc/self/fd/1): written directly, appending as a write to
// that descriptor would, since replacing it would cut the descriptor off (a log opened with
// >> would lose what it held).
bool namesStream(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0 || S_ISDIR(st.st_mode)) return false;
  if (!S_ISREG(st.st_mode)) return true;
  for (const fs::path& p : linkChain(path))
    if (p.string().rfind("/proc/", 0) == 0 || p.string().rfind("/dev/fd/", 0) == 0) return true;
  return false;
}

void writeDirectly(const std::string& path, const std::string& content) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
  if (fd < 0) failWriting(path, "open", errno);
  const bool written = writeAll(fd, content);
  const int error = errno;
  if (::close(fd) != 0 || !written) failWriting(path, "write", written ? errno : error);
}

}  // namespace

void keepStandardOutputForData() {
  std::fflush(stdout);
  const int saved = ::fcntl(STDOUT_FILENO, F_DUPFD_CLOEXEC, 3);
  if (saved < 0 || ::dup2(STDERR_FILENO, STDOUT_FILENO) < 0)
    throw InputError(std::string("-: (output): cannot keep standard output: ") +
                     std::strerror(errno));
  dataDescriptor = saved;
}

void writeFileAtomically(const std::string& path, const std::string& content) {
  if (path == kStandardOutput) {
    std::fflush(stdout);
    if (!writeAll(dataDescriptor, content)) failWriting("-", "write standard output", errno);
    return;
  }
  if (namesStream(path)) return writeDirectly(path, content);
  const fs::path target = linkChain(path).back();
  const std::string tmp = target.string() + ".tmp." + std::to_string(::getpid());
  auto fail = [&](const char* what) {
    const int error = errno;
    std::remove(tmp.c_str());
    failWriting(path, what, error);
  };
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) fail("create");
  // A file written again keeps its permissions.
  struct stat old {};
  if (::stat(target.c_str(), &old) == 0) (void)::fchmod(fd, old.st_mode & 07777);
  const bool written = writeAll(fd, content);
  if (::close(fd) != 0 || !written) fail("write");
  if (std::rename(tmp.c_str(), target.c_str()) != 0) fail("rename into place");
}

void checkWritable(const std::string& path, const std::string& option) {
  if (path.empty() || path == kStandardOutput) return;
  auto fail = [&](const std::string& why) {
    throw InputError(path + ": (" + option + "): cannot write here: " + why);
  };
  std::error_code ec;
  if (fs::is_directory(path, ec)) fail("it is a folder");
  if (namesStream(path)) {
    if (::access(path.c_str(), W_OK) != 0) fail(std::strerror(errno));
    return;
  }
  const fs::path p = linkChain(path).back();
  const fs::path folder = p.parent_path().empty() ? "." : p.parent_path();
  if (!fs::exists(folder, ec)) fail("folder " + folder.string() + " does not exist");
  if (!fs::is_directory(folder, ec)) fail(folder.string() + " is not a folder");
  if (::access(folder.c_str(), W_OK) != 0) fail("folder " + folder.string() + " is not writable");
}

}  // namespace mms
