// Reader of DFTB+ .skf files: known entries of the shipped tables, the free number layout, and
// one error (with file name and line number) per kind of malformed file.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "dftb/skf_file.hpp"
#include "dftb/skf_tokens.hpp"
#include "skf_test_util.hpp"

using namespace mesochain::dftb;
using namespace skftest;

TEST(SkfFile, CarbonPbcHeaderAndAtomicData) {
  const SkfTable t = readSkfFile(pbc("C-C.skf"), true);
  EXPECT_FALSE(t.extended);
  EXPECT_EQ(t.gridSpacing, 0.02);
  EXPECT_EQ(t.declaredPoints, 520);
  EXPECT_EQ(t.rows(), 519);  // DFTB+ reads nGrid - 1 rows; the file holds exactly 519
  EXPECT_EQ(t.onsite[0], -0.50489172);
  EXPECT_EQ(t.onsite[1], -0.19435511);
  EXPECT_EQ(t.onsite[2], 0.0);
  EXPECT_EQ(t.spinPolarisationError, -0.045479);
  for (int l = 0; l < 3; ++l) EXPECT_EQ(t.hubbard[l], 0.364302);
  EXPECT_EQ(t.occupation[0], 2.0);
  EXPECT_EQ(t.occupation[1], 2.0);
  EXPECT_EQ(t.occupation[2], 0.0);
  EXPECT_EQ(t.mass, 12.01);
  const std::array<double, 8> c = {0.0180339, 0.0947251, -0.128899, -0.116864,
                                   0.301533,  -0.172412, 0.032959,  0.0};
  EXPECT_EQ(t.polynomial.c, c);
  EXPECT_EQ(t.polynomial.cutoff, 3.83847);
}

TEST(SkfFile, CarbonPbcIntegralRows) {
  const SkfTable t = readSkfFile(pbc("C-C.skf"), true);
  // Row 1 is "20*1.0": every column of the simple format is 1, the f columns stay 0.
  for (int col : {7, 8, 9, 12, 13, 14, 15, 17, 18, 19}) {
    EXPECT_EQ(t.ham(0, col), 1.0);
    EXPECT_EQ(t.over(0, col), 1.0);
  }
  for (int col : {0, 1, 2, 3, 4, 5, 6, 10, 11, 16}) EXPECT_EQ(t.ham(0, col), 0.0);
  // Row 133 (file line 136, r = 2.66 Bohr).
  EXPECT_EQ(t.ham(132, kSkfPpSigma), 2.579971278478e-01);
  EXPECT_EQ(t.ham(132, kSkfPpPi), -1.235393530606e-01);
  EXPECT_EQ(t.ham(132, kSkfSpSigma), 2.928335922608e-01);
  EXPECT_EQ(t.ham(132, kSkfSsSigma), -2.861096914660e-01);
  EXPECT_EQ(t.over(132, kSkfPpSigma), -3.369019963390e-01);
  EXPECT_EQ(t.over(132, kSkfPpPi), 1.549903615702e-01);
  EXPECT_EQ(t.over(132, kSkfSpSigma), -3.285110383607e-01);
  EXPECT_EQ(t.over(132, kSkfSsSigma), 2.774236655861e-01);
  // Last row (file line 522).
  EXPECT_EQ(t.ham(518, kSkfPpSigma), 3.851288912330e-06);
  EXPECT_EQ(t.over(518, kSkfSsSigma), -2.988410941983e-05);
}

