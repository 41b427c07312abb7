#pragma once
// VTK XML UnstructuredGrid (.vtu) import and export of polygon meshes, as ParaView and meshio
// write and read them. Output: VTK_POLYGON cells, zlib-compressed appended raw binary data by
// default, or ASCII; point and cell arrays can be attached. Input: ASCII, binary and appended data
// arrays (VtuDataArray.hpp). The writer is VtuWriter.cpp, the reader VtuMesh.cpp.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/mesh/PolygonMesh.hpp"

namespace vorodg {

/// The VTK cell type codes vorodg writes (polygons) and reads (all four), as the VTK file format
/// numbers them.
namespace vtk_cell {
inline constexpr int triangle = 5, polygon = 7, pixel = 8, quad = 9;
}

/// A named array written with a mesh: `components` values per point or per cell.
struct VtuField {
  std::string name;
  int components = 1;
  std::vector<double> values;
};

struct VtuFields {
  std::vector<VtuField> point_data;
  std::vector<VtuField> cell_data;
};

/// How the data arrays are stored. binary_zlib: vtkZLibDataCompressor blocks (UInt64 headers) in
/// <AppendedData encoding="raw">, VTK's default layout; ParaView and meshio read it; 3-4x smaller
/// than ASCII, a quarter smaller than inline base64, but raw bytes that XML tools cannot parse.
/// ascii: numbers in the shortest text that reads back to the same double, for reading by eye.
enum class VtuEncoding { ascii, binary_zlib };

/// The .vtu text of a mesh with fields. Deterministic: the same mesh gives the same bytes. Throws
/// InputError if a field has the wrong size, NumericalError if it holds a NaN or infinity (a
/// result that broke down is never written).
std::string vtu_text(const PolygonMesh& mesh, const VtuFields& fields = {},
                     VtuEncoding encoding = VtuEncoding::binary_zlib);
/// Writes it atomically.
void write_vtu(const std::filesystem::path& path, const PolygonMesh& mesh,
               const VtuFields& fields = {}, VtuEncoding encoding = VtuEncoding::binary_zlib);

/// Points and CSR cells read from a .vtu (before any topology is built).
struct VtuCells {
  std::vector<Point> points;
  std::vector<int> offsets;
  std::vector<int> connectivity;
  std::optional<Rectangle> domain;  // FieldData "domain" (x0 y0 x1 y1), written by vorodg
  VtuFields fields;                 // the numeric PointData and CellData arrays, as doubles
};

/// Parses .vtu text; `source` names the file in error messages. Accepts ASCII, binary and
/// appended DataArrays with triangle (5), polygon (7), pixel (8, reordered) and quad (9) cells.
/// Throws InputError with one line naming what is wrong.
VtuCells parse_vtu(const std::string& text, const std::string& source);
/// Reads a mesh file. The domain is `domain` if given, else the file's FieldData "domain", else
/// the bounding box of the points.
PolygonMesh read_vtu(const std::filesystem::path& path, const Rectangle* domain = nullptr);
/// The same from .vtu text already in memory (`source` names it in messages).
PolygonMesh read_vtu_text(const std::string& text, const std::string& source,
                          const Rectangle* domain = nullptr);

}  // namespace vorodg
