#pragma once
// The small convergence study the command-line tests run: the beam on rcp meshes of the given
// sizes and realizations, CG and dg-nitsche at k_p 100 and 1000 (three runs per mesh).
#include <sstream>
#include <string>
#include <vector>

namespace vorodg::testing {

inline std::string small_study_scene(const std::string& name, const std::vector<double>& sizes,
                                     int realizations, int seed) {
  std::ostringstream s;
  s << R"({"name": ")" << name << R"(", "description": "a small convergence study",)"
    << R"( "study": "convergence", "problems": ["beam"],)"
    << R"( "meshes": [{"family": "rcp", "sizes": [)";
  for (std::size_t i = 0; i < sizes.size(); ++i) s << (i ? ", " : "") << sizes[i];
  s << R"(], "realizations": )" << realizations << R"(, "seed": )" << seed << "}],"
    << R"( "formulations": [{"name": "cg"}, {"name": "dg-nitsche", "kp": [100, 1000]}]})";
  return s.str();
}

}  // namespace vorodg::testing
