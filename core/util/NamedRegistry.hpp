#pragma once
// A list of entries known by name (each has a `name` member): the shipped ones first, in the
// order messages and docs list them, then any that a program or a test registers. What a seam of
// the code (a DG formulation, a contact law, a softening law) keeps its implementations in, so
// that adding one is its own file and one line; the names reach the scene readers, `--help` and
// the key tables from here.
#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"

namespace vorodg {

template <class Entry>
class NamedRegistry {
 public:
  /// `what` names an entry in messages ("contact law").
  NamedRegistry(std::string what, std::vector<Entry> shipped)
      : what_(std::move(what)), entries_(std::move(shipped)) {}

  const std::vector<Entry>& entries() const { return entries_; }

  /// Adds one; a name already known is refused with InputError. Returns true, so that a file can
  /// register at static initialization: `const bool registered = register_...(...)`.
  bool add(Entry entry) {
    if (find(entry.name)) throw InputError(what_ + " '" + entry.name + "': registered twice");
    entries_.push_back(std::move(entry));
    return true;
  }

  /// The entry called `name`; throws InputError naming the known ones otherwise.
  const Entry& at(const std::string& name) const {
    if (const Entry* e = find(name)) return *e;
    throw InputError(what_ + " '" + name + "': expected " + name_list(entries_));
  }

  /// " a b c ": the names, each with a space either side (what scene readers accept).
  std::string words() const {
    std::string out = " ";
    for (const Entry& e : entries_) out += e.name + " ";
    return out;
  }

 private:
  const Entry* find(const std::string& name) const {
    const auto it = std::find_if(entries_.begin(), entries_.end(),
                                 [&](const Entry& e) { return e.name == name; });
    return it == entries_.end() ? nullptr : &*it;
  }

  std::string what_;
  std::vector<Entry> entries_;
};

}  // namespace vorodg
