#pragma once
// Builds .vtu texts of a 2 x 2 grid with binary data arrays encoded as VTK and meshio write them,
// independently of the writer under test: inline base64 or appended data (raw or base64),
// uncompressed or in vtkZLibDataCompressor blocks (of a size chosen small enough to give several
// blocks), UInt32 or UInt64 headers, either byte order, any value type. Hooks let a test break
// one array to check the reader's error message.
#include <zlib.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "core/io/Base64.hpp"

namespace vorodg::testing {

enum class ArrayMode { binary, appended_raw, appended_base64 };

struct VtuFileSpec {
  ArrayMode mode = ArrayMode::binary;
  std::string header_type = "UInt64";
  bool zlib = true;
  std::size_t block_size = 40;  // bytes per zlib block: the 2 x 2 grid's points span 6 blocks
  bool big_endian = false;
  bool header_apart = true;  // base64 of the header and of the data separately (VTK)
  std::string point_type = "Float64";
  std::string index_type = "Int64";
  // Applied to the header and data bytes of the array named here, before encoding.
  std::string break_array;
  std::function<void(std::string& header, std::string& data)> breaker;
};

/// Little- or big-endian bytes of the values, converted to T.
template <class T, class V>
std::string bytes_of(const std::vector<V>& values, bool big_endian) {
  std::string out;
  for (V v : values) {
    const T t = static_cast<T>(v);
    char b[sizeof(T)];
    std::memcpy(b, &t, sizeof(T));
    if (big_endian) std::reverse(b, b + sizeof(T));
    out.append(b, sizeof(T));
  }
  return out;
}

class VtuFileBuilder {
 public:
  explicit VtuFileBuilder(VtuFileSpec spec) : s_(std::move(spec)) {}

  std::string text() {
    const std::vector<double> xyz{0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1,
                                  0, 2, 1, 0, 0, 2, 0, 1, 2, 0, 2, 2, 0};
    const std::vector<long long> conn{0, 1, 4, 3, 1, 2, 5, 4, 3, 4, 7, 6, 4, 5, 8, 7};
    const std::vector<long long> offs{4, 8, 12, 16}, types{7, 7, 7, 7};
    const std::vector<double> pressure{1.5, -2.25, 1e-300, 3};
    std::string body;
    body += "    <Piece NumberOfPoints=\"9\" NumberOfCells=\"4\">\n      <CellData>\n";
    body += array("Float64", "pressure", 1, bytes_of<double>(pressure, s_.big_endian));
    body += "      </CellData>\n      <Points>\n";
    body += array(s_.point_type, "Points", 3, points(xyz));
    body += "      </Points>\n      <Cells>\n";
    body += array(s_.index_type, "connectivity", 0, indices(conn));
    body += array(s_.index_type, "offsets", 0, indices(offs));
    body += array("UInt8", "types", 0, bytes_of<std::uint8_t>(types, s_.big_endian));
    body += "      </Cells>\n    </Piece>\n";
    std::string head =
        "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\"";
    head += std::string(" byte_order=\"") + (s_.big_endian ? "BigEndian" : "LittleEndian") + "\"";
    head += " header_type=\"" + s_.header_type + "\"";
    if (s_.zlib) head += " compressor=\"vtkZLibDataCompressor\"";
    std::string text = head + ">\n  <UnstructuredGrid>\n" + body + "  </UnstructuredGrid>\n";
    if (s_.mode != ArrayMode::binary)
      text += std::string("  <AppendedData encoding=\"") +
              (s_.mode == ArrayMode::appended_raw ? "raw" : "base64") + "\">\n   _" + appended_ +
              "\n  </AppendedData>\n";
    return text + "</VTKFile>\n";
  }

 private:
  std::string points(const std::vector<double>& xyz) const {
    if (s_.point_type == "Float32") return bytes_of<float>(xyz, s_.big_endian);
    return bytes_of<double>(xyz, s_.big_endian);
  }
  std::string indices(const std::vector<long long>& v) const {
    if (s_.index_type == "Int32") return bytes_of<std::int32_t>(v, s_.big_endian);
    if (s_.index_type == "UInt32") return bytes_of<std::uint32_t>(v, s_.big_endian);
    if (s_.index_type == "UInt64") return bytes_of<std::uint64_t>(v, s_.big_endian);
    return bytes_of<std::int64_t>(v, s_.big_endian);
  }
  std::string word(std::uint64_t v) const {
    if (s_.header_type == "UInt32")
      return bytes_of<std::uint32_t>(std::vector<std::uint64_t>{v}, s_.big_endian);
    return bytes_of<std::uint64_t>(std::vector<std::uint64_t>{v}, s_.big_endian);
  }

  /// The header and data of one array: [byte count] + bytes, or zlib blocks.
  void encode(const std::string& bytes, std::string& header, std::string& data) const {
    if (!s_.zlib) {
      header = word(bytes.size());
      data = bytes;
      return;
    }
    const std::size_t n = (bytes.size() + s_.block_size - 1) / s_.block_size;
    std::string sizes;
    for (std::size_t k = 0; k < n; ++k) {
      const std::string block = bytes.substr(k * s_.block_size, s_.block_size);
      std::string packed(compressBound(block.size()), '\0');
      uLongf len = packed.size();
      compress2(reinterpret_cast<Bytef*>(packed.data()), &len,
                reinterpret_cast<const Bytef*>(block.data()), block.size(), 6);
      data.append(packed.data(), len);
      sizes += word(len);
    }
    header = word(n) + word(s_.block_size) + word(bytes.size() % s_.block_size) + sizes;
  }

  std::string array(const std::string& type, const std::string& name, int components,
                    const std::string& bytes) {
    std::string header, data;
    encode(bytes, header, data);
    if (name == s_.break_array && s_.breaker) s_.breaker(header, data);
    std::string tag = "        <DataArray type=\"" + type + "\" Name=\"" + name + "\"";
    if (components) tag += " NumberOfComponents=\"" + std::to_string(components) + "\"";
    std::string encoded;
    if (s_.mode == ArrayMode::appended_raw) {
      encoded = header + data;
    } else if (s_.header_apart) {
      base64_append(header, encoded);
      base64_append(data, encoded);
    } else {
      base64_append(header + data, encoded);
    }
    if (s_.mode == ArrayMode::binary)
      return tag + " format=\"binary\">\n          " + encoded + "\n        </DataArray>\n";
    const std::size_t offset = appended_.size();
    appended_ += encoded;
    return tag + " format=\"appended\" offset=\"" + std::to_string(offset) + "\"/>\n";
  }

  VtuFileSpec s_;
  std::string appended_;
};

}  // namespace vorodg::testing
