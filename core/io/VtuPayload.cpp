#include "core/io/VtuPayload.hpp"

#include <algorithm>

#include "core/util/Errors.hpp"

namespace vorodg {

void VtuPayload::read(std::size_t n, std::string& out, const char* what) {
  std::size_t got = 0;
  if (is_base64_) {
    got = base64_.read(n, out);
    if (got < n && !base64_.error().empty()) throw InputError(base64_.error());
  } else {
    got = std::min(n, data_.size() - pos_);
    out.append(data_.substr(pos_, got));
    pos_ += got;
  }
  if (got < n)
    throw InputError(std::string(what) + " is cut short (" + std::to_string(got) + " of " +
                     std::to_string(n) + " bytes)");
}

std::uint64_t VtuPayload::word(int bytes, bool big_endian, const char* what) {
  std::string b;
  read(static_cast<std::size_t>(bytes), b, what);
  std::uint64_t v = 0;
  for (int i = 0; i < bytes; ++i) {
    const int k = big_endian ? i : bytes - 1 - i;
    v = (v << 8) | static_cast<unsigned char>(b[k]);
  }
  return v;
}

std::size_t VtuPayload::max_bytes_left() const {
  return is_base64_ ? base64_.max_bytes_left() : data_.size() - pos_;
}

}  // namespace vorodg
