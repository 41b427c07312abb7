#include "core/solve/SymbolicAnalyses.hpp"

#include <cholmod.h>

#include <algorithm>

namespace vorodg {

struct SymbolicAnalyses::Entry {
  long settings = 0;
  long rows = 0;
  std::vector<int> outer, inner;  // the lower pattern, compressed columns
  cholmod_factor* factor = nullptr;
  double seconds = 0.0;

  bool matches(const Eigen::SparseMatrix<double>& lower, long key) const {
    const int* o = lower.outerIndexPtr();
    const int* i = lower.innerIndexPtr();
    return key == settings && lower.rows() == rows &&
           static_cast<std::size_t>(lower.cols()) + 1 == outer.size() &&
           static_cast<std::size_t>(lower.nonZeros()) == inner.size() &&
           std::equal(outer.begin(), outer.end(), o) && std::equal(inner.begin(), inner.end(), i);
  }
};

struct SymbolicAnalyses::Impl {
  cholmod_common common{};
  std::vector<Entry> entries;
  Impl() {
    cholmod_start(&common);
    common.print = 0;
  }
  ~Impl() {
    for (Entry& e : entries) cholmod_free_factor(&e.factor, &common);
    cholmod_finish(&common);
  }
};

SymbolicAnalyses::SymbolicAnalyses() : impl_(std::make_unique<Impl>()) {}
SymbolicAnalyses::~SymbolicAnalyses() = default;

cholmod_factor* SymbolicAnalyses::copy(const Eigen::SparseMatrix<double>& lower, long settings,
                                       cholmod_common* common, double& seconds) const {
  const std::lock_guard<std::mutex> lock(mutex_);
  for (const Entry& e : impl_->entries)
    if (e.matches(lower, settings)) {
      seconds = e.seconds;
      return cholmod_copy_factor(e.factor, common);
    }
  return nullptr;
}

void SymbolicAnalyses::keep(const Eigen::SparseMatrix<double>& lower, long settings,
                            const cholmod_factor* factor, double seconds) {
  const std::lock_guard<std::mutex> lock(mutex_);
  Entry e;
  e.settings = settings;
  e.seconds = seconds;
  e.rows = lower.rows();
  e.outer.assign(lower.outerIndexPtr(), lower.outerIndexPtr() + lower.cols() + 1);
  e.inner.assign(lower.innerIndexPtr(), lower.innerIndexPtr() + lower.nonZeros());
  e.factor = cholmod_copy_factor(const_cast<cholmod_factor*>(factor), &impl_->common);
  if (e.factor) impl_->entries.push_back(std::move(e));  // out of memory: simply not kept
}

int SymbolicAnalyses::size() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return static_cast<int>(impl_->entries.size());
}

}  // namespace vorodg
