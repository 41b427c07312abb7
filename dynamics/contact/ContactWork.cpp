#include "dynamics/contact/ContactWork.hpp"

#include <string>

#include "core/util/Errors.hpp"

namespace vorodg {

void ContactWork::add(std::span<const Point> x, std::span<const Point> f) {
  if (x.size() != f.size() || (started_ && x.size() != x_.size()))
    throw InputError("contact work: " + std::to_string(x.size()) + " positions and " +
                     std::to_string(f.size()) + " forces: expected " +
                     std::to_string(started_ ? x_.size() : x.size()) + " of each");
  if (started_) {
    double step = 0.0;  // in pair order: the same sum on every run
    for (std::size_t p = 0; p < x.size(); ++p) step += 0.5 * (f_[p] + f[p]).dot(x[p] - x_[p]);
    work_ += step;
  }
  x_.assign(x.begin(), x.end());
  f_.assign(f.begin(), f.end());
  started_ = true;
}

}  // namespace vorodg
