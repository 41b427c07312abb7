#include "core/util/Digest.hpp"

#include <zlib.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iterator>

namespace vorodg {

Digest& Digest::add(const void* data, std::size_t bytes) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < bytes; ++i) h_ = (h_ ^ p[i]) * 1099511628211ull;
  return *this;
}

std::string hex_digest(std::uint64_t digest) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(digest));
  return text;
}

std::string Digest::hex() const {
  return hex_digest(h_);
}

std::uint32_t crc32_of(std::string_view bytes) {
  uLong crc = crc32(0L, Z_NULL, 0);
  // zlib takes lengths as uInt: feed it in pieces.
  constexpr std::size_t kPiece = 1u << 30;
  for (std::size_t at = 0; at < bytes.size(); at += kPiece) {
    const std::size_t n = std::min(kPiece, bytes.size() - at);
    crc = crc32(crc, reinterpret_cast<const Bytef*>(bytes.data() + at), static_cast<uInt>(n));
  }
  return static_cast<std::uint32_t>(crc);
}

std::uint64_t build_digest() {
  static const std::uint64_t digest = [] {
    std::ifstream exe("/proc/self/exe", std::ios::binary);
    if (!exe) return std::uint64_t{0};
    const std::string bytes{std::istreambuf_iterator<char>(exe), {}};
    return (static_cast<std::uint64_t>(bytes.size()) << 32) | crc32_of(bytes);
  }();
  return digest;
}

}  // namespace vorodg
