#pragma once
// Helpers for the Slater-Koster tests: paths of the tables in the repository, a scratch
// directory, and small synthetic .skf files.
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "dftb/parameters.hpp"

namespace skftest {

// Value and derivative of a radial potential at r.
struct Vd {
  double v, d;
};
inline Vd at(const mesochain::dftb::RadialPotential& p, double r) {
  Vd x{};
  p.evaluate(r, x.v, x.d);
  return x;
}

inline std::string pbc(const std::string& name) {
  return std::string(MESOCHAIN_SOURCE_DIR) + "/params/pbc-0-3/" + name;
}
inline std::string ob3(const std::string& name) {
  return std::string(MESOCHAIN_TEST_DATA) + "/skf/3ob-3-1/" + name;
}

// A fresh directory per test.
inline std::filesystem::path scratchDir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::filesystem::path p = std::filesystem::temp_directory_path() /
                            ("mesochain_skf_" + std::string(info->test_suite_name()) + "_" +
                             info->name() + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(p);
  std::filesystem::create_directories(p);
  return p;
}

inline std::string writeFile(const std::filesystem::path& dir, const std::string& name,
                             const std::string& text) {
  const std::filesystem::path p = dir / name;
  std::ofstream(p) << text;
  return p.string();
}

// A simple-format table with nRows rows; row i (1-based) holds f(i, column) for the 20 columns.
inline std::string syntheticTable(bool homonuclear, int nRows, const std::string& atomicLine,
                                  const std::function<double(int, int)>& f,
                                  const std::string& tail = "Spline\n2 2.0\n1.0 2.0 0.0\n"
                                                            "1.0 1.5 0.1 -0.1 0.0 0.0\n"
                                                            "1.5 2.0 0.05 -0.1 0.0 0.0 0.0 0.0\n") {
  std::ostringstream o;
  o.precision(17);
  o << "0.1, " << nRows + 1 << "\n";
  if (homonuclear) o << atomicLine << "\n";
  o << "12.0, 19*0.0\n";
  for (int i = 1; i <= nRows; ++i) {
    for (int c = 0; c < 20; ++c) o << f(i, c) << (c == 19 ? "\n" : " ");
  }
  o << tail;
  return o.str();
}

// Runs fn, expects an InputError, and returns its message.
template <class Fn>
std::string inputErrorOf(Fn fn) {
  try {
    fn();
  } catch (const mesochain::InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError thrown";
  return "";
}

}  // namespace skftest
