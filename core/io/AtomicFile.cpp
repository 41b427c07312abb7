#include "core/io/AtomicFile.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "core/util/Errors.hpp"

namespace vorodg {

void write_file_atomically(const std::filesystem::path& path, const std::string& contents) {
  namespace fs = std::filesystem;
  const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(folder, ec))
    throw InputError("output '" + path.string() + "': folder '" + folder.string() +
                     "' does not exist");
  // Unique per process so that parallel writers of different files never collide.
  const fs::path temp = path.string() + ".tmp." + std::to_string(::getpid());
  {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    if (!out)
      throw InputError("output '" + path.string() + "': cannot write in '" + folder.string() +
                       "' (" + std::strerror(errno) + ")");
    out.write(contents.data(), static_cast<std::streamsize>(contents.size()));
    out.flush();
    if (!out) {
      fs::remove(temp, ec);
      throw InputError("output '" + path.string() + "': write failed (disk full?)");
    }
  }
  fs::rename(temp, path, ec);
  if (ec) {
    fs::remove(temp, ec);
    throw InputError("output '" + path.string() + "': cannot rename the finished file into place");
  }
}

std::string read_file(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError("input '" + path.string() + "': is a folder, expected a file");
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InputError("input '" + path.string() + "': cannot open (" + std::strerror(errno) + ")");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace vorodg