TEST(SkfFile, CarbonPbcSplineBlock) {
  const SkfTable t = readSkfFile(pbc("C-C.skf"), true);
  ASSERT_TRUE(t.spline.has_value());
  const SplineRepulsiveData& s = *t.spline;
  EXPECT_EQ(t.splineLine, 523);
  EXPECT_EQ(s.start.size(), 50u);
  EXPECT_EQ(s.declaredCutoff, 3.83847);
  EXPECT_EQ(s.cutoff(), 3.83847);
  EXPECT_EQ(s.expHead[0], 2.840615140631801);
  EXPECT_EQ(s.expHead[1], 5.622306915911007);
  EXPECT_EQ(s.expHead[2], -3.100337689359979);
  EXPECT_EQ(s.start.front(), 1.0);
  EXPECT_EQ(s.end.front(), 1.0567694);
  const std::array<double, 6> first = {13.0459761, -45.86546341544799, 65.14306490500775,
                                       16.85208682864729, 0.0, 0.0};
  EXPECT_EQ(s.coeffs.front(), first);
  EXPECT_EQ(s.start.back(), 3.7817006);
  EXPECT_EQ(s.end.back(), 3.83847);
  const std::array<double, 6> last = {7.405148489999999e-05, -0.002974610736686984,
                                      0.02861646812060604,   -0.02178731106014187,
                                      3.515215468468079,     -50.76575060689886};
  EXPECT_EQ(s.coeffs.back(), last);
}

TEST(SkfFile, HeteronuclearAndExtraRowsIgnored) {
  // C-H: no atomic line; the mass line starts the file's second line.
  const SkfTable ch = readSkfFile(pbc("C-H.skf"), false);
  EXPECT_EQ(ch.rows(), 519);
  EXPECT_EQ(ch.polynomial.cutoff, 3.39);
  EXPECT_EQ(ch.polynomial.c[0], -0.000429);
  EXPECT_EQ(ch.polynomial.c[2], 0.083962);  // written as +0.083962
  EXPECT_EQ(ch.polynomial.c[4], 0.013795);
  ASSERT_TRUE(ch.spline.has_value());
  EXPECT_EQ(ch.spline->start.size(), 50u);
  // H-H declares 500 points but holds 519 rows: DFTB+ reads 499 and then looks for "Spline".
  const SkfTable hh = readSkfFile(pbc("H-H.skf"), true);
  EXPECT_EQ(hh.declaredPoints, 500);
  EXPECT_EQ(hh.rows(), 499);
  EXPECT_EQ(hh.ham(498, kSkfSsSigma), 1.309127854717e-05);
  EXPECT_EQ(hh.over(498, kSkfSsSigma), -9.462185853871e-05);
  EXPECT_EQ(hh.occupation[0], 1.0);
  EXPECT_EQ(hh.onsite[0], -0.23860040);
  ASSERT_TRUE(hh.spline.has_value());
  EXPECT_EQ(hh.splineLine, 523);
  EXPECT_EQ(hh.spline->start.size(), 16u);
}

TEST(SkfFile, NumberLayout) {
  SkfLine l;
  const std::string name = "x.skf";
  l.file = &name;
  l.number = 7;
  l.text = "  1*0.0 2*1.5,\t3.0, 1.0D-02 +2.5e1 -4, ";
  const std::vector<double> v = parseSkfNumbers(l);
  const std::vector<double> want = {0.0, 1.5, 1.5, 3.0, 0.01, 25.0, -4.0};
  EXPECT_EQ(v, want);
  l.text = "20*1.0,\t\t";
  EXPECT_EQ(parseSkfNumbers(l), std::vector<double>(20, 1.0));
  l.text = "9*0.0 1.3e-05 9*0.0 -9.4e-05";
  EXPECT_EQ(parseSkfNumbers(l).size(), 20u);
  // Refused, each naming file and line.
  for (const char* bad : {"1.0 ,, 2.0", ", 1.0", "1.0 abc", "0*1.0", "x*1.0", "3*", "*2.0",
                          "1.0 nan", "inf 1.0", "2*-inf", "1e999", "1.0.0", "++1.0"}) {
    l.text = bad;
    const std::string msg = inputErrorOf([&] { parseSkfNumbers(l); });
    EXPECT_NE(msg.find("x.skf"), std::string::npos) << bad << ": " << msg;
    EXPECT_NE(msg.find("line 7"), std::string::npos) << bad << ": " << msg;
  }
}

