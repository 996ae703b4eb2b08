#pragma once
// Why an input path cannot be read as a file, in words a user can act on: "not found" is
// wrong for a symbolic link that loops or points nowhere, and a folder or a device is not
// missing either.

#include <filesystem>
#include <optional>
#include <string>

namespace systole {

/// nullopt when `file` is a regular file this process may read; else what is wrong, e.g.
/// "not found", "a symbolic link loop (a link that leads back to itself)", "a broken
/// symbolic link (to 'x.obj', which does not exist)", "a directory", "not a regular file
/// (a device, pipe or socket)", "not readable (Permission denied)".
std::optional<std::string> unreadable_file_reason(const std::filesystem::path& file);

}  // namespace systole
