#include "core/io/PvdCollection.hpp"

#include <charconv>
#include <cmath>

#include "core/io/AtomicFile.hpp"
#include "core/io/StateArchive.hpp"
#include "core/util/Errors.hpp"

namespace vorodg {
namespace {

std::string shortest(double x) {
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, end);
}

/// The text of an XML attribute value: file names may hold '&', '<' or quotes.
std::string escaped(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace

void PvdCollection::add(double value, const std::filesystem::path& file) {
  if (!std::isfinite(value))
    throw InputError(path_.string() + ": the value of data set '" + file.string() + "' is " +
                     shortest(value) + ", expected a finite number");
  std::filesystem::path relative = file;
  if (file.is_absolute()) {
    const std::filesystem::path folder = std::filesystem::absolute(path_).parent_path();
    relative = file.lexically_relative(folder);
    if (relative.empty())
      throw InputError(path_.string() + ": data set '" + file.string() +
                       "' has no path relative to the collection's folder");
  }
  entries_.push_back({value, relative.generic_string()});
  try {
    write_file_atomically(path_, text());
  } catch (...) {  // the collection stays as the file says it is
    entries_.pop_back();
    throw;
  }
}

std::string PvdCollection::text() const {
  std::string out =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "  <Collection>\n";
  for (const Entry& e : entries_)
    out += "    <DataSet timestep=\"" + shortest(e.value) + "\" group=\"\" part=\"0\" file=\"" +
           escaped(e.file) + "\"/>\n";
  out += "  </Collection>\n</VTKFile>\n";
  return out;
}

void PvdCollection::archive(StateArchive& a) {
  a.each("pvd.entries", entries_, [](StateArchive& item, Entry& e) {
    item.value("pvd.value", e.value);
    item.text("pvd.file", e.file);
  });
}

}  // namespace vorodg
