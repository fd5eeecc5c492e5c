#pragma once
#include <string>

namespace mms {

/// Writes `content` to a temporary file beside `path` and renames it into place, so readers
/// never see a partial file and a failed or interrupted run leaves none behind. Throws
/// InputError naming the file when it cannot be written.
void writeFileAtomically(const std::string& path, const std::string& content);

}  // namespace mms
