// .vtu import/export: bit-exact round trip, field arrays, deterministic text, parse errors (each an
// InputError with a one-line message naming the source), the malformed files of tests/data/bad,
// accepted cell types (triangle, polygon, pixel reordered, quad), domain from the bounding box,
// and atomic file writing.
#include "core/io/VtuMesh.hpp"

#include <gtest/gtest.h>

#include <ostream>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "core/io/AtomicFile.hpp"
#include "core/mesh/MeshValidator.hpp"
#include "core/meshgen/MeshFamily.hpp"
#include "core/util/Errors.hpp"

namespace vorodg {

namespace {

namespace fs = std::filesystem;

const fs::path kData = VORODG_TEST_DATA;

// A fresh, empty folder per test.
fs::path temp_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  fs::path dir = fs::temp_directory_path() / ("vorodg_test_VtuMesh_" + std::string(info->name()) +
                                              "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// A valid 2 x 2 grid file, with hooks to break it.
struct VtuParts {
  std::string root = "VTKFile";
  std::string grid_type = "UnstructuredGrid";
  std::string n_points = "9";
  std::string n_cells = "4";
  std::string points = "0 0 0 1 0 0 2 0 0 0 1 0 1 1 0 2 1 0 0 2 0 1 2 0 2 2 0";
  std::string points_format = "ascii";
  bool with_points = true;
  std::string connectivity = "0 1 4 3 1 2 5 4 3 4 7 6 4 5 8 7";
  std::string offsets = "4 8 12 16";
  std::string types = "7 7 7 7";
  std::string text() const {
    std::ostringstream os;
    os << "<?xml version=\"1.0\"?>\n"
       << "<" << root << " type=\"" << grid_type
       << "\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
       << "  <UnstructuredGrid>\n"
       << "    <Piece NumberOfPoints=\"" << n_points << "\" NumberOfCells=\"" << n_cells << "\">\n";
    if (with_points)
      os << "      <Points>\n"
         << "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\""
         << points_format << "\">\n          " << points << "\n        </DataArray>\n"
         << "      </Points>\n";
    os << "      <Cells>\n"
       << "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">"
       << connectivity << "</DataArray>\n"
       << "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">" << offsets
       << "</DataArray>\n"
       << "        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">" << types
       << "</DataArray>\n"
       << "      </Cells>\n"
       << "    </Piece>\n"
       << "  </UnstructuredGrid>\n"
       << "</" << root << ">\n";
    return os.str();
  }
};

void expect_input_error(const std::string& text, const std::string& what_case) {
  SCOPED_TRACE(what_case);
  try {
    parse_vtu(text, "memory.vtu");
    ADD_FAILURE() << "expected InputError for " << what_case;
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_FALSE(msg.empty());
    EXPECT_EQ(msg.find('\n'), std::string::npos) << "one line: " << msg;
    EXPECT_NE(msg.find("memory.vtu"), std::string::npos) << "names the source: " << msg;
  } catch (const std::exception& e) {
    ADD_FAILURE() << what_case << ": wrong exception type: " << e.what();
  }
}

PolygonMesh small_rcp() {
  MeshSpec s;
  s.family = MeshFamily::rcp;
  s.domain = Rectangle(0, 0, 1, 1);
  s.size = 0.05;
  s.seed = 77;
  return generate_mesh(s).mesh;
}

TEST(VtuMesh, ParsesTheBaseGrid) {
  const VtuCells cells = parse_vtu(VtuParts{}.text(), "memory.vtu");
  ASSERT_EQ(cells.points.size(), 9u);
  EXPECT_EQ(cells.points[5], Point(2, 1));
  EXPECT_EQ(cells.offsets, (std::vector<int>{0, 4, 8, 12, 16}));
  EXPECT_EQ(cells.connectivity, (std::vector<int>{0, 1, 4, 3, 1, 2, 5, 4, 3, 4, 7, 6, 4, 5, 8, 7}));
}

TEST(VtuMesh, RoundTripIsBitExact) {
  const PolygonMesh m = small_rcp();
  const fs::path dir = temp_dir();
  const fs::path file = dir / "rcp.vtu";
  write_vtu(file, m);
  ASSERT_TRUE(fs::exists(file));
  const Rectangle dom = m.domain();
  const PolygonMesh back = read_vtu(file, &dom);
  ASSERT_EQ(back.num_vertices(), m.num_vertices());
  for (int v = 0; v < m.num_vertices(); ++v) {
    ASSERT_EQ(back.vertex(v).x(), m.vertex(v).x()) << "vertex " << v;
    ASSERT_EQ(back.vertex(v).y(), m.vertex(v).y()) << "vertex " << v;
  }
  EXPECT_EQ(back.offsets(), m.offsets());
  EXPECT_EQ(back.cell_vertex_list(), m.cell_vertex_list());
  EXPECT_EQ(back.num_edges(), m.num_edges());
  for (int e = 0; e < m.num_edges(); ++e) EXPECT_EQ(back.edge(e).side, m.edge(e).side) << e;
  // Written again, the file is byte-identical.
  EXPECT_EQ(vtu_text(back), read_file(file));
  // Read without a domain: the bounding box, which for a generated mesh is the domain.
  const PolygonMesh bbox = read_vtu(file);
  EXPECT_EQ(bbox.domain().lo(), dom.lo());
  EXPECT_EQ(bbox.domain().hi(), dom.hi());
  EXPECT_TRUE(validate_mesh(bbox).ok()) << validate_mesh(bbox).summary();
  fs::remove_all(dir);
}

TEST(VtuMesh, CoordinatesUseShortestRoundTripFormatting) {
  // 0.1 is written as "0.1" (not 0.10000000000000001), 1/3 with all 17 digits it needs.
  const std::vector<Point> v{Point(0, 0), Point(0.1, 0), Point(0.1, 1.0 / 3.0),
                             Point(0, 1.0 / 3.0)};
  const PolygonMesh m(Rectangle(0, 0, 0.1, 1.0 / 3.0), v, {0, 4}, {0, 1, 2, 3});
  const std::string text = vtu_text(m, {}, VtuEncoding::ascii);
  EXPECT_NE(text.find("0.1"), std::string::npos);
  EXPECT_EQ(text.find("0.10000000000000001"), std::string::npos) << text;
  const VtuCells back = parse_vtu(text, "m.vtu");
  ASSERT_EQ(back.points.size(), 4u);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(back.points[i], v[i]);
}

TEST(VtuMesh, TextIsDeterministicAndDeclaresPolygons) {
  const PolygonMesh m = small_rcp();
  const std::string a = vtu_text(m);
  EXPECT_EQ(a, vtu_text(m));
  EXPECT_NE(a.find("UnstructuredGrid"), std::string::npos);
  EXPECT_NE(a.find("format=\"ascii\""), std::string::npos);
  EXPECT_NE(a.find("Name=\"connectivity\""), std::string::npos);
  EXPECT_NE(a.find("Name=\"offsets\""), std::string::npos);
  EXPECT_NE(a.find("Name=\"types\""), std::string::npos);
  // Every cell is a VTK_POLYGON (7).
  const VtuCells c = parse_vtu(a, "m.vtu");
  EXPECT_EQ(static_cast<int>(c.offsets.size()), m.num_cells() + 1);
}

TEST(VtuMesh, PointAndCellFieldsAppearWithTheirNames) {
  const PolygonMesh m = small_rcp();
  VtuFields f;
  VtuField disp{"displacement", 2, {}};
  for (int v = 0; v < m.num_vertices(); ++v) {
    disp.values.push_back(m.vertex(v).x());
    disp.values.push_back(-m.vertex(v).y());
  }
  VtuField id{"cell_id", 1, {}};
  for (int c = 0; c < m.num_cells(); ++c) id.values.push_back(c);
  VtuField vm{"von_mises", 1, std::vector<double>(m.num_cells(), 0.25)};
  f.point_data = {disp};
  f.cell_data = {id, vm};
  const std::string text = vtu_text(m, f);
  EXPECT_NE(text.find("<PointData"), std::string::npos);
  EXPECT_NE(text.find("<CellData"), std::string::npos);
  EXPECT_NE(text.find("Name=\"displacement\""), std::string::npos);
  EXPECT_NE(text.find("Name=\"cell_id\""), std::string::npos);
  EXPECT_NE(text.find("Name=\"von_mises\""), std::string::npos);
  // Point data lies inside <PointData>, cell data inside <CellData>.
  const auto pd = text.find("<PointData"), pd_end = text.find("</PointData>");
  const auto cd = text.find("<CellData"), cd_end = text.find("</CellData>");
  const auto disp_at = text.find("Name=\"displacement\"");
  const auto id_at = text.find("Name=\"cell_id\"");
  EXPECT_TRUE(pd < disp_at && disp_at < pd_end);
  EXPECT_TRUE(cd < id_at && id_at < cd_end);
  // Fields do not disturb the mesh.
  const VtuCells back = parse_vtu(text, "fields.vtu");
  EXPECT_EQ(back.points.size(), static_cast<std::size_t>(m.num_vertices()));
  EXPECT_EQ(static_cast<int>(back.offsets.size()), m.num_cells() + 1);
}

TEST(VtuMesh, WriteRejectsBadFieldsAndLeavesNoFile) {
  const PolygonMesh m = small_rcp();
  const fs::path dir = temp_dir();
  const fs::path file = dir / "bad_fields.vtu";
  VtuFields wrong_size;
  wrong_size.cell_data = {VtuField{"cell_id", 1, std::vector<double>(m.num_cells() - 1, 0.0)}};
  EXPECT_THROW(write_vtu(file, m, wrong_size), InputError);
  EXPECT_FALSE(fs::exists(file));
  VtuFields wrong_components;
  wrong_components.point_data = {VtuField{"u", 2, std::vector<double>(m.num_vertices(), 0.0)}};
  EXPECT_THROW(write_vtu(file, m, wrong_components), InputError);
  EXPECT_FALSE(fs::exists(file));
  VtuFields non_finite;
  non_finite.cell_data = {VtuField{"e", 1, std::vector<double>(m.num_cells(), 1.0)}};
  non_finite.cell_data[0].values[3] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(write_vtu(file, m, non_finite),
               NumericalError);  // a NaN result is a breakdown (exit 3)
  EXPECT_FALSE(fs::exists(file));
  // Nothing else was left behind (no temporary files).
  EXPECT_TRUE(fs::is_empty(dir));
  // A folder that does not exist.
  EXPECT_THROW(write_vtu(dir / "no" / "such" / "dir.vtu", m), InputError);
  fs::remove_all(dir);
}

TEST(VtuMesh, ParseErrorsAreInputErrorsWithOneLineMessages) {
  expect_input_error("", "empty text");
  expect_input_error("hello, not xml", "not XML");
  {
    const std::string t = VtuParts{}.text();
    expect_input_error(t.substr(0, t.size() / 2), "truncated XML");
  }
  {
    VtuParts p;
    p.root = "Mesh";
    expect_input_error(p.text(), "wrong root element");
  }
  {
    VtuParts p;
    p.grid_type = "PolyData";
    expect_input_error(p.text(), "wrong grid type");
  }
  {
    VtuParts p;
    p.with_points = false;
    expect_input_error(p.text(), "missing Points");
  }
  {
    VtuParts p;
    p.n_points = "12";
    expect_input_error(p.text(), "NumberOfPoints disagrees with the data");
  }
  {
    VtuParts p;
    p.points += " 3";
    expect_input_error(p.text(), "coordinate count not a multiple of 3");
  }
  {
    VtuParts p;
    p.n_cells = "5";
    expect_input_error(p.text(), "NumberOfCells disagrees with the offsets");
  }
  {
    VtuParts p;
    p.offsets = "4 8 12 17";
    expect_input_error(p.text(), "offsets disagree with the connectivity length");
  }
  {
    VtuParts p;
    p.offsets = "4 12 8 16";
    expect_input_error(p.text(), "decreasing offsets");
  }
  {
    VtuParts p;
    p.types = "7 7 7";
    expect_input_error(p.text(), "types count disagrees");
  }
  {
    VtuParts p;
    p.connectivity = "0 1 4 3 1 2 9 4 3 4 7 6 4 5 8 7";
    expect_input_error(p.text(), "connectivity index out of range");
  }
  {
    VtuParts p;
    p.connectivity = "0 1 4 3 1 2 -1 4 3 4 7 6 4 5 8 7";
    expect_input_error(p.text(), "negative connectivity index");
  }
  {
    VtuParts p;
    p.connectivity = "0 1 4 3 1 2 five 4 3 4 7 6 4 5 8 7";
    expect_input_error(p.text(), "non-numeric connectivity");
  }
  {
    VtuParts p;
    p.points = "0 0 0 1 0 0 2 0 0 0 1 0 nan 1 0 2 1 0 0 2 0 1 2 0 2 2 0";
    expect_input_error(p.text(), "NaN coordinate");
  }
  {
    VtuParts p;
    p.points = "0 0 0 1 0 0 2 0 0 0 1 0 1 inf 0 2 1 0 0 2 0 1 2 0 2 2 0";
    expect_input_error(p.text(), "infinite coordinate");
  }
  {
    VtuParts p;
    p.points_format = "binary";
    expect_input_error(p.text(), "binary format");
  }
  {
    VtuParts p;
    p.points_format = "appended";
    expect_input_error(p.text(), "appended format");
  }
  {
    VtuParts p;
    p.types = "7 7 10 7";
    expect_input_error(p.text(), "unsupported cell type (tetrahedron)");
  }
  {
    VtuParts p;
    p.offsets = "4 8 12 16";
    p.types = "7 7 9 5";  // a quad type with 4 vertices is fine; a triangle type with 4 is not
    expect_input_error(p.text(), "triangle cell with 4 vertices");
  }
}

TEST(VtuMesh, ErrorMessageNamesTheFileAndTheProblem) {
  VtuParts p;
  p.connectivity = "0 1 4 3 1 2 42 4 3 4 7 6 4 5 8 7";
  try {
    parse_vtu(p.text(), "mesh_in_question.vtu");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("mesh_in_question.vtu"), std::string::npos) << msg;
    EXPECT_NE(msg.find("42"), std::string::npos) << "should name the bad index: " << msg;
  }
}

TEST(VtuMesh, MalformedFilesInTestDataAreRejected) {
  const fs::path bad = kData / "bad";
  ASSERT_TRUE(fs::is_directory(bad)) << bad;
  int files = 0;
  for (const auto& entry : fs::directory_iterator(bad)) {
    if (entry.path().extension() != ".vtu") continue;
    ++files;
    SCOPED_TRACE(entry.path().filename().string());
    try {
      read_vtu(entry.path());
      ADD_FAILURE() << "accepted " << entry.path();
    } catch (const InputError& e) {
      const std::string msg = e.what();
      EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
      EXPECT_NE(msg.find(entry.path().filename().string()), std::string::npos)
          << "should name the file: " << msg;
    } catch (const std::exception& e) {
      ADD_FAILURE() << "wrong exception type: " << e.what();
    }
  }
  EXPECT_GE(files, 10);
}

TEST(VtuMesh, MissingFileIsAnInputError) {
  EXPECT_THROW(read_vtu(kData / "no_such_file.vtu"), InputError);
}

TEST(VtuMesh, AcceptsTrianglePolygonPixelAndQuadCells) {
  const fs::path file = kData / "good" / "mixed_cell_types.vtu";
  const VtuCells c = parse_vtu(read_file(file), file.string());
  ASSERT_EQ(c.offsets, (std::vector<int>{0, 4, 8, 11, 14}));
  // The pixel (0,1,4,5) in VTK's x-then-y order becomes the counter-clockwise loop (0,1,5,4).
  EXPECT_EQ(std::vector<int>(c.connectivity.begin(), c.connectivity.begin() + 4),
            (std::vector<int>{0, 1, 5, 4}));
  EXPECT_EQ(std::vector<int>(c.connectivity.begin() + 4, c.connectivity.end()),
            (std::vector<int>{1, 2, 6, 5, 2, 3, 7, 2, 7, 6}));
}

TEST(VtuMesh, ImportedMeshGetsBoundaryTagsFromItsBoundingBox) {
  // Points span [1,4] x [-1,0.5].
  const PolygonMesh m = read_vtu(kData / "good" / "mixed_cell_types.vtu");
  EXPECT_EQ(m.domain().x0(), 1.0);
  EXPECT_EQ(m.domain().y0(), -1.0);
  EXPECT_EQ(m.domain().x1(), 4.0);
  EXPECT_EQ(m.domain().y1(), 0.5);
  const auto report = validate_mesh(m);
  EXPECT_TRUE(report.ok()) << report.summary();
  std::map<Side, int> count;
  for (const MeshEdge& e : m.edges())
    if (e.on_boundary()) ++count[e.side];
  EXPECT_EQ(count[Side::none], 0);
  EXPECT_EQ(count[Side::bottom], 3);
  EXPECT_EQ(count[Side::top], 3);
  EXPECT_EQ(count[Side::left], 1);
  EXPECT_EQ(count[Side::right], 1);
  // With an explicit larger domain, the same edges lie on no side.
  const Rectangle bigger(0, -2, 5, 1);
  const PolygonMesh n = read_vtu(kData / "good" / "mixed_cell_types.vtu", &bigger);
  for (const MeshEdge& e : n.edges())
    if (e.on_boundary()) {
      EXPECT_EQ(e.side, Side::none);
    }
  EXPECT_FALSE(validate_mesh(n).ok());
}

TEST(AtomicFile, WritesReadsAndReplaces) {
  const fs::path dir = temp_dir();
  const fs::path file = dir / "a.txt";
  write_file_atomically(file, "first");
  EXPECT_EQ(read_file(file), "first");
  write_file_atomically(file, "second, longer contents\n");
  EXPECT_EQ(read_file(file), "second, longer contents\n");
  // Only the target remains in the folder.
  int entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++entries;
  EXPECT_EQ(entries, 1);
  EXPECT_THROW(write_file_atomically(dir / "missing" / "b.txt", "x"), InputError);
  EXPECT_THROW(read_file(dir / "missing.txt"), InputError);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace vorodg
