// .vtu data-array encodings: base64, the binary writer (zlib blocks, deterministic, exact round
// trip against the ASCII writer), and the reader on files as VTK and meshio write them (inline
// base64 or appended raw/base64 data, compressed or not, UInt32/UInt64 headers, Float32 points,
// Int32..UInt64 indices, big-endian), and on corrupted binary data: one InputError line naming
// the file and the array each.
#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <vector>

#include "core/io/Base64.hpp"
#include "core/io/VtuMesh.hpp"
#include "core/meshgen/MeshFamily.hpp"
#include "core/util/Errors.hpp"
#include "support/VtuTestFiles.hpp"

namespace vorodg {
namespace {

using testing::ArrayMode;
using testing::VtuFileBuilder;
using testing::VtuFileSpec;

const std::vector<Point> kGrid{Point(0, 0), Point(1, 0), Point(2, 0), Point(0, 1), Point(1, 1),
                               Point(2, 1), Point(0, 2), Point(1, 2), Point(2, 2)};

std::string encode(std::string_view s) {
  std::string out;
  base64_append(s, out);
  return out;
}

std::string decode_all(std::string_view text, std::string* error = nullptr) {
  Base64Decoder d(text);
  std::string out;
  d.read(1000, out);
  if (error) *error = d.error();
  return out;
}

PolygonMesh mesh_of(MeshFamily family, double size, double x1) {
  MeshSpec s;
  s.family = family;
  s.domain = Rectangle(0, 0, x1, 1);
  s.size = size;
  s.seed = 5;
  return generate_mesh(s).mesh;
}

VtuFields fields_of(const PolygonMesh& m) {
  VtuFields f;
  VtuField u{"displacement", 3, {}}, id{"cell_id", 1, {}}, s{"stress", 3, {}};
  for (const Point& p : m.vertices())
    u.values.insert(u.values.end(), {p.x() / 3, -p.y() * 1e-7, 0});
  for (int c = 0; c < m.num_cells(); ++c) {
    id.values.push_back(c);
    s.values.insert(s.values.end(), {1.0 / (c + 1), -std::numeric_limits<double>::min(), 1e300});
  }
  f.point_data = {u};
  f.cell_data = {id, s};
  return f;
}

void expect_same_fields(const std::vector<VtuField>& a, const std::vector<VtuField>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].name, b[i].name);
    EXPECT_EQ(a[i].components, b[i].components) << a[i].name;
    EXPECT_EQ(a[i].values, b[i].values) << a[i].name;  // bit for bit
  }
}

void expect_grid(const VtuCells& c) {
  EXPECT_EQ(c.points, kGrid);
  EXPECT_EQ(c.offsets, (std::vector<int>{0, 4, 8, 12, 16}));
  EXPECT_EQ(c.connectivity, (std::vector<int>{0, 1, 4, 3, 1, 2, 5, 4, 3, 4, 7, 6, 4, 5, 8, 7}));
  ASSERT_EQ(c.fields.cell_data.size(), 1u);
  EXPECT_EQ(c.fields.cell_data[0].name, "pressure");
  EXPECT_EQ(c.fields.cell_data[0].values, (std::vector<double>{1.5, -2.25, 1e-300, 3}));
}

/// parse_vtu must throw an InputError of one line naming the file and containing `mention`.
void expect_error(const std::string& text, const std::string& mention) {
  SCOPED_TRACE(mention);
  try {
    parse_vtu(text, "broken.vtu");
    ADD_FAILURE() << "accepted a file that should fail with: " << mention;
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
    EXPECT_EQ(msg.rfind("broken.vtu: ", 0), 0u) << msg;
    EXPECT_NE(msg.find(mention), std::string::npos) << msg;
  }
}

