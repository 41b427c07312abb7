#pragma once
// VTK XML UnstructuredGrid (.vtu) import and export of polygon meshes, ASCII, VTK_POLYGON cells,
// readable by ParaView and meshio. Field data (point and cell arrays) can be attached on output.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/mesh/PolygonMesh.hpp"

namespace vorodg {

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

/// The .vtu text of a mesh with fields. Deterministic: the same mesh gives the same bytes.
std::string vtu_text(const PolygonMesh& mesh, const VtuFields& fields = {});
/// Writes it atomically. Throws InputError if a field has the wrong size, NumericalError if it
/// holds a NaN or infinity (a result that broke down is never written).
void write_vtu(const std::filesystem::path& path, const PolygonMesh& mesh, const VtuFields& fields = {});

/// Points and CSR cells read from a .vtu (before any topology is built).
struct VtuCells {
  std::vector<Point> points;
  std::vector<int> offsets;
  std::vector<int> connectivity;
  std::optional<Rectangle> domain;  // FieldData "domain" (x0 y0 x1 y1), written by vorodg
};

/// Parses .vtu text; `source` names the file in error messages. Accepts ASCII DataArrays with
/// triangle (5), polygon (7), pixel (8, reordered) and quad (9) cells. Throws InputError with one
/// line naming what is wrong.
VtuCells parse_vtu(const std::string& text, const std::string& source);
/// Reads a mesh file. The domain is `domain` if given, else the file's FieldData "domain", else
/// the bounding box of the points.
PolygonMesh read_vtu(const std::filesystem::path& path, const Rectangle* domain = nullptr);
/// The same from .vtu text already in memory (`source` names it in messages).
PolygonMesh read_vtu_text(const std::string& text, const std::string& source,
                          const Rectangle* domain = nullptr);

}  // namespace vorodg
