// Atomic replacement of output files: write to a temporary in the same
// directory, then rename over the target. rename() within one file system is
// atomic on POSIX, so a reader (or an interrupted run) sees either the old
// complete file or the new complete file, never a partial one.
#pragma once

#include <filesystem>
#include <functional>
#include <string_view>

namespace rkpm::io {

// The temporary name used for `target`: same directory, so the rename never
// crosses file systems. Tests use it to check nothing is left behind.
std::filesystem::path temporary_path_for(const std::filesystem::path& target);

// Calls write_to(temporary) and renames the result onto `target`. If write_to
// throws, the temporary is removed and the exception propagates; `target` is
// untouched.
void replace_atomically(const std::filesystem::path& target,
                        const std::function<void(const std::filesystem::path&)>& write_to);

// Text convenience over replace_atomically. Throws std::runtime_error naming
// the file when it cannot be written.
void write_text_atomically(const std::filesystem::path& target, std::string_view text);

}  // namespace rkpm::io
