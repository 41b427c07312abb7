// Test helper of meshio_roundtrip.py: reads a .vtu written by vorodg (points, cells, domain, every
// point and cell array) and writes it again with vorodg's writer in the encoding asked for, so
// the script can compare meshio's reading of a binary file with its reading of the same data as
// exact ASCII text. Usage: vtu_reencode IN OUT ascii|binary
#include <iostream>
#include <string>

#include "core/io/AtomicFile.hpp"
#include "core/io/VtuMesh.hpp"
#include "core/util/Errors.hpp"

int main(int argc, char** argv) {
  using namespace vorodg;
  const std::string mode = argc == 4 ? argv[3] : "";
  if (mode != "ascii" && mode != "binary") {
    std::cerr << "usage: vtu_reencode IN OUT ascii|binary\n";
    return 2;
  }
  try {
    VtuCells cells = parse_vtu(read_file(argv[1]), argv[1]);
    if (!cells.domain) throw InputError(std::string(argv[1]) + ": no FieldData 'domain'");
    const PolygonMesh mesh(*cells.domain, std::move(cells.points), std::move(cells.offsets),
                           std::move(cells.connectivity));
    write_vtu(argv[2], mesh, cells.fields,
              mode == "ascii" ? VtuEncoding::ascii : VtuEncoding::binary_zlib);
  } catch (const std::exception& e) {
    std::cerr << "vtu_reencode: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
