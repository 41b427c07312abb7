#pragma once
// What the runs of a study on one mesh share: the element table of each element setting (the
// weight functions, quadrature and shape functions depend on the mesh and that setting only, not
// on the material, the formulation or the penalty) and the symbolic analyses of their
// factorizations (the pattern depends on the space and the Dirichlet sides only). A study task
// makes one for its mesh and passes it to each of its runs, which run one after another.
//
// Shared work is recorded as what it cost when it was made, so that every run's stage times
// still say what the run costs on its own (what the trade-off and the figures compare); the
// run's record names the stages it shared (SolveResult::shared_stages).
#include <memory>
#include <vector>

#include "core/element/ElementTable.hpp"
#include "core/solve/SymbolicAnalyses.hpp"

namespace vorodg {

class SharedMeshWork {
 public:
  explicit SharedMeshWork(const PolygonMesh& mesh) : mesh_(mesh) {}

  const PolygonMesh& mesh() const { return mesh_; }
  /// The table of this element setting (threads aside), built on the first request.
  /// `seconds` is what building it took; `reused` says whether an earlier run built it.
  const ElementTable& element_table(const ElementOptions& options, double& seconds, bool& reused);
  SymbolicAnalyses& analyses() { return analyses_; }

 private:
  struct Table {
    ElementOptions options;
    std::unique_ptr<ElementTable> table;
    double seconds = 0.0;
  };
  const PolygonMesh& mesh_;
  std::vector<Table> tables_;
  SymbolicAnalyses analyses_;
};

}  // namespace vorodg
