// dg-penalty: the interior penalty alone, a(u, v) + eps int [u].[v] = l(v), one solve. It adds
// nothing to what DgElasticity assembles for every scheme; inconsistent (the traction on an
// interface is not in the weak form), so it fails the patch test by O(1 / eps).
#include "dg/DgFormulation.hpp"

namespace vorodg {

namespace {
class PenaltyOnly final : public DgFormulation {};
}  // namespace

std::unique_ptr<DgFormulation> make_penalty_only(const DgOptions&) {
  return std::make_unique<PenaltyOnly>();
}

}  // namespace vorodg
