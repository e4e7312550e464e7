#include "skgen/skf_writer.hpp"

#include <array>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>

#include "common/atomic_file.hpp"
#include "common/errors.hpp"

namespace mesochain::skgen {

namespace {
// Columns of the simple format in file order (extended indices, dftb/skf_file.hpp).
constexpr std::array<int, 10> kSimpleColumns = {7, 8, 9, 12, 13, 14, 15, 17, 18, 19};

// Every number of a table goes through here: a non-finite one (a failed integral) is an error,
// never "nan" in a file DFTB+ would read.
std::string num(double x) {
  if (!std::isfinite(x)) throw NumericalError(fmt::format("a non-finite number ({})", x));
  return fmt::format("{:.16e}", x);
}

void writeSkfText(const std::string& path, const dftb::SkfTable& t,
                  const std::string& documentation);
}  // namespace

dftb::SplineRepulsiveData zeroRepulsive(double start, double cutoff) {
  if (!(cutoff > start) || !(start > 0.0))
    throw std::invalid_argument("zeroRepulsive: need 0 < start < cutoff");
  dftb::SplineRepulsiveData s;
  s.declaredCutoff = cutoff;
  s.expHead = {0.0, 0.0, -1.0};  // exp(0) − 1 = 0
  s.start = {start};
  s.end = {cutoff};
  s.coeffs = {std::array<double, 6>{}};
  return s;
}

void writeSkfFile(const std::string& path, const dftb::SkfTable& t,
                  const std::string& documentation) {
  if (!t.spline || t.spline->start.empty())
    throw std::invalid_argument("writeSkfFile: the table needs a spline repulsive block");
  if (t.ham.rows() != t.over.rows() || t.ham.cols() != dftb::kSkfColumnCount ||
      t.over.cols() != dftb::kSkfColumnCount || t.ham.rows() < 1 || !(t.gridSpacing > 0.0))
    throw std::invalid_argument("writeSkfFile: inconsistent integral table");
  for (int c : {0, 1, 2, 3, 4, 5, 6, 10, 11, 16})  // the f columns of the extended order
    if (t.ham.col(c).cwiseAbs().maxCoeff() > 0.0 || t.over.col(c).cwiseAbs().maxCoeff() > 0.0)
      throw std::invalid_argument("writeSkfFile: f integrals need the extended format (not written)");

  try {
    writeSkfText(path, t, documentation);
  } catch (const NumericalError& e) {
    throw NumericalError(path + ": the Slater-Koster table holds " + e.what() +
                         "; nothing was written");
  }
}

namespace {
void writeSkfText(const std::string& path, const dftb::SkfTable& t,
                  const std::string& documentation) {
  std::ostringstream out;
  out << num(t.gridSpacing) << " " << t.rows() + 1 << "\n";
  if (t.homonuclear) {
    // Ed Ep Es SPE Ud Up Us fd fp fs
    out << num(t.onsite[2]) << " " << num(t.onsite[1]) << " " << num(t.onsite[0]) << " "
        << num(t.spinPolarisationError) << " " << num(t.hubbard[2]) << " " << num(t.hubbard[1])
        << " " << num(t.hubbard[0]) << " " << num(t.occupation[2]) << " "
        << num(t.occupation[1]) << " " << num(t.occupation[0]) << "\n";
  }
  // mass, polynomial c2..c9 = 0, rcut = 0, d1..d10 = 0 (the spline block below is used)
  out << num(t.homonuclear ? t.mass : 0.0);
  for (int k = 0; k < 19; ++k) out << " 0.0";
  out << "\n";
  for (int i = 0; i < t.rows(); ++i) {
    for (int c : kSimpleColumns) out << num(t.ham(i, c)) << " ";
    for (std::size_t k = 0; k < kSimpleColumns.size(); ++k)
      out << num(t.over(i, kSimpleColumns[k])) << (k + 1 < kSimpleColumns.size() ? " " : "\n");
  }
  const dftb::SplineRepulsiveData& s = *t.spline;
  out << "Spline\n" << s.start.size() << " " << num(s.declaredCutoff) << "\n";
  out << num(s.expHead[0]) << " " << num(s.expHead[1]) << " " << num(s.expHead[2]) << "\n";
  for (std::size_t j = 0; j < s.start.size(); ++j) {
    const bool last = j + 1 == s.start.size();
    out << num(s.start[j]) << " " << num(s.end[j]);
    for (int k = 0; k < (last ? 6 : 4); ++k) out << " " << num(s.coeffs[j][k]);
    out << "\n";
  }
  if (!documentation.empty()) out << "\n" << documentation << (documentation.back() == '\n' ? "" : "\n");

  writeFileAtomically(path, out.str());
}
}  // namespace

}  // namespace mesochain::skgen
