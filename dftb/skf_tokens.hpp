#pragma once
// Numbers on one line of a DFTB+ .skf file, in the free (Fortran list-directed) layout the
// published tables use:
//   - values separated by blanks, tabs and/or single commas; a trailing comma is allowed;
//   - "N*value" repeats value N times ("20*1.0", "9*0.0", "1*0.0");
//   - Fortran exponents with D ("1.0D-03") and a leading '+' are accepted.
// Refused, with an InputError naming the file and line: an empty value between two commas (a
// Fortran null value, which would silently keep an old value), a garbled number, a repeat count
// that is not a positive integer, and non-finite numbers (nan, inf).
#include <string>
#include <vector>

namespace mesochain::dftb {

struct SkfLine {
  const std::string* file = nullptr;  // for error messages
  int number = 0;                     // 1-based line number
  std::string text;
};

// All numbers of the line, with repeats expanded.
std::vector<double> parseSkfNumbers(const SkfLine& line);

// One integer token (e.g. the number of grid points or of spline intervals), at the given
// position of the line's tokens (repeats are not allowed there).
int parseSkfInteger(const SkfLine& line, int position, const std::string& what);

// Throws InputError(file, "line N", found, expected).
[[noreturn]] void skfError(const SkfLine& line, const std::string& found,
                           const std::string& expected);

}  // namespace mesochain::dftb