TEST(SkfFile, ExtendedFormat) {
  const auto dir = scratchDir();
  std::ostringstream o;
  o << "@ extended format\n0.1, 11\n"
    << "0.0 0.0 -0.2 -0.5 0.0 0.0 0.0 0.3 0.4 0.0 0.0 2.0 2.0\n"
    << "12.0, 19*0.0\n";
  for (int i = 1; i <= 10; ++i) {
    for (int c = 0; c < 40; ++c) o << (c < 20 ? i + 0.01 * c : -i - 0.01 * (c - 20)) << " ";
    o << "\n";
  }
  o << "Spline\n1 1.0\n1 0 0\n0.5 1.0 0.1 0 0 0 0 0\n";  // within the 1 Bohr table
  const SkfTable t = readSkfFile(writeFile(dir, "X-X.skf", o.str()), true);
  EXPECT_TRUE(t.extended);
  EXPECT_EQ(t.rows(), 10);
  EXPECT_EQ(t.onsite[0], -0.5);  // Ef Ed Ep Es: s is the fourth value
  EXPECT_EQ(t.onsite[1], -0.2);
  EXPECT_EQ(t.hubbard[0], 0.4);
  EXPECT_EQ(t.occupation[1], 2.0);
  EXPECT_EQ(t.occupation[3], 0.0);
  EXPECT_DOUBLE_EQ(t.ham(2, kSkfSsSigma), 3.19);
  EXPECT_DOUBLE_EQ(t.ham(2, kSkfPpPi), 3.15);
  EXPECT_DOUBLE_EQ(t.over(2, kSkfSpSigma), -3.18);
  EXPECT_DOUBLE_EQ(t.ham(2, 0), 3.0);  // ff0 is kept, though we do not use it
}

namespace {

// Writes `text` as bad.skf and checks the InputError names the file and the line.
void expectErrorAt(const std::string& text, int line, bool homonuclear = true,
                   const std::string& also = "") {
  const auto dir = scratchDir();
  const std::string path = writeFile(dir, "bad.skf", text);
  const std::string msg = inputErrorOf([&] { readSkfFile(path, homonuclear); });
  EXPECT_NE(msg.find("bad.skf"), std::string::npos) << msg;
  EXPECT_NE(msg.find("line " + std::to_string(line)), std::string::npos) << msg;
  if (!also.empty()) {
    EXPECT_NE(msg.find(also), std::string::npos) << msg;
  }
}

const char* kAtomic = "0.0 -0.2 -0.5 0.0 0.36 0.36 0.36 0.0 2.0 2.0";

std::string rows(int n, int from = 1) {
  std::string s;
  for (int i = from; i < from + n; ++i) s += std::to_string(0.1 * i) + " 19*0.5\n";
  return s;
}

}  // namespace

