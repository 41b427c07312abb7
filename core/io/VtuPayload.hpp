#pragma once
// The bytes of one binary VTK data array, read front to back: raw bytes (appended raw data) or
// base64 text (format="binary", appended base64 data). Errors are InputErrors with a bare message
// ("the array data is cut short (12 of 16 bytes)"); the caller prefixes the file and the array.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "core/io/Base64.hpp"

namespace vorodg {

class VtuPayload {
 public:
  static VtuPayload raw(std::string_view bytes) { return VtuPayload(bytes, false); }
  static VtuPayload base64(std::string_view text) { return VtuPayload(text, true); }

  /// Appends exactly `n` bytes to `out`; throws InputError if the data ends first or is bad.
  void read(std::size_t n, std::string& out, const char* what);
  /// One header word: `bytes` (4 or 8) little- or big-endian bytes as an unsigned integer.
  std::uint64_t word(int bytes, bool big_endian, const char* what);
  /// An upper bound of the bytes left, to check sizes from a header before allocating.
  std::size_t max_bytes_left() const;

 private:
  VtuPayload(std::string_view data, bool base64) : data_(data), base64_(data), is_base64_(base64) {}

  std::string_view data_;
  std::size_t pos_ = 0;
  Base64Decoder base64_;
  bool is_base64_;
};

}  // namespace vorodg
