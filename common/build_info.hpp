#pragma once
// The version of mesochain and the git commit it was built from (cmake/build_info.cmake writes
// the definitions at build time). The commit is "unknown" outside a git checkout and ends in
// "-dirty" when the checkout had uncommitted changes. `mesochain --version` prints both and
// every results JSON carries them (buildInfoJson()).
#include <nlohmann/json.hpp>
#include <string>

namespace mesochain {

const char* buildCommit();
const char* buildVersion();

// "mesochain 0.1.0 (commit 0123456789ab)".
std::string versionLine();

// {"version": ..., "commit": ...}: the "program" entry of every results JSON.
nlohmann::json buildInfoJson();

}  // namespace mesochain