TEST(SkfFile, MalformedFilesNameFileAndLine) {
  const std::string head = std::string("0.1, 6\n") + kAtomic + "\n12.0, 19*0.0\n";
  // The repulsion ends within the 0.5 Bohr of table.
  const std::string spline = "Spline\n1 0.5\n1 0 0\n0.25 0.5 0.1 0 0 0 0 0\n";
  // A well-formed file first, so that each failure below is due to its one defect.
  {
    const auto dir = scratchDir();
    EXPECT_NO_THROW(readSkfFile(writeFile(dir, "good.skf", head + rows(5) + spline), true));
  }
  expectErrorAt(head + rows(2) + "0.3 18*0.5 0.1x\n" + rows(2, 4) + spline, 6, true, "0.1x");
  expectErrorAt(head + rows(3) + "0.4 18*0.5\n" + rows(1, 5) + spline, 7, true, "19 numbers");
  expectErrorAt(head + rows(3) + spline, 7, true, "Spline");  // fewer rows than declared
  expectErrorAt(head + rows(3), 7, true, "end of file");       // file ends inside the table
  expectErrorAt(std::string("0.1\n") + kAtomic + "\n", 1);      // no grid count
  expectErrorAt(std::string("0.1, 6.5\n") + kAtomic + "\n", 1);  // non-integer grid count
  expectErrorAt(std::string("0.1, 6\n0.0 -0.2 -0.5 0.0 0.36 0.36 0.36 0.0 2.0\n"), 2, true,
                "9 numbers");
  expectErrorAt(std::string("0.1, 6\n0.0 -0.2 nan 0.0 0.36 0.36 0.36 0.0 2.0 2.0\n"), 2, true,
                "non-finite");
  expectErrorAt(std::string("0.1, 6\n") + kAtomic + "\n12.0, 18*0.0\n", 3, true, "19 numbers");
  expectErrorAt("0.1, 6\n12.0, 19*0.0\n" + rows(1) + "1.0 ,, 2.0\n", 4, false, "empty value");
  // Spline block: a gap between intervals, a short interval line, a missing interval.
  expectErrorAt(head + rows(5) + "Spline\n2 2.0\n1 0 0\n1.0 1.5 0.1 0 0 0\n1.6 2.0 0 0 0 0 0 0\n",
                13, true, "previous interval");
  expectErrorAt(head + rows(5) + "Spline\n2 2.0\n1 0 0\n1.0 1.5 0.1 0 0\n", 12, true,
                "6 numbers");
  expectErrorAt(head + rows(5) + "Spline\n2 2.0\n1 0 0\n1.0 1.5 0.1 0 0 0\n", 13, true,
                "end of file");
  expectErrorAt(head + rows(5) + "Spline\n2.5 2.0\n", 10, true, "intervals");
}

TEST(SkfFile, MissingFileIsInputError) {
  const std::string msg = inputErrorOf([] { readSkfFile("/nonexistent/Q-Q.skf", true); });
  EXPECT_NE(msg.find("/nonexistent/Q-Q.skf"), std::string::npos) << msg;
}

namespace {
std::string withFirstLine(const std::string& path, const std::string& first) {
  std::ifstream in(path);
  std::string line, out = first + "\n";
  std::getline(in, line);
  while (std::getline(in, line)) out += line + "\n";
  return out;
}
}  // namespace

// A grid line garbled from "0.02, 520" to "0.002, 520" leaves a table of 1 Bohr, shorter than the
// repulsion (3.8 Bohr): refused, naming the grid line, instead of atoms that do not interact.
TEST(SkfFile, GridShorterThanTheRepulsionIsRefused) {
  const std::string cc = std::string(MESOCHAIN_SOURCE_DIR) + "/params/pbc-0-3/C-C.skf";
  EXPECT_NO_THROW(readSkfFile(cc, true));
  expectErrorAt(withFirstLine(cc, "0.002, 520"), 1, true, "shorter than the repulsive potential");
}

// nGrid = 2e9 would allocate 640 GB: refused on the grid line with the estimate and the limit.
TEST(SkfFile, HugeGridCountIsRefusedBeforeAllocating) {
  const std::string cc = std::string(MESOCHAIN_SOURCE_DIR) + "/params/pbc-0-3/C-C.skf";
  expectErrorAt(withFirstLine(cc, "0.02, 2000000000"), 1, true, "at most 1000000 grid points");
  expectErrorAt(withFirstLine(cc, "0.02, 3000000000"), 1, true, "at most 2147483647");
}

// Every table shipped with the project (params/) and the test data still loads.
TEST(SkfFile, EveryShippedTableLoads) {
  int tables = 0;
  for (const std::string& root : {std::string(MESOCHAIN_SOURCE_DIR) + "/params",
                                 std::string(MESOCHAIN_TEST_DATA)})
    for (const auto& e : std::filesystem::recursive_directory_iterator(root))
      if (e.path().extension() == ".skf") {
        const std::string name = e.path().stem().string();
        const auto dash = name.find('-');
        const bool homonuclear = dash != std::string::npos &&
                                 name.substr(0, dash) == name.substr(dash + 1);
        EXPECT_NO_THROW(readSkfFile(e.path().string(), homonuclear)) << e.path();
        ++tables;
      }
  EXPECT_GE(tables, 11);
}
