#include "common/build_info.hpp"

namespace mesochain {

std::string versionLine() {
  return std::string("mesochain ") + buildVersion() + " (commit " + buildCommit() + ")";
}

nlohmann::json buildInfoJson() { return {{"name", "mesochain"}, {"version", buildVersion()}, {"commit", buildCommit()}}; }

}  // namespace mesochain