TEST(Base64, KnownVectorsAndConcatenatedGroups) {
  EXPECT_EQ(encode(""), "");
  EXPECT_EQ(encode("f"), "Zg==");
  EXPECT_EQ(encode("fo"), "Zm8=");
  EXPECT_EQ(encode("foo"), "Zm9v");
  EXPECT_EQ(encode("foobar"), "Zm9vYmFy");
  EXPECT_EQ(encode(std::string("\xff\xfe\x00", 3)), "//4A");
  EXPECT_EQ(decode_all("Zm9vYmFy"), "foobar");
  EXPECT_EQ(decode_all(" Zm9v\n Ym\tFy \r\n"), "foobar");
  EXPECT_EQ(decode_all("Zg==Zm8=Zm9v"), "ffofoo");  // separately padded parts, as VTK writes
  std::string error;
  EXPECT_EQ(decode_all("Zm9v Zm", &error), "foo");
  EXPECT_NE(error.find("ends inside a group"), std::string::npos) << error;
  decode_all("Zm9v*m9v", &error);
  EXPECT_NE(error.find("invalid base64 character '*' at character 4"), std::string::npos) << error;
  decode_all("Z=9v", &error);
  EXPECT_NE(error.find("misplaced base64 padding"), std::string::npos) << error;
  std::string all(256, '\0');
  for (int i = 0; i < 256; ++i) all[i] = static_cast<char>(i);
  EXPECT_EQ(decode_all(encode(all)), all);
}

TEST(VtuEncoding, BinaryAndAsciiRoundTripsAreBitExact) {
  // 2500 quads: the points (60 kB) and every array span several 32 kB zlib blocks.
  for (const PolygonMesh& m :
       {mesh_of(MeshFamily::rcp, 0.08, 2), mesh_of(MeshFamily::quad, 0.02, 1)}) {
    const VtuFields f = fields_of(m);
    for (VtuEncoding enc : {VtuEncoding::ascii, VtuEncoding::binary_zlib}) {
      const std::string text = vtu_text(m, f, enc);
      const VtuCells c = parse_vtu(text, "rt.vtu");
      EXPECT_EQ(c.points, m.vertices());
      EXPECT_EQ(c.offsets, m.offsets());
      EXPECT_EQ(c.connectivity, m.cell_vertex_list());
      ASSERT_TRUE(c.domain.has_value());
      EXPECT_EQ(c.domain->hi(), m.domain().hi());
      expect_same_fields(c.fields.point_data, f.point_data);
      expect_same_fields(c.fields.cell_data, f.cell_data);
      EXPECT_EQ(text, vtu_text(m, f, enc)) << "deterministic";
    }
  }
}

TEST(VtuEncoding, BinaryIsTheDefaultAndDeclaresItsLayout) {
  const PolygonMesh m = mesh_of(MeshFamily::quad, 0.25, 1);
  const std::string text = vtu_text(m);
  EXPECT_EQ(text, vtu_text(m, {}, VtuEncoding::binary_zlib));
  EXPECT_NE(text.find("header_type=\"UInt64\" compressor=\"vtkZLibDataCompressor\""),
            std::string::npos);
  EXPECT_NE(text.find("Name=\"connectivity\" format=\"appended\" offset=\""), std::string::npos);
  EXPECT_NE(text.find("<AppendedData encoding=\"raw\">\n   _"), std::string::npos);
  // The domain stays readable text.
  EXPECT_NE(text.find("Name=\"domain\" NumberOfTuples=\"4\" format=\"ascii\"> 0 0 1 1 <"),
            std::string::npos);
  const std::string ascii = vtu_text(m, {}, VtuEncoding::ascii);
  EXPECT_EQ(ascii.find("format=\"appended\""), std::string::npos);
  EXPECT_EQ(ascii.find("AppendedData"), std::string::npos);
  EXPECT_EQ(ascii.find("compressor"), std::string::npos);
}

TEST(VtuEncoding, BinaryIsSmallerThanAscii) {
  const PolygonMesh m = mesh_of(MeshFamily::rcp, 0.03, 2);
  const VtuFields f{{}, {VtuField{"cell_id", 1, fields_of(m).cell_data[0].values}}};
  const std::size_t ascii = vtu_text(m, f, VtuEncoding::ascii).size();
  const std::size_t binary = vtu_text(m, f).size();
  // 3.2x on a 1e5-cell mesh (docs/meshes.md); a margin for this small one.
  EXPECT_LT(2.5 * binary, ascii) << binary << " vs " << ascii;
}

