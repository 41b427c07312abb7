#pragma once
// Base64 (RFC 4648, with '=' padding) as VTK XML files use it for binary data arrays. The decoder
// reads a stream of concatenated, separately padded groups: VTK and meshio encode a compressed
// array's header and its data one after the other, each with its own padding.
#include <cstddef>
#include <string>
#include <string_view>

namespace vorodg {

/// Appends the base64 encoding of `bytes` to `out`.
void base64_append(std::string_view bytes, std::string& out);

/// Reads base64 text front to back, skipping whitespace, on demand.
class Base64Decoder {
 public:
  explicit Base64Decoder(std::string_view text) : text_(text) {}

  /// Appends up to `n` decoded bytes to `out`; returns how many. Fewer than `n` means the text
  /// ended or is not base64; then error() says which (empty: it just ended).
  std::size_t read(std::size_t n, std::string& out);
  /// An upper bound of the bytes still to come (for checking sizes before allocating).
  std::size_t max_bytes_left() const { return (text_.size() - pos_) / 4 * 3 + (len_ - next_); }
  const std::string& error() const { return error_; }

 private:
  /// Decodes the next group of four characters into group_; false at the end or on bad text.
  bool next_group();

  std::string_view text_;
  std::size_t pos_ = 0;
  unsigned char group_[3] = {0, 0, 0};
  int len_ = 0, next_ = 0;
  std::string error_;
};

}  // namespace vorodg
