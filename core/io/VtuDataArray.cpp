#include "core/io/VtuDataArray.hpp"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "core/io/VtuPayload.hpp"
#include "core/io/ZlibBlocks.hpp"
#include "core/util/Errors.hpp"

namespace vorodg {
namespace {

enum class Kind { signed_int, unsigned_int, real };

struct ScalarType {
  const char* name;
  int size;
  Kind kind;
};

constexpr ScalarType kTypes[] = {
    {"Int8", 1, Kind::signed_int},  {"UInt8", 1, Kind::unsigned_int},
    {"Int16", 2, Kind::signed_int}, {"UInt16", 2, Kind::unsigned_int},
    {"Int32", 4, Kind::signed_int}, {"UInt32", 4, Kind::unsigned_int},
    {"Int64", 8, Kind::signed_int}, {"UInt64", 8, Kind::unsigned_int},
    {"Float32", 4, Kind::real},     {"Float64", 8, Kind::real},
};

const ScalarType* find_type(const pugi::xml_node& array) {
  const char* name = array.attribute("type").as_string();
  for (const ScalarType& t : kTypes)
    if (std::strcmp(t.name, name) == 0) return &t;
  return nullptr;
}

bool is_space(char c) {
  return c == ' ' || c == '\n' || c == '\t' || c == '\r';
}

/// Entry `i` of the bytes as an unsigned integer of `size` bytes in the file's byte order.
std::uint64_t raw_word(const char* p, int size, bool big_endian) {
  std::uint64_t v = 0;
  for (int i = 0; i < size; ++i) {
    const int k = big_endian ? i : size - 1 - i;
    v = (v << 8) | static_cast<unsigned char>(p[k]);
  }
  return v;
}

std::int64_t sign_extend(std::uint64_t v, int size) {
  if (size == 8) return static_cast<std::int64_t>(v);
  const std::uint64_t sign = std::uint64_t{1} << (8 * size - 1);
  return static_cast<std::int64_t>((v ^ sign) - sign);
}

double real_at(const char* p, const ScalarType& t, bool big_endian) {
  const std::uint64_t w = raw_word(p, t.size, big_endian);
  switch (t.kind) {
    case Kind::signed_int: return static_cast<double>(sign_extend(w, t.size));
    case Kind::unsigned_int: return static_cast<double>(w);
    case Kind::real: break;
  }
  if (t.size == 4) return std::bit_cast<float>(static_cast<std::uint32_t>(w));
  return std::bit_cast<double>(w);
}

/// ASCII numbers, whitespace-separated.
template <class T>
std::vector<T> ascii_numbers(const VtuArrayDecoder& d, const pugi::xml_node& array,
                             const std::string& name, bool finite) {
  const char* p = array.child_value();
  const char* end = p + std::char_traits<char>::length(p);
  std::vector<T> values;
  while (true) {
    while (p < end && is_space(*p)) ++p;
    if (p == end) break;
    T x{};
    auto [next, ec] = std::from_chars(p, end, x);
    if (ec != std::errc() || (next < end && !is_space(*next)))
      d.fail("DataArray '" + name + "' entry " + std::to_string(values.size()) +
             " is not a valid number");
    if constexpr (std::is_floating_point_v<T>)
      if (finite && !std::isfinite(x))
        d.fail("DataArray '" + name + "' entry " + std::to_string(values.size()) +
               " is not finite");
    values.push_back(x);
    p = next;
  }
  return values;
}

std::string format_of(const pugi::xml_node& array) {
  return array.attribute("format").as_string("ascii");
}

}  // namespace

void VtuArrayDecoder::fail(const std::string& what) const {
  throw InputError(source_ + ": " + what);
}

bool VtuArrayDecoder::numeric(const pugi::xml_node& array) {
  return find_type(array) != nullptr;
}

std::vector<double> VtuArrayDecoder::reals(const pugi::xml_node& array, const std::string& name,
                                           bool finite) const {
  if (format_of(array) == "ascii") return ascii_numbers<double>(*this, array, name, finite);
  const std::string bytes = binary_bytes(array, name);
  const ScalarType& t = *find_type(array);
  const bool big = format_.byte_order == "BigEndian";
  std::vector<double> values(bytes.size() / t.size);
  for (std::size_t i = 0; i < values.size(); ++i) {
    values[i] = real_at(bytes.data() + i * t.size, t, big);
    if (finite && !std::isfinite(values[i]))
      fail("DataArray '" + name + "' entry " + std::to_string(i) + " is not finite");
  }
  return values;
}

std::vector<long long> VtuArrayDecoder::integers(const pugi::xml_node& array,
                                                 const std::string& name) const {
  if (format_of(array) == "ascii") return ascii_numbers<long long>(*this, array, name, false);
  const std::string bytes = binary_bytes(array, name);
  const ScalarType& t = *find_type(array);
  if (t.kind == Kind::real)
    fail("DataArray '" + name + "' has type=\"" + t.name + "\", expected an integer type");
  const bool big = format_.byte_order == "BigEndian";
  std::vector<long long> values(bytes.size() / t.size);
  for (std::size_t i = 0; i < values.size(); ++i) {
    const std::uint64_t w = raw_word(bytes.data() + i * t.size, t.size, big);
    if (t.kind == Kind::unsigned_int && w > std::uint64_t{std::numeric_limits<long long>::max()})
      fail("DataArray '" + name + "' entry " + std::to_string(i) + " (" + std::to_string(w) +
           ") is out of range");
    values[i] = t.kind == Kind::signed_int ? sign_extend(w, t.size) : static_cast<long long>(w);
  }
  return values;
}

std::string VtuArrayDecoder::binary_bytes(const pugi::xml_node& array,
                                          const std::string& name) const {
  const std::string format = format_of(array);
  if (format != "binary" && format != "appended")
    fail("DataArray '" + name + "' has format=\"" + format +
         "\", expected \"ascii\", \"binary\" or \"appended\"");
  const std::string where = "DataArray '" + name + "' (format=\"" + format + "\")";
  const ScalarType* t = find_type(array);
  if (!t)
    fail(where + " has type=\"" + array.attribute("type").as_string() +
         "\", expected Int8..Int64, UInt8..UInt64, Float32 or Float64");
  std::string bytes = payload_bytes(array, where);
  if (bytes.size() % t->size != 0)
    fail(where + " holds " + std::to_string(bytes.size()) + " bytes, not a whole number of " +
         t->name + " values");
  return bytes;
}

std::string VtuArrayDecoder::payload_bytes(const pugi::xml_node& array,
                                           const std::string& where) const {
  int header_bytes = 0;
  if (format_.header_type == "UInt32") header_bytes = 4;
  if (format_.header_type == "UInt64") header_bytes = 8;
  if (!header_bytes)
    fail(where + ": the file's header_type=\"" + format_.header_type +
         "\" is not supported, expected UInt32 or UInt64");
  if (format_.byte_order != "LittleEndian" && format_.byte_order != "BigEndian")
    fail(where + ": the file's byte_order=\"" + format_.byte_order +
         "\", expected LittleEndian or BigEndian");
  const bool zlib = format_.compressor == "vtkZLibDataCompressor";
  if (!zlib && !format_.compressor.empty())
    fail(where + ": the file's compressor=\"" + format_.compressor +
         "\" is not supported, expected vtkZLibDataCompressor or none");
  VtuPayload payload = VtuPayload::base64(array.child_value());
  if (std::string_view(array.attribute("format").as_string()) == "appended") {
    if (!format_.has_appended) fail(where + " but the file has no <AppendedData>");
    const std::string& encoding = format_.appended_encoding;
    if (encoding != "raw" && encoding != "base64")
      fail(where + ": <AppendedData encoding=\"" + encoding + "\">, expected raw or base64");
    const std::string text = array.attribute("offset").as_string();
    std::size_t offset = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), offset);
    if (text.empty() || ec != std::errc() || end != text.data() + text.size())
      fail(where + " has offset=\"" + text + "\", expected a non-negative integer");
    if (offset >= format_.appended.size())
      fail(where + " has offset " + text + ", beyond the " +
           std::to_string(format_.appended.size()) + " bytes of appended data");
    const std::string_view data = format_.appended.substr(offset);
    payload = encoding == "raw" ? VtuPayload::raw(data) : VtuPayload::base64(data);
  }
  const bool big = format_.byte_order == "BigEndian";
  try {
    if (zlib) return inflate_vtk_blocks(payload, header_bytes, big);
    const std::uint64_t n = payload.word(header_bytes, big, "the header");
    if (n > payload.max_bytes_left())
      throw InputError("the header announces " + std::to_string(n) + " bytes, but at most " +
                       std::to_string(payload.max_bytes_left()) + " follow");
    std::string bytes;
    bytes.reserve(n);
    payload.read(n, bytes, "the array data");
    return bytes;
  } catch (const InputError& e) {  // a bare message from the payload or zlib layer
    fail(where + ": " + e.what());
  }
}

}  // namespace vorodg
