#pragma once
// The state of a run as a flat sequence of named entries, for checkpoints. One function per
// class, `archive(StateArchive&)`, both saves and loads (the archive knows which it does), so the
// two can never list different members or take them in a different order. Each entry is its
// name, its byte count and its bytes; a load checks the name and the size before it copies, so a
// payload from another layout is refused at the first entry that differs, naming it.
//
// Values are stored as their bytes: a checkpoint is read back only by the build that wrote it
// (Checkpoint refuses any other), so the layout of a plain struct is the same on both ends.
// "Plain" (PlainBytes) is wider than trivially copyable, which Eigen's fixed-size vectors are not
// by the trait although their bytes are all there is to them: standard layout and trivially
// destructible, which keeps out whatever owns memory (vectors, strings, maps).
#include <Eigen/Core>
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <map>
#include <sstream>
#include <string>
#include <string_view>
#include <type_traits>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace vorodg {

/// Appends the bytes of `x` to `out` (the archive's entries and the checkpoint's header).
template <class T>
void append_bytes(std::string& out, T x) {
  out.append(reinterpret_cast<const char*>(&x), sizeof(T));
}

template <class T>
concept PlainBytes = std::is_trivially_destructible_v<T> && std::is_standard_layout_v<T>;

class StateArchive {
 public:
  /// An empty archive that saves.
  StateArchive() = default;
  /// An archive that loads from `bytes` (a payload written by a saving archive).
  explicit StateArchive(std::string bytes) : bytes_(std::move(bytes)), loading_(true) {}

  bool loading() const { return loading_; }
  /// The entries saved so far.
  const std::string& bytes() const { return bytes_; }
  /// Loading: throws CheckpointError unless every byte was read.
  void finish() const;

  /// A trivially copyable value (numbers, flags, plain structs, fixed-size Eigen types).
  template <PlainBytes T>
  void value(std::string_view name, T& x) {
    raw(name, &x, sizeof(T), sizeof(T));
  }
  /// A vector of plain values (resized on load).
  template <PlainBytes T>
  void vector(std::string_view name, std::vector<T>& x) {
    const std::size_t n = entry(name, x.size() * sizeof(T), sizeof(T));
    if (loading_) x.resize(n / sizeof(T));
    copy(x.data(), n);
  }
  void vector(std::string_view name, Eigen::VectorXd& x);
  void text(std::string_view name, std::string& s);
  /// A text being written (rows of a CSV kept in memory): its contents; a load refills it and
  /// puts the write position at its end, so that writing goes on where it stopped.
  void text(std::string_view name, std::ostringstream& s);
  /// A hash map, saved in key order so that one state always gives one payload. Loading
  /// refills it in that order.
  template <class K, class V>
  void map(std::string_view name, std::unordered_map<K, V>& m) {
    std::vector<K> keys;
    std::vector<V> values;
    if (!loading_) {
      std::map<K, V> sorted(m.begin(), m.end());
      for (const auto& [k, v] : sorted) keys.push_back(k), values.push_back(v);
    }
    vector(std::string(name) + ".keys", keys);
    vector(std::string(name) + ".values", values);
    if (loading_ && keys.size() != values.size()) throw_mismatch(name, "as many keys as values");
    if (loading_) {
      m.clear();
      for (std::size_t i = 0; i < keys.size(); ++i) m.emplace(keys[i], values[i]);
    }
  }
  template <class K>
  void set(std::string_view name, std::unordered_set<K>& s) {
    std::vector<K> items(s.begin(), s.end());
    if (!loading_) std::sort(items.begin(), items.end());
    vector(name, items);
    if (loading_) s = std::unordered_set<K>(items.begin(), items.end());
  }
  /// A vector of anything else: its size, then `each(archive, element)` per element.
  template <class T, class Each>
  void each(std::string_view name, std::vector<T>& x, Each each) {
    std::uint64_t n = x.size();
    value(name, n);
    if (loading_) x.resize(n);
    for (T& item : x) each(*this, item);
  }

 private:
  [[noreturn]] static void throw_mismatch(std::string_view name, const std::string& expected);
  /// Writes or checks the entry's header; returns its byte count (`unit` divides it on load).
  std::size_t entry(std::string_view name, std::size_t bytes, std::size_t unit);
  void raw(std::string_view name, void* data, std::size_t bytes, std::size_t unit);
  void copy(void* data, std::size_t bytes);

  std::string bytes_;
  std::size_t read_ = 0;
  bool loading_ = false;
};

}  // namespace vorodg
