#include "core/io/StateArchive.hpp"

#include "core/util/Errors.hpp"

namespace vorodg {
void StateArchive::throw_mismatch(std::string_view name, const std::string& expected) {
  throw CheckpointError("state entry '" + std::string(name) + "': expected " + expected);
}

void StateArchive::finish() const {
  if (loading_ && read_ != bytes_.size())
    throw CheckpointError("state: " + std::to_string(bytes_.size() - read_) +
                          " bytes left after the last entry (another layout)");
}

std::size_t StateArchive::entry(std::string_view name, std::size_t bytes, std::size_t unit) {
  if (!loading_) {
    append_bytes(bytes_, static_cast<std::uint16_t>(name.size()));
    bytes_.append(name);
    append_bytes(bytes_, static_cast<std::uint64_t>(bytes));
    return bytes;
  }
  auto take = [&](void* to, std::size_t n) {
    if (bytes_.size() - read_ < n)
      throw CheckpointError("state entry '" + std::string(name) + "': the payload ends early");
    std::memcpy(to, bytes_.data() + read_, n);
    read_ += n;
  };
  std::uint16_t length = 0;
  take(&length, sizeof length);
  std::string found(length, '\0');
  take(found.data(), length);
  if (found != name)
    throw CheckpointError("state entry: expected '" + std::string(name) + "', found '" + found +
                          "' (another layout)");
  std::uint64_t stored = 0;
  take(&stored, sizeof stored);
  if (stored % unit != 0 || stored > bytes_.size() - read_)
    throw CheckpointError("state entry '" + std::string(name) + "': " + std::to_string(stored) +
                          " bytes, not whole items of " + std::to_string(unit) +
                          " or past the payload's end");
  return stored;
}

void StateArchive::raw(std::string_view name, void* data, std::size_t bytes, std::size_t unit) {
  const std::size_t n = entry(name, bytes, unit);
  if (n != bytes)
    throw CheckpointError("state entry '" + std::string(name) + "': expected " +
                          std::to_string(bytes) + " bytes, found " + std::to_string(n));
  copy(data, n);
}

void StateArchive::copy(void* data, std::size_t bytes) {
  if (bytes == 0) return;
  if (!loading_) {
    bytes_.append(static_cast<const char*>(data), bytes);
    return;
  }
  std::memcpy(data, bytes_.data() + read_, bytes);
  read_ += bytes;
}

void StateArchive::vector(std::string_view name, Eigen::VectorXd& x) {
  const std::size_t n =
      entry(name, static_cast<std::size_t>(x.size()) * sizeof(double), sizeof(double));
  if (loading_) x.resize(static_cast<Eigen::Index>(n / sizeof(double)));
  copy(x.data(), n);
}

void StateArchive::text(std::string_view name, std::string& s) {
  const std::size_t n = entry(name, s.size(), 1);
  if (loading_) s.resize(n);
  copy(s.data(), n);
}

void StateArchive::text(std::string_view name, std::ostringstream& s) {
  std::string contents = s.str();
  text(name, contents);
  if (!loading_) return;
  s.str(contents);
  s.seekp(0, std::ios::end);
}

}  // namespace vorodg
