#pragma once
// Test helpers: a DFTB+ case of tests/data/dftbplus copied to a temporary folder with its
// table prefix pointed at this source tree's params/pbc-0-3/ (the recorded inputs name the
// absolute folder of the side-by-side run; tests/data/dftbplus/README.md: "change the prefix if
// the files move"), and small inputs written from text.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "common/errors.hpp"

namespace mesochain::testing {

// The message of the InputError `f` throws ("" when it throws nothing).
template <class F>
std::string errorOf(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

inline std::string hsdTempDir(const std::string& name) {
  const auto d = std::filesystem::temp_directory_path() / ("mesochain-hsd-" + name);
  std::filesystem::create_directories(d);
  return d.string();
}

inline std::string readText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void writeText(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

inline std::string localPrefix(std::string text) {
  const std::string recorded = "/work/shared/params/pbc-0-3/";
  const std::string here = std::string(MESOCHAIN_SOURCE_DIR) + "/params/pbc-0-3/";
  for (auto at = text.find(recorded); at != std::string::npos; at = text.find(recorded, at + here.size()))
    text.replace(at, recorded.size(), here);
  return text;
}

// The case folder's dftb_in.hsd (prefix replaced, nothing else changed) and geo.gen in a fresh
// folder; returns the path of the copied dftb_in.hsd.
inline std::string copiedDftbPlusCase(const std::string& name) {
  const std::string from = std::string(MESOCHAIN_TEST_DATA) + "/dftbplus/" + name;
  const std::string to = hsdTempDir("case-" + name);
  writeText(to + "/dftb_in.hsd", localPrefix(readText(from + "/dftb_in.hsd")));
  std::filesystem::copy_file(from + "/geo.gen", to + "/geo.gen", std::filesystem::copy_options::overwrite_existing);
  return to + "/dftb_in.hsd";
}

// A folder with geo.gen (the methane of tests/data/dftbplus/ch4) and `text` as dftb_in.hsd.
inline std::string methaneInput(const std::string& name, const std::string& text) {
  const std::string d = hsdTempDir(name);
  std::filesystem::copy_file(std::string(MESOCHAIN_TEST_DATA) + "/dftbplus/ch4/geo.gen", d + "/geo.gen",
                             std::filesystem::copy_options::overwrite_existing);
  writeText(d + "/dftb_in.hsd", localPrefix(text));
  return d + "/dftb_in.hsd";
}

}  // namespace mesochain::testing
