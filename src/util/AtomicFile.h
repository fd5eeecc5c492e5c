#pragma once
#include <string>

namespace mms {

/// The name that means standard output wherever a command writes one file ("-o -").
inline constexpr const char* kStandardOutput = "-";

/// Writes `content` to `path` so that readers never see a partial file and a failed or
/// interrupted run leaves none behind: into a temporary file beside the file `path` finally
/// names (symbolic links are followed, not replaced) and renamed into place. A `path` that
/// names no regular file (a pipe, a terminal, /dev/stdout) is written directly, and "-" is
/// standard output. Throws InputError naming the file when it cannot be written.
void writeFileAtomically(const std::string& path, const std::string& content);

/// Throws the InputError writeFileAtomically would throw for `path` (its folder missing, not a
/// folder or not writable; `path` itself a folder), before any work: a long run must not end
/// by losing its result. `option` names the option in the message, e.g. "-o".
void checkWritable(const std::string& path, const std::string& option);

/// From now on "-" writes to what standard output is now, and everything else printed on
/// standard output goes to standard error: a command whose file goes to standard output keeps
/// its report out of the data.
void keepStandardOutputForData();

}  // namespace mms
