// The .vtu writer (vtu_text, write_vtu of VtuMesh.hpp): ASCII, or zlib-compressed appended raw
// binary data.
#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string_view>

#include "core/io/AtomicFile.hpp"
#include "core/io/VtuMesh.hpp"
#include "core/io/ZlibBlocks.hpp"
#include "core/util/Errors.hpp"

namespace vorodg {
namespace {

class TextBuilder {
 public:
  explicit TextBuilder(std::size_t reserve) { text_.reserve(reserve); }
  TextBuilder& operator<<(std::string_view s) {
    text_.append(s);
    return *this;
  }
  /// Shortest decimal form that reads back to the same double: deterministic and exact.
  void number(double x) {
    char buf[32];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, x);
    text_.append(buf, end);
  }
  void number(long long x) {
    char buf[24];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, x);
    text_.append(buf, end);
  }
  /// The <AppendedData> bytes so far: an array's offset is their size when it is declared.
  std::string& appended() { return appended_; }
  std::string take() { return std::move(text_); }

 private:
  std::string text_;
  std::string appended_;
};

void check_field(const VtuField& field, std::size_t count, const char* where) {
  if (field.values.size() != count * field.components)
    throw InputError(std::string("vtu ") + where + " field '" + field.name +
                     "': " + std::to_string(field.values.size()) + " values, expected " +
                     std::to_string(count * field.components));
  for (double v : field.values)
    if (!std::isfinite(v))
      throw NumericalError(std::string("vtu ") + where + " field '" + field.name +
                           "' holds a non-finite value; refusing to write it");
}

/// Appends `v` in little-endian byte order (the files declare byte_order="LittleEndian").
template <class T>
void put_le(std::string& bytes, T v) {
  char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  if constexpr (std::endian::native == std::endian::big) std::reverse(b, b + sizeof(T));
  bytes.append(b, sizeof(T));
}

/// The compression header and the compressed blocks of an array, appended raw.
void binary_payload(TextBuilder& out, std::string_view bytes, BlockContent content) {
  const ZlibBlocks blocks = deflate_vtk_blocks(bytes, content);
  out.appended() += blocks.header;
  out.appended() += blocks.data;
}

void open_array(TextBuilder& out, const char* type, std::string_view name, int components,
                VtuEncoding encoding) {
  out << "        <DataArray type=\"" << type << "\"";
  if (!name.empty()) out << " Name=\"" << name << "\"";
  if (components) out << " NumberOfComponents=\"" << std::to_string(components) << "\"";
  if (encoding == VtuEncoding::ascii)
    out << " format=\"ascii\">\n";
  else
    out << " format=\"appended\" offset=\"" << std::to_string(out.appended().size()) << "\"/>\n";
}

void write_field(TextBuilder& out, const VtuField& field, VtuEncoding encoding) {
  open_array(out, "Float64", field.name, field.components, encoding);
  if (encoding == VtuEncoding::binary_zlib) {
    std::string bytes;
    bytes.reserve(8 * field.values.size());
    for (double v : field.values) put_le(bytes, v);
    binary_payload(out, bytes, BlockContent::reals);
    return;
  }
  for (std::size_t i = 0; i < field.values.size(); ++i) {
    out << ((i % field.components == 0) ? (i ? "\n          " : "          ") : " ");
    out.number(field.values[i]);
  }
  out << "\n        </DataArray>\n";
}

void write_points(TextBuilder& out, const PolygonMesh& mesh, VtuEncoding encoding) {
  open_array(out, "Float64", "", 3, encoding);
  if (encoding == VtuEncoding::binary_zlib) {
    std::string bytes;
    bytes.reserve(24 * mesh.vertices().size());
    for (const Point& p : mesh.vertices()) {
      put_le(bytes, p.x());
      put_le(bytes, p.y());
      put_le(bytes, 0.0);
    }
    return binary_payload(out, bytes, BlockContent::reals);
  }
  for (const Point& p : mesh.vertices()) {
    out << "          ";
    out.number(p.x());
    out << " ";
    out.number(p.y());
    out << " 0\n";
  }
  out << "        </DataArray>\n";
}

