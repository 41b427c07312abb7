#pragma once
// Decodes the DataArray elements of a .vtu: ASCII text, base64 binary (format="binary") and
// appended data (format="appended", <AppendedData> raw or base64), uncompressed or compressed
// with vtkZLibDataCompressor, UInt32 or UInt64 headers, any numeric VTK type, either byte order.
// Every failure is an InputError of one line naming the file and the array.
#include <pugixml.hpp>

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace vorodg {

/// What the <VTKFile> and <AppendedData> elements say about binary data.
struct VtuBinaryFormat {
  std::string header_type = "UInt32";  // VTK's default when the attribute is absent
  std::string compressor;              // empty: uncompressed
  std::string byte_order = "LittleEndian";
  bool has_appended = false;
  std::string_view appended;  // the bytes after the '_' that opens <AppendedData>
  std::string appended_encoding = "raw";
};

class VtuArrayDecoder {
 public:
  VtuArrayDecoder(std::string source, VtuBinaryFormat format)
      : source_(std::move(source)), format_(std::move(format)) {}

  [[noreturn]] void fail(const std::string& what) const;
  /// Numbers of any numeric type as doubles; with `finite`, a NaN or infinity is an error.
  std::vector<double> reals(const pugi::xml_node& array, const std::string& name,
                            bool finite) const;
  /// Integers: binary data of an integer type, or ASCII text of integers.
  std::vector<long long> integers(const pugi::xml_node& array, const std::string& name) const;
  /// Whether the array's type is one of VTK's numeric types (not String or Bit).
  static bool numeric(const pugi::xml_node& array);

 private:
  /// The decoded bytes of a binary or appended array.
  std::string binary_bytes(const pugi::xml_node& array, const std::string& name) const;
  std::string payload_bytes(const pugi::xml_node& array, const std::string& where) const;

  std::string source_;
  VtuBinaryFormat format_;
};

}  // namespace vorodg