TEST(VtuEncoding, WriterChecksFieldsInEveryEncoding) {
  const PolygonMesh m = mesh_of(MeshFamily::quad, 0.5, 1);
  for (VtuEncoding enc : {VtuEncoding::ascii, VtuEncoding::binary_zlib}) {
    VtuFields nan{{}, {VtuField{"e", 1, std::vector<double>(m.num_cells(), 1.0)}}};
    nan.cell_data[0].values[1] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(vtu_text(m, nan, enc), NumericalError);
    const VtuFields short_field{{VtuField{"u", 3, std::vector<double>(3, 0.0)}}, {}};
    EXPECT_THROW(vtu_text(m, short_field, enc), InputError);
  }
}

TEST(VtuEncoding, ReadsEveryBinaryLayout) {
  for (ArrayMode mode : {ArrayMode::binary, ArrayMode::appended_raw, ArrayMode::appended_base64})
    for (const char* header : {"UInt32", "UInt64"})
      for (bool zlib : {false, true})
        for (bool big : {false, true}) {
          VtuFileSpec s;
          s.mode = mode;
          s.header_type = header;
          s.zlib = zlib;
          s.big_endian = big;
          SCOPED_TRACE(::testing::Message() << "mode " << static_cast<int>(mode) << " " << header
                                            << (zlib ? " zlib" : " raw") << (big ? " BE" : " LE"));
          expect_grid(parse_vtu(VtuFileBuilder(s).text(), "layout.vtu"));
        }
}

TEST(VtuEncoding, ReadsValueTypesAndMeshioUncompressedLayout) {
  for (const char* index : {"Int32", "Int64", "UInt32", "UInt64"}) {
    VtuFileSpec s;
    s.index_type = index;
    s.point_type = "Float32";  // the grid's coordinates are exact in single precision
    SCOPED_TRACE(index);
    expect_grid(parse_vtu(VtuFileBuilder(s).text(), "types.vtu"));
  }
  VtuFileSpec meshio;  // meshio: uncompressed, header and data in one base64 text, UInt32
  meshio.zlib = false;
  meshio.header_type = "UInt32";
  meshio.header_apart = false;
  expect_grid(parse_vtu(VtuFileBuilder(meshio).text(), "meshio.vtu"));
}

TEST(VtuEncoding, ReadsMeshesThroughReadVtuText) {
  VtuFileSpec s;
  s.mode = ArrayMode::appended_raw;
  const PolygonMesh m = read_vtu_text(VtuFileBuilder(s).text(), "appended.vtu");
  EXPECT_EQ(m.num_cells(), 4);
  EXPECT_EQ(m.domain().hi(), Point(2, 2));
}

VtuFileSpec broken(const std::string& array, std::function<void(std::string&, std::string&)> f,
                   ArrayMode mode = ArrayMode::binary) {
  VtuFileSpec s;
  s.mode = mode;
  s.break_array = array;
  s.breaker = std::move(f);
  return s;
}

TEST(VtuEncoding, CorruptBinaryDataIsAnInputErrorNamingTheArray) {
  auto text = [](VtuFileSpec s) { return VtuFileBuilder(std::move(s)).text(); };
  std::string t = text({});
  t.replace(t.find("format=\"binary\">\n          ") + 30, 1, "#");
  expect_error(t, "DataArray 'pressure' (format=\"binary\"): invalid base64 character '#'");
  expect_error(text(broken("offsets", [](auto& h, auto&) { h.resize(12); })), "'offsets'");
  expect_error(text(broken("Points", [](auto&, auto& d) { d[d.size() / 2] ^= 0x55; })),
               "DataArray 'Points' (format=\"binary\"): zlib block");
  expect_error(text(broken("Points", [](auto& h, auto&) { h[8] = 10; })), "do not add up");
  expect_error(text(broken("types", [](auto& h, auto&) { h[16] = 3; })), "inflates to");
  expect_error(text(broken("connectivity", [](auto& h, auto&) { h[0] = 100; })),
               "'connectivity' (format=\"binary\"): the compression header announces 100 blocks");
  expect_error(text(broken("Points", [](auto& h, auto&) { h[26] = 1; })), "sizes do not add up");
  VtuFileSpec plain = broken("Points", [](auto& h, auto&) { h[1] = 7; });
  plain.zlib = false;
  expect_error(text(plain), "'Points' (format=\"binary\"): the header announces 2008 bytes");
  plain.breaker = [](auto& h, auto& d) { d.pop_back(), h[0] -= 1; };
  expect_error(text(plain), "215 bytes, not a whole number of Float64 values");
  // Appended raw data: the last array without its data (what follows is the 3 bytes "\n  ").
  plain.mode = ArrayMode::appended_raw;
  plain.break_array = "types";
  plain.breaker = [](auto&, auto& d) { d.clear(); };
  expect_error(text(plain),
               "'types' (format=\"appended\"): the header announces 4 bytes, but at most 3");
  // Base64 padding hides the missing byte from the size check; the read itself finds it.
  plain.mode = ArrayMode::binary;
  plain.break_array = "Points";
  plain.breaker = [](auto&, auto& d) { d.pop_back(); };
  expect_error(text(plain),
               "'Points' (format=\"binary\"): the array data is cut short (215 of 216");
}

