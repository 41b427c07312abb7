// Adding a study kind, measured: a toy kind defined in this file alone and registered with one
// line, run end to end through `vorodg run`'s entry point. It tiles each mesh of its scene's
// blocks and records the cells, h_avg and the covered area (the domain's: a closed form), through
// the harness's pieces only: the key table and reader, the mesh blocks, the run ids and seeds,
// the resumable run loop, and the writers of results.csv and summary.json.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/io/AtomicFile.hpp"
#include "core/meshgen/MeshFamily.hpp"
#include "core/schema/SceneKeyReader.hpp"
#include "verification/api/SceneStudy.hpp"
#include "verification/harness/EnsembleStudy.hpp"
#include "verification/harness/SceneVariants.hpp"
#include "verification/harness/StudyFiles.hpp"
#include "verification/harness/StudyKind.hpp"

namespace vorodg {
namespace {

namespace fs = std::filesystem;

struct TilingScene {
  std::string name;
  Rectangle domain;
  std::vector<SceneMesh> meshes;
};

struct TilingRecord {
  EnsembleRunId run;
  int cells = 0;
  double h_avg = 0.0, area = 0.0;
  bool complete = false;
  std::string failure;
};

const KeyTable& tiling_keys() {
  static const KeyTable table{
      "tiling",
      {key("study", "text", "convergence", "tiling", "the study kind"),
       key("name", "text", "the file name", "any text", "the scene's name"),
       key("domain", "[x0, y0, x1, y1]", "[0, 0, 4, 1]", kRectangleRange, "the tiled rectangle"),
       key("meshes", "array of mesh blocks", "(required)", "non-empty", "what to tile")},
      {}};
  return table;
}

TilingScene read_tiling(const std::string& text, const std::string& source) {
  const nlohmann::json root = parse_scene_json(text, source);  // the reader refers to it
  SceneKeyReader reader(tiling_keys(), root, source);
  SceneObject& top = reader.top();
  TilingScene s;
  top.text("study", "");
  s.name = top.text("name", source);
  s.domain = reader.rectangle(top, "domain", {0, 0, 4, 1});
  const nlohmann::json& meshes = top.at("meshes");
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    SceneObject m(meshes[i], "meshes[" + std::to_string(i) + "]", source);
    s.meshes.push_back(read_mesh(m, s.domain));
    m.finish();
  }
  top.finish();  // an unknown key is refused, naming it
  return s;
}

const std::vector<RecordField<TilingRecord>>& tiling_fields() {
  using R = TilingRecord;
  static const std::vector<RecordField<R>> fields = [] {
    std::vector<RecordField<R>> f = run_id_fields<R>();
    f.insert(f.end(), {field("cells", &R::cells), field("h_avg", &R::h_avg),
                       field("area", &R::area, {true, 15}), field("complete", &R::complete),
                       field("failure", &R::failure, kNotInCsv)});
    return f;
  }();
  return fields;
}

TilingRecord tile(const TilingScene& scene, const EnsembleRunId& id) {
  const GeneratedMesh g =
      generate_mesh(scene.meshes[id.mesh].spec(scene.domain, id.level, id.seed));
  TilingRecord r;
  r.run = id;
  r.cells = g.mesh.num_cells();
  r.h_avg = g.mesh.h_avg();
  for (int c = 0; c < r.cells; ++c) r.area += g.mesh.cell_area(c);
  r.complete = true;
  return r;
}

int run_tiling(const StudyCall& call) {
  const TilingScene scene = read_tiling(read_file(call.scene), call.scene.string());
  const auto result = run_study_records<TilingRecord>(
      scene.meshes, call.out, call.threads, call.progress, tiling_fields(),
      [&](const EnsembleRunId& id) { return tile(scene, id); },
      [](const TilingRecord& r) { return r.run.id() + ": " + std::to_string(r.cells) + " cells"; });
  write_results_csv(call.out, tiling_fields(), result.records);
  nlohmann::json summary = summary_head(scene.name, "tiling");
  summary["runs"] = result.records.size();
  write_summary(call.out, summary);
  return result.incomplete == 0 ? 0 : 3;
}

// The one registration line.
const bool registered = register_study_kind(
    {"tiling", "tiles a rectangle with each mesh block (a toy kind of the harness test)",
     [](const std::string& text, const std::string& source) {
       return read_tiling(text, source).name;
     },
     run_tiling, [] { return tiling_keys().keys; }});

fs::path write_scene(const fs::path& dir) {
  fs::create_directories(dir);
  const fs::path file = dir / "tiling.json";
  std::ofstream(file) << R"({"study": "tiling", "name": "toy tiling", "domain": [0, 0, 2, 1],
    "meshes": [{"family": "hex", "sizes": [0.5, 0.25], "realizations": 2, "seed": 7},
               {"family": "rcp", "sizes": [0.3], "realizations": 3, "seed": 11}]})";
  return file;
}

