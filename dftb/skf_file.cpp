#include "dftb/skf_file.hpp"

#include <cmath>
#include <fstream>
#include <vector>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "dftb/skf_tokens.hpp"

namespace mesochain::dftb {

namespace {

// Columns of the simple format, in file order, mapped to the extended order.
constexpr std::array<int, 10> kSimpleToExtended = {7, 8, 9, 12, 13, 14, 15, 17, 18, 19};

// Reads lines one by one and remembers the line number.
class LineReader {
 public:
  explicit LineReader(const std::string& path) : path_(path), in_(path) {
    if (!in_) throw InputError(path, "", "no readable file", "a Slater-Koster (.skf) file");
  }
  // Next line; throws with `expected` at end of file.
  SkfLine next(const std::string& expected) {
    SkfLine line = tryNext();
    if (!line.file) {
      throw InputError(path_, "line " + std::to_string(number_ + 1) + " (end of file)",
                       "the end of the file", expected);
    }
    return line;
  }
  int lines() const { return number_; }
  // Next line, or a line with file == nullptr at end of file.
  SkfLine tryNext() {
    SkfLine line;
    if (!std::getline(in_, line.text)) return line;
    ++number_;
    line.file = &path_;
    line.number = number_;
    return line;
  }

 private:
  std::string path_;
  std::ifstream in_;
  int number_ = 0;
};

std::vector<double> numbers(const SkfLine& line, std::size_t count, const std::string& what,
                            bool allowExtra = false) {
  std::vector<double> v = parseSkfNumbers(line);
  if (v.size() < count || (!allowExtra && v.size() > count)) {
    skfError(line, std::to_string(v.size()) + " numbers",
             std::to_string(count) + " numbers (" + what + ")");
  }
  return v;
}

std::string trimmed(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

// At most this many grid points (published tables have 500-1000): each row holds 40 doubles,
// 320 bytes, so 1e6 rows are 0.32 GB; more is a garbled nGrid, refused before any allocation.
constexpr int kMaxSkfGridPoints = 1000000;

int readGridLine(LineReader& reader, SkfTable& t) {
  const SkfLine line = reader.next("the grid line 'gridDist nGrid'");
  const std::vector<double> v = parseSkfNumbers(line);
  // DFTB+ reads two values and ignores the rest (published tables have a third, e.g. "500,1").
  if (v.size() < 2) {
    skfError(line, std::to_string(v.size()) + " numbers", "'gridDist nGrid' (2 numbers)");
  }
  t.gridSpacing = v[0];
  t.declaredPoints = parseSkfInteger(line, 1, "the number of grid points nGrid");
  if (!(t.gridSpacing > 0.0)) {
    skfError(line, "grid spacing " + std::to_string(t.gridSpacing), "a positive grid spacing");
  }
  if (t.declaredPoints < 2) {
    skfError(line, "nGrid = " + std::to_string(t.declaredPoints),
             "at least 2 grid points (DFTB+ reads nGrid - 1 table rows)");
  }
  if (t.declaredPoints > kMaxSkfGridPoints) {
    skfError(line,
             fmt::format("nGrid = {} (about {:.3g} GB of integral tables)", t.declaredPoints,
                         320e-9 * t.declaredPoints),
             fmt::format("at most {} grid points (published tables have 500-1000)",
                         kMaxSkfGridPoints));
  }
  return line.number;
}

// The integral table must reach beyond the repulsive potential: in every DFTB table the H and S
// integrals (tails of atomic orbitals) extend further than the short-ranged repulsion (params/:
// 10.4 Bohr of table, repulsion to 2.1-4.2 Bohr). A grid spacing mistyped as 0.002 for 0.02
// would leave atoms beyond 1 Bohr without any integral, i.e. not interacting.
void checkGridCoversRepulsion(const SkfTable& t, int gridLine) {
  const double extent = t.gridSpacing * (t.declaredPoints - 1);  // DFTB+: rows at dr .. (n-1) dr
  const bool spline = t.spline.has_value();
  const double cutoff = spline ? t.spline->cutoff() : t.polynomial.cutoff;
  if (cutoff > extent)
    throw InputError(
        t.path, "line " + std::to_string(gridLine) + " (the grid line 'gridDist nGrid')",
        fmt::format("an integral table to {:.6g} Bohr (gridDist {:.6g} x {} rows), shorter than "
                    "the repulsive potential, which reaches {:.6g} Bohr ({})",
                    extent, t.gridSpacing, t.declaredPoints - 1, cutoff,
                    spline ? "line " + std::to_string(t.splineLine) + ", the Spline block"
                           : std::string("rcut of the polynomial")),
        "a grid that reaches beyond the repulsion (is gridDist or nGrid mistyped?)");
}

void readAtomicLine(LineReader& reader, SkfTable& t) {
  const int nShell = t.extended ? 4 : 3;  // f d p s or d p s, highest shell first
  const SkfLine line = reader.next("the atomic line (energies, Hubbard U, occupations)");
  const std::vector<double> v =
      numbers(line, static_cast<std::size_t>(3 * nShell + 1),
              t.extended ? "Ef Ed Ep Es SPE Uf Ud Up Us ff fd fp fs"
                         : "Ed Ep Es SPE Ud Up Us fd fp fs");
  for (int k = 0; k < nShell; ++k) {
    const std::size_t shell = static_cast<std::size_t>(nShell - 1 - k);  // s = 0
    t.onsite[shell] = v[static_cast<std::size_t>(k)];
    t.hubbard[shell] = v[static_cast<std::size_t>(nShell + 1 + k)];
    t.occupation[shell] = v[static_cast<std::size_t>(2 * nShell + 1 + k)];
  }
  t.spinPolarisationError = v[static_cast<std::size_t>(nShell)];
}

void readMassLine(LineReader& reader, SkfTable& t) {
  const SkfLine line = reader.next("the mass / polynomial repulsive line");
  const std::vector<double> v = numbers(line, 20, "mass c2..c9 rcut d1..d10");
  if (t.homonuclear) t.mass = v[0];
  for (std::size_t i = 0; i < 8; ++i) t.polynomial.c[i] = v[1 + i];
  t.polynomial.cutoff = v[9];
}

void readTable(LineReader& reader, SkfTable& t) {
  const int rows = t.declaredPoints - 1;
  const std::size_t perMatrix = t.extended ? 20 : 10;
  t.ham = Eigen::MatrixXd::Zero(rows, kSkfColumnCount);
  t.over = Eigen::MatrixXd::Zero(rows, kSkfColumnCount);
  const std::string expect = std::to_string(rows) + " integral rows (nGrid = " +
                             std::to_string(t.declaredPoints) + " declared; DFTB+ reads nGrid - 1)";
  for (int i = 0; i < rows; ++i) {
    const SkfLine line = reader.tryNext();
    if (!line.file) {
      throw InputError(t.path, "line " + std::to_string(reader.lines() + 1) + " (end of file)",
                       "only " + std::to_string(i) + " integral rows", expect);
    }
    if (trimmed(line.text) == "Spline") {
      skfError(line, "'Spline' after " + std::to_string(i) + " integral rows", expect);
    }
    const std::vector<double> v =
        numbers(line, 2 * perMatrix,
                t.extended ? "20 H then 20 S integrals of the extended format"
                           : "10 H then 10 S integrals; a table with f shells must start with '@'");
    for (std::size_t k = 0; k < perMatrix; ++k) {
      const int col = t.extended ? static_cast<int>(k) : kSimpleToExtended[k];
      t.ham(i, col) = v[k];
      t.over(i, col) = v[perMatrix + k];
    }
  }
}

void readSpline(LineReader& reader, SkfTable& t) {
  // Look for a line reading "Spline" (trailing blanks allowed, as in the Fortran comparison).
  SkfLine line;
  while (true) {
    line = reader.tryNext();
    if (!line.file) return;  // no spline block
    if (trimmed(line.text) == "Spline" && line.text.rfind("Spline", 0) == 0) break;
  }
  t.splineLine = line.number;
  SplineRepulsiveData s;
  const SkfLine head = reader.next("the line 'nInt cutoff' after 'Spline'");
  const std::vector<double> hv = numbers(head, 2, "nInt cutoff");
  const int nInt = parseSkfInteger(head, 0, "the number of spline intervals");
  if (nInt < 1) skfError(head, "nInt = " + std::to_string(nInt), "at least one spline interval");
  s.declaredCutoff = hv[1];
  const std::vector<double> ev = numbers(reader.next("the line 'a1 a2 a3'"), 3, "a1 a2 a3");
  s.expHead = {ev[0], ev[1], ev[2]};
  for (int j = 0; j < nInt; ++j) {
    const bool last = (j == nInt - 1);
    const SkfLine l = reader.next("spline interval " + std::to_string(j + 1) + " of " +
                                  std::to_string(nInt));
    const std::vector<double> v =
        numbers(l, last ? 8 : 6,
                last ? "start end c0 c1 c2 c3 c4 c5 of the last interval"
                     : "start end c0 c1 c2 c3 of a cubic interval");
    if (!(v[1] > v[0])) {
      skfError(l, "interval [" + std::to_string(v[0]) + ", " + std::to_string(v[1]) + "]",
               "start < end");
    }
    // DFTB+ refuses an interval that does not start where the previous one ended (1e-8).
    if (j > 0 && std::abs(v[0] - s.end.back()) > 1e-8) {
      skfError(l, "an interval starting at " + std::to_string(v[0]),
               "the end of the previous interval, " + std::to_string(s.end.back()));
    }
    s.start.push_back(v[0]);
    s.end.push_back(v[1]);
    std::array<double, 6> c{};
    for (std::size_t k = 0; k < (last ? 6u : 4u); ++k) c[k] = v[2 + k];
    s.coeffs.push_back(c);
  }
  t.spline = std::move(s);
}

}  // namespace

SkfTable readSkfFile(const std::string& path, bool homonuclear) {
  SkfTable t;
  t.path = path;
  t.homonuclear = homonuclear;
  LineReader reader(path);
  {
    // Extended format: the first line starts with '@' and carries nothing DFTB+ reads.
    LineReader probe(path);
    const SkfLine first = probe.next("the grid line 'gridDist nGrid'");
    t.extended = !first.text.empty() && first.text[0] == '@';
  }
  if (t.extended) reader.next("the grid line");
  const int gridLine = readGridLine(reader, t);
  if (homonuclear) readAtomicLine(reader, t);
  readMassLine(reader, t);
  readTable(reader, t);
  readSpline(reader, t);
  checkGridCoversRepulsion(t, gridLine);
  return t;
}

}  // namespace mesochain::dftb
