#include "common/input_file.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace systole {

std::optional<std::string> unreadable_file_reason(const std::filesystem::path& file) {
  struct stat info {};
  if (::stat(file.c_str(), &info) != 0) {
    const int error = errno;
    if (error == ELOOP) return "a symbolic link loop (a link that leads back to itself); point it at the real file";
    if (error == ENOENT || error == ENOTDIR) {
      std::error_code ec;
      if (std::filesystem::is_symlink(file, ec)) {
        return "a broken symbolic link (to '" + std::filesystem::read_symlink(file, ec).string() +
               "', which does not exist)";
      }
      return std::string("not found");
    }
    if (error == EACCES) return "not reachable (a folder on the way is not searchable: " + std::string(std::strerror(error)) + ")";
    if (error == ENAMETOOLONG) return std::string("a path too long for this system");
    return "not readable (" + std::string(std::strerror(error)) + ")";
  }
  if (S_ISDIR(info.st_mode)) return std::string("a directory, not a file");
  if (!S_ISREG(info.st_mode)) return std::string("not a regular file (a device, pipe or socket would never end)");
  if (::access(file.c_str(), R_OK) != 0) return "not readable (" + std::string(std::strerror(errno)) + ")";
  return std::nullopt;
}

}  // namespace systole
