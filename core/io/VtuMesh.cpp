// The .vtu reader (parse_vtu, read_vtu, read_vtu_text of VtuMesh.hpp); the data arrays are decoded
// by VtuArrayDecoder, the writer is VtuWriter.cpp.
#include "core/io/VtuMesh.hpp"

#include <pugixml.hpp>

#include <algorithm>
#include <charconv>
#include <limits>
#include <string_view>

#include "core/io/AtomicFile.hpp"
#include "core/io/VtuDataArray.hpp"
#include "core/util/Errors.hpp"

namespace vorodg {
namespace {

constexpr int kMaxComponents = 1024;
constexpr std::string_view kAppendedClose = "</AppendedData>";

/// Raw appended data is not XML: the parser gets the text with <AppendedData> emptied, and the
/// arrays read the bytes after its opening '_' directly, by offset.
struct SplitText {
  bool has_appended = false;
  std::string xml;            // the text without the appended data (if there is any)
  std::string_view appended;  // the bytes after the '_'
};

SplitText split_appended(const std::string& text, const VtuArrayDecoder& d) {
  SplitText s;
  const std::size_t open = text.find("<AppendedData");
  const std::size_t tag_end = open == std::string::npos ? open : text.find('>', open);
  if (tag_end == std::string::npos || text[tag_end - 1] == '/') return s;  // the parser decides
  std::size_t at = tag_end + 1;
  while (at < text.size() && std::string_view(" \t\r\n").find(text[at]) != std::string_view::npos)
    ++at;
  if (at == text.size() || text[at] != '_')
    d.fail("<AppendedData> does not begin with '_', expected '_' before the data");
  // The last closing tag: raw data may contain any bytes, "</AppendedData>" among them.
  const std::size_t close = text.rfind(kAppendedClose);
  if (close == std::string::npos || close < at)
    d.fail("<AppendedData> has no closing </AppendedData> after its data (truncated file?)");
  s.has_appended = true;
  s.appended = std::string_view(text).substr(at + 1, close - at - 1);
  s.xml = text.substr(0, tag_end + 1) + text.substr(close);
  return s;
}

long long count_attribute(const VtuArrayDecoder& d, const pugi::xml_node& piece, const char* name) {
  const auto attr = piece.attribute(name);
  long long value = -1;
  const std::string text = attr.as_string();
  auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (!attr || ec != std::errc() || value < 0 || value > std::numeric_limits<int>::max() / 8)
    d.fail(std::string("<Piece> attribute ") + name + "=\"" + text +
           "\", expected a non-negative integer");
  return value;
}

pugi::xml_node named_array(const VtuArrayDecoder& d, const pugi::xml_node& parent,
                           const char* name) {
  for (auto a : parent.children("DataArray"))
    if (std::string_view(a.attribute("Name").as_string()) == name) return a;
  d.fail(std::string("<Cells> has no DataArray Name=\"") + name + "\"");
}

/// The numeric arrays under <PointData> or <CellData>, `count` tuples each (String and Bit arrays
/// are not numbers and are left out).
std::vector<VtuField> read_fields(const VtuArrayDecoder& d, const pugi::xml_node& parent,
                                  long long count, const char* where) {
  std::vector<VtuField> fields;
  for (auto a : parent.children("DataArray")) {
    if (!VtuArrayDecoder::numeric(a)) continue;
    VtuField f{a.attribute("Name").as_string(), a.attribute("NumberOfComponents").as_int(1), {}};
    const std::string what = std::string(where) + " array '" + f.name + "'";
    if (f.components < 1 || f.components > kMaxComponents)
      d.fail(what + " has NumberOfComponents=" + std::to_string(f.components) + ", expected 1.." +
             std::to_string(kMaxComponents));
    f.values = d.reals(a, f.name, false);
    if (static_cast<long long>(f.values.size()) != count * f.components)
      d.fail(what + " holds " + std::to_string(f.values.size()) + " numbers, expected " +
             std::to_string(count * f.components) + " (" + std::to_string(count) + " x " +
             std::to_string(f.components) + " components)");
    fields.push_back(std::move(f));
  }
  return fields;
}

std::optional<Rectangle> read_domain(const VtuArrayDecoder& d, const pugi::xml_node& grid) {
  std::optional<Rectangle> domain;
  for (auto a : grid.child("FieldData").children("DataArray"))
    if (std::string_view(a.attribute("Name").as_string()) == "domain") {
      const auto v = d.reals(a, "domain", true);
      if (v.size() != 4)
        d.fail("FieldData 'domain' holds " + std::to_string(v.size()) +
               " numbers, expected 4 (x0 y0 x1 y1)");
      try {
        domain = Rectangle(v[0], v[1], v[2], v[3]);
      } catch (const InputError& e) {
        d.fail(std::string("FieldData 'domain': ") + e.what());
      }
    }
  return domain;
}

/// Checks the cells and converts them to counter-clockwise loops in CSR form.
void read_cells(const VtuArrayDecoder& d, const pugi::xml_node& cells, long long n_points,
                long long n_cells, VtuCells& out) {
  const auto conn = d.integers(named_array(d, cells, "connectivity"), "connectivity");
  const auto offs = d.integers(named_array(d, cells, "offsets"), "offsets");
  const auto types = d.integers(named_array(d, cells, "types"), "types");
  if (static_cast<long long>(offs.size()) != n_cells ||
      static_cast<long long>(types.size()) != n_cells)
    d.fail("offsets/types hold " + std::to_string(offs.size()) + "/" +
           std::to_string(types.size()) +
           " entries, expected NumberOfCells=" + std::to_string(n_cells));
  out.offsets.reserve(n_cells + 1);
  out.offsets.push_back(0);
  out.connectivity.reserve(conn.size());
  long long begin = 0;
  for (long long c = 0; c < n_cells; ++c) {
    const long long end = offs[c];
    const std::string cell = "cell " + std::to_string(c);
    if (end <= begin || end > static_cast<long long>(conn.size()))
      d.fail(cell + ": offset " + std::to_string(end) + " out of order or beyond the " +
             std::to_string(conn.size()) + " connectivity entries");
    const long long t = types[c];
    const long long n = end - begin;
    const bool ok = (t == vtk_cell::polygon && n >= 3) || (t == vtk_cell::triangle && n == 3) ||
                    ((t == vtk_cell::quad || t == vtk_cell::pixel) && n == 4);
    if (!ok)
      d.fail(cell + ": VTK cell type " + std::to_string(t) + " with " + std::to_string(n) +
             " vertices, expected a polygon (7), triangle (5), pixel (8) or quad (9)");
    const std::size_t first = out.connectivity.size();
    for (long long k = begin; k < end; ++k) {
      if (conn[k] < 0 || conn[k] >= n_points)
        d.fail(cell + ": vertex index " + std::to_string(conn[k]) + " out of range 0.." +
               std::to_string(n_points - 1));
      out.connectivity.push_back(static_cast<int>(conn[k]));
    }
    // Pixels are numbered row by row; swap the last two for a counter-clockwise loop.
    if (t == vtk_cell::pixel) std::swap(out.connectivity[first + 2], out.connectivity[first + 3]);
    out.offsets.push_back(static_cast<int>(out.connectivity.size()));
    begin = end;
  }
}

VtuBinaryFormat binary_format(const pugi::xml_node& root, const SplitText& split) {
  VtuBinaryFormat format;
  format.header_type = root.attribute("header_type").as_string("UInt32");
  format.compressor = root.attribute("compressor").as_string("");
  format.byte_order = root.attribute("byte_order").as_string("LittleEndian");
  format.has_appended = split.has_appended;
  format.appended = split.appended;
  format.appended_encoding = root.child("AppendedData").attribute("encoding").as_string("raw");
  return format;
}

std::vector<Point> read_points(const VtuArrayDecoder& d, const pugi::xml_node& piece,
                               long long n_points) {
  const auto array = piece.child("Points").child("DataArray");
  if (!array) d.fail("no <Points><DataArray> element");
  const int components = array.attribute("NumberOfComponents").as_int(1);
  if (components != 2 && components != 3)
    d.fail("<Points> has NumberOfComponents=" + std::to_string(components) + ", expected 3");
  const auto xyz = d.reals(array, "Points", true);
  if (static_cast<long long>(xyz.size()) != n_points * components)
    d.fail("<Points> holds " + std::to_string(xyz.size()) + " numbers, expected " +
           std::to_string(n_points * components) +
           " for NumberOfPoints=" + std::to_string(n_points));
  std::vector<Point> points;
  points.reserve(n_points);
  for (long long i = 0; i < n_points; ++i)
    points.emplace_back(xyz[components * i], xyz[components * i + 1]);
  return points;
}

}  // namespace

VtuCells parse_vtu(const std::string& text, const std::string& source) {
  const VtuArrayDecoder plain(source, {});  // for the errors found before the format is known
  const SplitText split = split_appended(text, plain);
  const std::string& xml = split.has_appended ? split.xml : text;
  pugi::xml_document doc;
  const auto parsed = doc.load_buffer(xml.data(), xml.size());
  if (!parsed)
    plain.fail(std::string("not well-formed XML (") + parsed.description() + " at byte " +
               std::to_string(parsed.offset) + ")");
  const auto root = doc.child("VTKFile");
  if (!root || std::string_view(root.attribute("type").as_string()) != "UnstructuredGrid")
    plain.fail("expected a <VTKFile type=\"UnstructuredGrid\"> root element");
  const VtuArrayDecoder d(source, binary_format(root, split));

  const auto grid = root.child("UnstructuredGrid");
  const auto piece = grid.child("Piece");
  if (!piece) d.fail("no <UnstructuredGrid><Piece> element");
  if (piece.next_sibling("Piece")) d.fail("more than one <Piece>, expected exactly one");
  const long long n_points = count_attribute(d, piece, "NumberOfPoints");
  const long long n_cells = count_attribute(d, piece, "NumberOfCells");
  VtuCells out;
  out.points = read_points(d, piece, n_points);
  const auto cells = piece.child("Cells");
  if (!cells) d.fail("no <Cells> element");
  read_cells(d, cells, n_points, n_cells, out);
  out.domain = read_domain(d, grid);
  out.fields.point_data = read_fields(d, piece.child("PointData"), n_points, "PointData");
  out.fields.cell_data = read_fields(d, piece.child("CellData"), n_cells, "CellData");
  return out;
}

PolygonMesh read_vtu(const std::filesystem::path& path, const Rectangle* domain) {
  return read_vtu_text(read_file(path), path.string(), domain);
}

PolygonMesh read_vtu_text(const std::string& text, const std::string& source,
                          const Rectangle* domain) {
  VtuCells cells = parse_vtu(text, source);
  if (cells.points.empty() || cells.offsets.size() < 2)
    throw InputError(source + ": the mesh is empty (no points or no cells)");
  Rectangle dom;
  if (domain) {
    dom = *domain;
  } else if (cells.domain) {
    dom = *cells.domain;  // the generator's own domain
  } else {
    Point lo = cells.points[0], hi = cells.points[0];
    for (const Point& p : cells.points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    try {
      dom = Rectangle(lo.x(), lo.y(), hi.x(), hi.y());
    } catch (const InputError& e) {  // all points on one line: name the file
      throw InputError(source +
                       ": no FieldData 'domain', and the bounding box of the points: " + e.what());
    }
  }
  return PolygonMesh(dom, std::move(cells.points), std::move(cells.offsets),
                     std::move(cells.connectivity));
}

}  // namespace vorodg
