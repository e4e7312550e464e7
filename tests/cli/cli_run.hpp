#pragma once
// Running the `mesochain` binary from the CLI tests, and reading what it wrote.
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace mesochain::testing {

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

inline nlohmann::json readJson(const std::filesystem::path& p) {
  std::ifstream in(p);
  return nlohmann::json::parse(in);
}

// Runs `mesochain ARGS` in `dir` with one OpenMP thread and CI=true (no progress bars); returns
// its exit code (-1 if it did not exit) and fills `output` with its stdout and stderr, which
// are kept in dir/log.txt.
inline int runMesochain(const std::string& args, const std::filesystem::path& dir,
                        std::string& output) {
  const std::filesystem::path log = dir / "log.txt";
  const std::string cmd = fmt::format("cd {} && OMP_NUM_THREADS=1 CI=true {} {} > {} 2>&1",
                                      dir.string(), MESOCHAIN_BINARY, args, log.string());
  const int status = std::system(cmd.c_str());
  output = slurp(log);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace mesochain::testing
