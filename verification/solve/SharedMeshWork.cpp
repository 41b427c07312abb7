#include "verification/solve/SharedMeshWork.hpp"

#include "core/util/Stopwatch.hpp"

namespace vorodg {
namespace {

/// Whether two settings give the same table (the thread count does not change it).
bool same_table(ElementOptions a, const ElementOptions& b) {
  a.threads = b.threads;
  return a == b;
}

}  // namespace

const ElementTable& SharedMeshWork::element_table(const ElementOptions& options, double& seconds,
                                                  bool& reused) {
  for (const Table& t : tables_)
    if (same_table(t.options, options)) {
      seconds = t.seconds;
      reused = true;
      return *t.table;
    }
  Stopwatch clock;
  auto table = std::make_unique<ElementTable>(mesh_, options);
  seconds = clock.seconds();
  reused = false;
  tables_.push_back({options, std::move(table), seconds});
  return *tables_.back().table;
}

}  // namespace vorodg