TEST(VtuEncoding, UnsupportedLayoutsAndTypesAreNamed) {
  auto text = [](VtuFileSpec s) { return VtuFileBuilder(std::move(s)).text(); };
  auto replaced = [](std::string t, const std::string& from, const std::string& to) {
    t.replace(t.find(from), from.size(), to);
    return t;
  };
  const std::string good = text({});
  expect_error(replaced(good, "UInt64", "UInt16"), "header_type=\"UInt16\" is not supported");
  expect_error(replaced(good, "vtkZLibDataCompressor", "vtkLZ4DataCompressor"),
               "compressor=\"vtkLZ4DataCompressor\" is not supported");
  expect_error(replaced(good, "\"LittleEndian\"", "\"Middle\""), "byte_order=\"Middle\"");
  expect_error(
      replaced(good, "type=\"Float64\" Name=\"Points\"", "type=\"String\" Name=\"Points\""),
      "DataArray 'Points' (format=\"binary\") has type=\"String\"");
  VtuFileSpec floats;
  floats.index_type = "Int64";
  expect_error(replaced(text(floats), "Int64\" Name=\"offsets", "Float64\" Name=\"offsets"),
               "DataArray 'offsets' has type=\"Float64\", expected an integer type");
  // The first index, 0, becomes 2^64 - 1: out of range of a signed index.
  VtuFileSpec huge =
      broken("connectivity", [](auto&, auto& d) { std::fill(d.begin(), d.begin() + 8, '\xff'); });
  huge.zlib = false;
  huge.index_type = "UInt64";
  expect_error(text(huge), "'connectivity' entry 0 (18446744073709551615) is out of range");
  VtuFileSpec nan =
      broken("Points", [](auto&, auto& d) { std::fill(d.begin() + 16, d.begin() + 24, '\xff'); });
  nan.zlib = false;
  expect_error(text(nan), "DataArray 'Points' entry 2 is not finite");
}

TEST(VtuEncoding, AppendedDataErrorsAreNamed) {
  VtuFileSpec s;
  s.mode = ArrayMode::appended_raw;
  const std::string good = VtuFileBuilder(s).text();
  auto replaced = [&](const std::string& from, const std::string& to) {
    std::string t = good;
    t.replace(t.find(from), from.size(), to);
    return t;
  };
  expect_error(replaced("offset=\"0\"", "offset=\"99999\""),
               "'pressure' (format=\"appended\") has offset 99999, beyond the");
  expect_error(replaced("offset=\"0\"", "offset=\"-1\""), "offset=\"-1\", expected a non-negative");
  expect_error(replaced("encoding=\"raw\"", "encoding=\"hex\""), "encoding=\"hex\"");
  expect_error(replaced("   _", "   x"), "<AppendedData> does not begin with '_'");
  expect_error(good.substr(0, good.find("</AppendedData>")), "no closing </AppendedData>");
  const std::string no_data = good.substr(0, good.find("  <AppendedData")) + "</VTKFile>\n";
  expect_error(no_data, "'Points' (format=\"appended\") but the file has no <AppendedData>");
}

TEST(VtuEncoding, FieldArraysAreCheckedAgainstTheirCounts) {
  VtuFileSpec s;
  s.zlib = false;
  std::string t = VtuFileBuilder(s).text();
  const std::string from = "Name=\"pressure\"";
  t.replace(t.find(from), from.size(), from + " NumberOfComponents=\"2\"");
  expect_error(t, "CellData array 'pressure' holds 4 numbers, expected 8");
}

}  // namespace
}  // namespace vorodg
