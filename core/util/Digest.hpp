#pragma once
// Fingerprints that say whether two things are the same: a scene's settings, a mesh, the running
// build. FNV-1a over bytes (64 bits: a chance mismatch is out of the question for what we
// compare); the build's is the CRC-32 and size of the executable itself, so any rebuild that
// changed a byte of code is another build.
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace vorodg {

class Digest {
 public:
  Digest& add(const void* data, std::size_t bytes);
  Digest& add(std::string_view text) {
    add(static_cast<std::uint64_t>(text.size()));
    return add(text.data(), text.size());
  }
  template <class T>
  requires std::is_trivially_copyable_v<T> Digest& add(const T& x) { return add(&x, sizeof(T)); }
  template <class T>
  Digest& add(const std::vector<T>& x) {
    add(static_cast<std::uint64_t>(x.size()));
    return add(x.data(), x.size() * sizeof(T));
  }
  std::uint64_t value() const { return h_; }
  /// 16 hex digits.
  std::string hex() const;

 private:
  std::uint64_t h_ = 14695981039346656037ull;
};

/// A digest as 16 hex digits.
std::string hex_digest(std::uint64_t digest);

/// The running executable's fingerprint (computed once); 0 where it cannot be read.
std::uint64_t build_digest();

/// CRC-32 of `bytes` (zlib's).
std::uint32_t crc32_of(std::string_view bytes);

}  // namespace vorodg