/// Connectivity, offsets and types. Binary: Int32 indices, which hold every index of a mesh.
void write_cells_binary(TextBuilder& out, const PolygonMesh& mesh) {
  std::string conn, offs,
      types(static_cast<std::size_t>(mesh.num_cells()), static_cast<char>(vtk_cell::polygon));
  conn.reserve(4 * mesh.cell_vertex_list().size());
  offs.reserve(4 * static_cast<std::size_t>(mesh.num_cells()));
  for (int v : mesh.cell_vertex_list()) put_le(conn, static_cast<std::int32_t>(v));
  for (int c = 0; c < mesh.num_cells(); ++c)
    put_le(offs, static_cast<std::int32_t>(mesh.offsets()[c + 1]));
  open_array(out, "Int32", "connectivity", 0, VtuEncoding::binary_zlib);
  binary_payload(out, conn, BlockContent::integers);
  open_array(out, "Int32", "offsets", 0, VtuEncoding::binary_zlib);
  binary_payload(out, offs, BlockContent::integers);
  open_array(out, "UInt8", "types", 0, VtuEncoding::binary_zlib);
  binary_payload(out, types, BlockContent::integers);
}

void write_cells_ascii(TextBuilder& out, const PolygonMesh& mesh) {
  open_array(out, "Int64", "connectivity", 0, VtuEncoding::ascii);
  for (int c = 0; c < mesh.num_cells(); ++c) {
    out << "         ";
    for (int v : mesh.cell_vertices(c)) {
      out << " ";
      out.number(static_cast<long long>(v));
    }
    out << "\n";
  }
  out << "        </DataArray>\n";
  open_array(out, "Int64", "offsets", 0, VtuEncoding::ascii);
  for (int c = 0; c < mesh.num_cells(); ++c) {
    out << ((c % 16 == 0) ? (c ? "\n          " : "          ") : " ");
    out.number(static_cast<long long>(mesh.offsets()[c + 1]));
  }
  out << "\n        </DataArray>\n";
  open_array(out, "UInt8", "types", 0, VtuEncoding::ascii);
  for (int c = 0; c < mesh.num_cells(); ++c)
    out << ((c % 32 == 0) ? (c ? "\n          7" : "          7") : " 7");
  out << "\n        </DataArray>\n";
}

}  // namespace

std::string vtu_text(const PolygonMesh& mesh, const VtuFields& fields, VtuEncoding encoding) {
  for (const auto& f : fields.point_data) check_field(f, mesh.num_vertices(), "point");
  for (const auto& f : fields.cell_data) check_field(f, mesh.num_cells(), "cell");
  const bool ascii = encoding == VtuEncoding::ascii;
  TextBuilder out(
      (ascii ? 64 : 24) * static_cast<std::size_t>(mesh.num_vertices() + mesh.num_cells()) + 4096);
  out << "<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\"";
  if (!ascii) out << " header_type=\"UInt64\" compressor=\"vtkZLibDataCompressor\"";
  // The domain stays ASCII in every encoding: four numbers anyone can read in the file.
  out << ">\n"
         "  <UnstructuredGrid>\n"
         "    <FieldData>\n"
         "      <DataArray type=\"Float64\" Name=\"domain\" NumberOfTuples=\"4\" format=\"ascii\">";
  const Rectangle& d = mesh.domain();
  for (double x : {d.x0(), d.y0(), d.x1(), d.y1()}) {
    out << " ";
    out.number(x);
  }
  out << " </DataArray>\n    </FieldData>\n";
  out << "    <Piece NumberOfPoints=\"" << std::to_string(mesh.num_vertices())
      << "\" NumberOfCells=\"" << std::to_string(mesh.num_cells()) << "\">\n";
  out << "      <PointData>\n";
  for (const auto& f : fields.point_data) write_field(out, f, encoding);
  out << "      </PointData>\n      <CellData>\n";
  for (const auto& f : fields.cell_data) write_field(out, f, encoding);
  out << "      </CellData>\n      <Points>\n";
  write_points(out, mesh, encoding);
  out << "      </Points>\n      <Cells>\n";
  if (ascii)
    write_cells_ascii(out, mesh);
  else
    write_cells_binary(out, mesh);
  out << "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n";
  if (!ascii) {  // raw bytes after '_', then a newline, as VTK writes them
    out << "  <AppendedData encoding=\"raw\">\n   _" << out.appended();
    out << "\n  </AppendedData>\n";
  }
  out << "</VTKFile>\n";
  return out.take();
}

void write_vtu(const std::filesystem::path& path, const PolygonMesh& mesh, const VtuFields& fields,
               VtuEncoding encoding) {
  write_file_atomically(path, vtu_text(mesh, fields, encoding));
}

}  // namespace vorodg
