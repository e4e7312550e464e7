#pragma once
// A folder of this test process under the system temp folder, NAME-PID, removed when the process
// exits. ctest runs every test in a process of its own and several at once, so a fixed name
// races: one test reads a file that another has just rewritten (ScanFile.BadInputNamesFileAndKey
// and ScanFile.BadListsAndWordsSayWhatWasFound failed together that way in a CI run).
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

namespace mesochain::testing {

inline std::filesystem::path processTempDir(const std::string& name) {
  struct Folders {
    std::vector<std::filesystem::path> paths;
    ~Folders() {
      for (const auto& p : paths) {
        std::error_code ec;
        std::filesystem::remove_all(p, ec);
      }
    }
  };
  static Folders folders;
  const auto dir = std::filesystem::temp_directory_path() / (name + "-" + std::to_string(::getpid()));
  if (std::find(folders.paths.begin(), folders.paths.end(), dir) == folders.paths.end()) folders.paths.push_back(dir);
  return dir;
}

}  // namespace mesochain::testing