std::vector<std::string> lines_of(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

TEST(StudyKindSeam, AToyKindRegisteredInOneLineRunsEndToEndThroughTheHarness) {
  ASSERT_TRUE(registered);
  const fs::path dir = fs::temp_directory_path() / "vorodg_study_kind_seam";
  fs::remove_all(dir);
  SceneStudyOptions options;
  options.scene = write_scene(dir).string();
  options.out = (dir / "out").string();
  options.threads = 2;
  options.quiet = true;
  options.no_plots = true;
  ASSERT_EQ(run_scene_study(options), 0);

  // Seven runs: 2 levels x 2 realizations of hex, 1 x 3 of rcp, named as every kind names them.
  const std::vector<std::string> csv = lines_of(dir / "out" / "results.csv");
  ASSERT_EQ(csv.size(), 1u + 7u);
  EXPECT_EQ(csv[0], "id,mesh,level,realization,cells,h_avg,area,complete");
  EXPECT_EQ(csv[1].substr(0, 9), "hex-L0-R0");
  EXPECT_EQ(csv[7].substr(0, 9), "rcp-L0-R2");
  // Each tiling covers the domain: the area is the rectangle's to round-off.
  for (std::size_t i = 1; i < csv.size(); ++i) {
    std::stringstream row(csv[i]);
    std::vector<std::string> cells;
    for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
    ASSERT_EQ(cells.size(), 8u) << csv[i];
    EXPECT_NEAR(std::stod(cells[6]), 2.0, 2.0 * 1e-12) << csv[i];
  }
  const auto summary = nlohmann::json::parse(read_file(dir / "out" / "summary.json"));
  EXPECT_EQ(summary["scene"], "toy tiling");
  EXPECT_EQ(summary["study"], "tiling");
  EXPECT_EQ(summary["runs"], 7);

  // A rerun resumes: every run is in results.jsonl, so nothing runs and nothing is appended.
  const std::vector<std::string> before = lines_of(dir / "out" / "results.jsonl");
  ASSERT_EQ(before.size(), 7u);
  ASSERT_EQ(run_scene_study(options), 0);
  EXPECT_EQ(lines_of(dir / "out" / "results.jsonl"), before);

  // A line of a run the scene does not have (an older id) is kept, ignored and reported.
  std::ofstream(dir / "out" / "results.jsonl", std::ios::app) << R"({"id": "hex/L0/R0"})"
                                                              << "\n";
  testing::internal::CaptureStderr();
  ASSERT_EQ(run_scene_study(options), 0);
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_NE(err.find("holds 1 finished run(s) this scene does not have"), std::string::npos) << err;
  EXPECT_EQ(lines_of(dir / "out" / "results.jsonl").size(), 8u);
  fs::remove_all(dir);
}

TEST(StudyKindSeam, TheToyKindIsListedWithItsKeysAndItsNameIsRefusedTwice) {
  EXPECT_EQ(study_kinds().back().name, "tiling");
  EXPECT_NE(key_table_markdown(study_kind("tiling", "")).find("`meshes`"), std::string::npos);
  EXPECT_THROW(register_study_kind({"tiling", "again", {}, {}, {}}), InputError);
}

}  // namespace
}  // namespace vorodg
