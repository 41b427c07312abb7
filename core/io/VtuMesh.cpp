#include "core/io/VtuMesh.hpp"

#include <pugixml.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

#include "core/io/AtomicFile.hpp"
#include "core/util/Errors.hpp"

namespace vorodg {
namespace {

constexpr int kVtkTriangle = 5, kVtkPolygon = 7, kVtkPixel = 8, kVtkQuad = 9;

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
  std::string take() { return std::move(text_); }

 private:
  std::string text_;
};

void write_field(TextBuilder& out, const VtuField& field, std::size_t count, const char* where) {
  if (field.values.size() != count * field.components)
    throw InputError(std::string("vtu ") + where + " field '" + field.name + "': " +
                     std::to_string(field.values.size()) + " values, expected " +
                     std::to_string(count * field.components));
  for (double v : field.values)
    if (!std::isfinite(v))
      throw NumericalError(std::string("vtu ") + where + " field '" + field.name +
                           "' holds a non-finite value; refusing to write it");
  out << "        <DataArray type=\"Float64\" Name=\"" << field.name
      << "\" NumberOfComponents=\"" << std::to_string(field.components) << "\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < field.values.size(); ++i) {
    out << ((i % field.components == 0) ? (i ? "\n          " : "          ") : " ");
    out.number(field.values[i]);
  }
  out << "\n        </DataArray>\n";
}

}  // namespace

std::string vtu_text(const PolygonMesh& mesh, const VtuFields& fields) {
  TextBuilder out(64 * static_cast<std::size_t>(mesh.num_vertices() + mesh.num_cells()) + 4096);
  out << "<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
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
  for (const auto& f : fields.point_data) write_field(out, f, mesh.num_vertices(), "point");
  out << "      </PointData>\n      <CellData>\n";
  for (const auto& f : fields.cell_data) write_field(out, f, mesh.num_cells(), "cell");
  out << "      </CellData>\n      <Points>\n"
         "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const Point& p : mesh.vertices()) {
    out << "          ";
    out.number(p.x());
    out << " ";
    out.number(p.y());
    out << " 0\n";
  }
  out << "        </DataArray>\n      </Points>\n      <Cells>\n"
         "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (int c = 0; c < mesh.num_cells(); ++c) {
    out << "         ";
    for (int v : mesh.cell_vertices(c)) {
      out << " ";
      out.number(static_cast<long long>(v));
    }
    out << "\n";
  }
  out << "        </DataArray>\n"
         "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (int c = 0; c < mesh.num_cells(); ++c) {
    out << ((c % 16 == 0) ? (c ? "\n          " : "          ") : " ");
    out.number(static_cast<long long>(mesh.offsets()[c + 1]));
  }
  out << "\n        </DataArray>\n"
         "        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (int c = 0; c < mesh.num_cells(); ++c)
    out << ((c % 32 == 0) ? (c ? "\n          7" : "          7") : " 7");
  out << "\n        </DataArray>\n      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  return out.take();
}

void write_vtu(const std::filesystem::path& path, const PolygonMesh& mesh, const VtuFields& fields) {
  write_file_atomically(path, vtu_text(mesh, fields));
}

namespace {

class VtuParser {
 public:
  explicit VtuParser(std::string source) : source_(std::move(source)) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(source_ + ": " + what);
  }

  template <class T>
  std::vector<T> numbers(const pugi::xml_node& array, const std::string& name) const {
    const std::string format = array.attribute("format").as_string("ascii");
    if (format != "ascii")
      fail("DataArray '" + name + "' has format=\"" + format +
           "\", expected \"ascii\" (binary and appended data are not supported)");
    const char* p = array.child_value();
    const char* end = p + std::char_traits<char>::length(p);
    std::vector<T> values;
    while (true) {
      while (p < end && (*p == ' ' || *p == '\n' || *p == '\t' || *p == '\r')) ++p;
      if (p == end) break;
      T x{};
      auto [next, ec] = std::from_chars(p, end, x);
      if (ec != std::errc() || (next < end && !std::isspace(static_cast<unsigned char>(*next))))
        fail("DataArray '" + name + "' entry " + std::to_string(values.size()) +
             " is not a valid number");
      if constexpr (std::is_floating_point_v<T>)
        if (!std::isfinite(x))
          fail("DataArray '" + name + "' entry " + std::to_string(values.size()) +
               " is not finite");
      values.push_back(x);
      p = next;
    }
    return values;
  }

  pugi::xml_node named_array(const pugi::xml_node& parent, const char* name) const {
    for (auto a : parent.children("DataArray"))
      if (std::string(a.attribute("Name").as_string()) == name) return a;
    fail(std::string("<Cells> has no DataArray Name=\"") + name + "\"");
  }

 private:
  std::string source_;
};

long long count_attribute(const VtuParser& parser, const pugi::xml_node& piece, const char* name) {
  const auto attr = piece.attribute(name);
  long long value = -1;
  const std::string text = attr.as_string();
  auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (!attr || ec != std::errc() || value < 0 || value > std::numeric_limits<int>::max() / 8)
    parser.fail(std::string("<Piece> attribute ") + name + "=\"" + text +
                "\", expected a non-negative integer");
  return value;
}

}  // namespace

