#pragma once
// The result file of one solve (.vtu): displacement, exact displacement and error at the
// points; per cell the mean stress, von Mises stress, error densities, cell id and largest
// interface gap. DG results give every cell its own copies of its vertices, so each cell's
// displacement is its own and ParaView shows the jumps between cells.
#include <string>

#include "core/io/VtuMesh.hpp"
#include "verification/solve/SolveRun.hpp"

namespace vorodg {

void write_result(const std::string& path, const PolygonMesh& mesh, const SolveResult& result,
                  const ExactSolution& exact, bool discontinuous, VtuEncoding encoding);

}  // namespace vorodg
