#pragma once
// Runs the built `vorodg` program the way a user does (a shell, no standard input) and captures
// its exit code, signal, stdout and stderr: for the command-line tests.
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace vorodg::testing {

struct RunResult {
  int exit_code = -1;  // -1: did not exit normally (crashed)
  int signal = 0;
  std::string out, err;
  int err_lines() const {
    return static_cast<int>(std::count(err.begin(), err.end(), '\n')) +
           (!err.empty() && err.back() != '\n' ? 1 : 0);
  }
};

/// Single-quotes a shell word.
inline std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) {
    if (c == '\'')
      q.append("'\\''");
    else
      q.push_back(c);
  }
  q.push_back('\'');
  return q;
}

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

/// Runs `exe args...`, with its stdout and stderr captured through files in `scratch`.
inline RunResult run_program(const std::filesystem::path& exe, const std::vector<std::string>& args,
                             const std::filesystem::path& scratch) {
  std::string cmd = quote(exe.string());
  for (const auto& a : args) cmd.append(" ").append(quote(a));
  const auto out = scratch / "stdout.txt", err = scratch / "stderr.txt";
  cmd.append(" >").append(quote(out.string())).append(" 2>").append(quote(err.string()));
  cmd.append(" </dev/null");
  const int status = std::system(cmd.c_str());
  RunResult r;
  if (WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
  r.out = slurp(out);
  r.err = slurp(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return r;
}

}  // namespace vorodg::testing
