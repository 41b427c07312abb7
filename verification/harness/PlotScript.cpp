#include "verification/harness/PlotScript.hpp"

#include <cstdlib>
#include <iostream>

namespace vorodg {

bool draw_plots(const std::string& script, const std::filesystem::path& out) {
  namespace fs = std::filesystem;
  const fs::path path = fs::path(VORODG_SOURCE_DIR) / "scripts" / script;
  // Debian's interpreter first: another python3 earlier on PATH may lack matplotlib.
  const char* python = fs::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
  const std::string cmd =
      std::string(python) + " '" + path.string() + "' '" + out.string() + "' >/dev/null";
  if (fs::exists(path) && std::system(cmd.c_str()) == 0) return true;
  std::cerr << "note: the plots could not be drawn (" << cmd << ")\n";
  return false;
}

}  // namespace vorodg