VtuCells parse_vtu(const std::string& text, const std::string& source) {
  VtuParser parser(source);
  pugi::xml_document doc;
  const auto parsed = doc.load_buffer(text.data(), text.size());
  if (!parsed)
    parser.fail(std::string("not well-formed XML (") + parsed.description() + " at byte " +
                std::to_string(parsed.offset) + ")");
  const auto root = doc.child("VTKFile");
  if (!root || std::string(root.attribute("type").as_string()) != "UnstructuredGrid")
    parser.fail("expected a <VTKFile type=\"UnstructuredGrid\"> root element");
  const auto piece = root.child("UnstructuredGrid").child("Piece");
  if (!piece) parser.fail("no <UnstructuredGrid><Piece> element");
  if (piece.next_sibling("Piece")) parser.fail("more than one <Piece>, expected exactly one");
  const long long n_points = count_attribute(parser, piece, "NumberOfPoints");
  const long long n_cells = count_attribute(parser, piece, "NumberOfCells");

  const auto points_array = piece.child("Points").child("DataArray");
  if (!points_array) parser.fail("no <Points><DataArray> element");
  const int components = points_array.attribute("NumberOfComponents").as_int(1);
  if (components != 2 && components != 3)
    parser.fail("<Points> has NumberOfComponents=" + std::to_string(components) + ", expected 3");
  const auto xyz = parser.numbers<double>(points_array, "Points");
  if (static_cast<long long>(xyz.size()) != n_points * components)
    parser.fail("<Points> holds " + std::to_string(xyz.size()) + " numbers, expected " +
                std::to_string(n_points * components) + " for NumberOfPoints=" +
                std::to_string(n_points));

  const auto cells = piece.child("Cells");
  if (!cells) parser.fail("no <Cells> element");
  const auto conn = parser.numbers<long long>(parser.named_array(cells, "connectivity"), "connectivity");
  const auto offs = parser.numbers<long long>(parser.named_array(cells, "offsets"), "offsets");
  const auto types = parser.numbers<int>(parser.named_array(cells, "types"), "types");
  if (static_cast<long long>(offs.size()) != n_cells || static_cast<long long>(types.size()) != n_cells)
    parser.fail("offsets/types hold " + std::to_string(offs.size()) + "/" +
                std::to_string(types.size()) + " entries, expected NumberOfCells=" +
                std::to_string(n_cells));

  VtuCells out;
  for (auto a : root.child("UnstructuredGrid").child("FieldData").children("DataArray"))
    if (std::string(a.attribute("Name").as_string()) == "domain") {
      const auto v = parser.numbers<double>(a, "domain");
      if (v.size() != 4) parser.fail("FieldData 'domain' holds " + std::to_string(v.size()) +
                                     " numbers, expected 4 (x0 y0 x1 y1)");
      try {
        out.domain = Rectangle(v[0], v[1], v[2], v[3]);
      } catch (const InputError& e) {
        parser.fail(std::string("FieldData 'domain': ") + e.what());
      }
    }
  out.points.reserve(n_points);
  for (long long i = 0; i < n_points; ++i) out.points.emplace_back(xyz[components * i], xyz[components * i + 1]);
  out.offsets.reserve(n_cells + 1);
  out.offsets.push_back(0);
  out.connectivity.reserve(conn.size());
  long long begin = 0;
  for (long long c = 0; c < n_cells; ++c) {
    const long long end = offs[c];
    const std::string cell = "cell " + std::to_string(c);
    if (end <= begin || end > static_cast<long long>(conn.size()))
      parser.fail(cell + ": offset " + std::to_string(end) + " out of order or beyond the " +
                  std::to_string(conn.size()) + " connectivity entries");
    const int t = types[c];
    const long long n = end - begin;
    const bool ok = (t == kVtkPolygon && n >= 3) || (t == kVtkTriangle && n == 3) ||
                    ((t == kVtkQuad || t == kVtkPixel) && n == 4);
    if (!ok)
      parser.fail(cell + ": VTK cell type " + std::to_string(t) + " with " + std::to_string(n) +
                  " vertices, expected a polygon (7), triangle (5), pixel (8) or quad (9)");
    std::vector<int> loop;
    for (long long k = begin; k < end; ++k) {
      if (conn[k] < 0 || conn[k] >= n_points)
        parser.fail(cell + ": vertex index " + std::to_string(conn[k]) + " out of range 0.." +
                    std::to_string(n_points - 1));
      loop.push_back(static_cast<int>(conn[k]));
    }
    if (t == kVtkPixel) std::swap(loop[2], loop[3]);  // pixels are numbered row by row
    out.connectivity.insert(out.connectivity.end(), loop.begin(), loop.end());
    out.offsets.push_back(static_cast<int>(out.connectivity.size()));
    begin = end;
  }
  return out;
}

PolygonMesh read_vtu(const std::filesystem::path& path, const Rectangle* domain) {
  return read_vtu_text(read_file(path), path.string(), domain);
}

PolygonMesh read_vtu_text(const std::string& text, const std::string& source, const Rectangle* domain) {
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
      throw InputError(source + ": no FieldData 'domain', and the bounding box of the points: " + e.what());
    }
  }
  return PolygonMesh(dom, std::move(cells.points), std::move(cells.offsets),
                     std::move(cells.connectivity));
}

}  // namespace vorodg
