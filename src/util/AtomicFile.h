#pragma once
#include <string>

namespace mms {

/// Writes `content` to a temporary file beside `path` and renames it into place, so readers
/// never see a partial file and a failed or interrupted run leaves none behind. Throws
/// InputError naming the file when it cannot be written.
void writeFileAtomically(const std::string& path, const std::string& content);

/// Throws the InputError writeFileAtomically would throw for `path` (its folder missing, not a
/// folder or not writable; `path` itself a folder), before any work: a long run must not end
/// by losing its result. `option` names the option in the message, e.g. "-o".
void checkWritable(const std::string& path, const std::string& option);

}  // namespace mms
