#include "verification/cli/CliSupport.hpp"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"
#include "verification/model/Choices.hpp"

namespace vorodg {
CLI::Validator finite_number() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const char* first = text.data() + (text.starts_with('+') ? 1 : 0);
        const char* last = text.data() + text.size();
        double x = 0.0;
        const auto [end, ec] = std::from_chars(first, last, x);
        if (ec == std::errc::result_out_of_range)
          return "'" + text + "' is out of range, expected a finite number";
        if (ec != std::errc() || end != last) return "'" + text + "' is not a number";
        if (!std::isfinite(x)) return "'" + text + "', expected a finite number";
        return {};
      },
      "");
}

CLI::Validator unsigned_integer() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        std::uint64_t x = 0;
        const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), x);
        if (ec != std::errc() || end != text.data() + text.size())
          return "'" + text + "', expected an integer from 0 to 18446744073709551615";
        return {};
      },
      "");
}

void add_vtu_output_options(CLI::App& cmd, VtuOutputOptions& o, const std::string& what) {
  cmd.add_option("-o,--output", o.path, what + " to write (.vtu)");
  cmd.add_flag("--ascii", o.ascii, "Write ASCII .vtu (default: zlib-compressed binary)");
}

void add_mesh_source_options(CLI::App& cmd, MeshSourceOptions& o) {
  cmd.add_option("--family", o.family, choice_alternatives(generated_family_choices()))
      ->capture_default_str();
  cmd.add_option("--domain", o.domain, "Rectangle x0,y0,x1,y1")->capture_default_str();
  cmd.add_option("--d", o.d, "rcp, tri: minimum distance between seeds")->check(finite_number());
  cmd.add_option("--h", o.h, "hex, perturbed-hex: hexagon spacing; quad: edge length")
      ->check(finite_number());
  cmd.add_option("--r", o.r, "perturbed-hex: perturbation, fraction of the shortest edge")
      ->capture_default_str()
      ->check(finite_number());
  cmd.add_option("--seed", o.seed, "Random seed")->capture_default_str()->check(unsigned_integer());
  cmd.add_option("--regularize", o.regularize,
                 "rcp: collapse edges shorter than this times d (0: keep the raw Voronoi mesh)")
      ->capture_default_str()
      ->check(finite_number());
}

void echo_options(const std::string& prefix, const CLI::App& command,
                  const std::map<std::string, std::string>& resolved) {
  std::ostringstream os;
  os << prefix;
  for (const CLI::Option* opt : command.get_options()) {
    if (opt->get_name() == "--help") continue;
    if (opt->get_positional()) {
      if (opt->count()) os << " " << opt->as<std::string>();
      continue;
    }
    if (opt->get_expected_max() == 0) {  // a flag: shown when set
      if (opt->count()) os << " " << opt->get_name();
      continue;
    }
    const auto given = resolved.find(opt->get_name());
    const std::string value = opt->count()              ? opt->as<std::string>()
                              : given != resolved.end() ? given->second
                                                        : opt->get_default_str();
    if (value.empty()) continue;
    os << " " << opt->get_name() << " " << value;
  }
  std::cout << "# " << os.str() << "\n";
}

void check_output_folder(const std::string& path, const char* option) {
  if (path.empty()) return;
  const std::filesystem::path p(path);
  const auto folder = p.has_parent_path() ? p.parent_path() : std::filesystem::path(".");
  std::error_code ec;
  if (!std::filesystem::is_directory(folder, ec))
    throw InputError(
        std::string(option) + " '" + path + "': expected an existing folder, but '" +
        folder.string() + "'" +
        (std::filesystem::exists(folder, ec) ? " is not a folder" : " does not exist"));
}

}  // namespace vorodg
