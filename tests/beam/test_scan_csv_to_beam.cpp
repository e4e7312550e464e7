// The CSV `mesochain scan` writes (input/scan_output.hpp) is a table `mesochain beam`
// reads (beam/scan_table.hpp): its header lines carry T0, atoms per cell, kind, direction and
// the measured dimensions, and the CSV gives the same curve as the JSON written beside it.
#include <cmath>

#include <gtest/gtest.h>

#include "beam/scan_table.hpp"
#include "common/errors.hpp"
#include "input/scan_output.hpp"

namespace mesochain::beam {
namespace {

objective::ScanResult syntheticBend() {
  objective::ScanResult r;
  r.kind = objective::ScanKind::Bend;
  r.direction = objective::BendDirection::Hard;
  r.translation0 = 4.6482371234567891;
  r.atomsPerCell = 12;
  r.cellsPerSlice = 10;  // the curve reports 120 atoms and energies per slice
  r.thickness = 6.61;
  r.width = 41.3;
  r.complete = true;
  for (int k = 0; k < 5; ++k) {
    objective::ScanPoint p;
    p.deformation = 0.002 * k;
    p.energy = -5.0 + 0.5 * 3.7 * p.deformation * p.deformation;  // a quadratic, per cell
    p.converged = k != 3;
    p.measuredCurvature = 0.00199 * k;
    p.helicalKPoints = 1;
    p.angularPoints = 4;
    p.evaluations = 7 + k;
    r.points.push_back(p);
  }
  return r;
}

TEST(ScanCsvToBeam, BeamReadsTheScanCsvAsTheScanJson) {
  const objective::ScanResult r = syntheticBend();
  const ScanCurve c = parseScanCsv(objective::scanCurveCsv(r), "curve.csv");
  const ScanCurve j = parseScanJson(objective::scanCurveJson(r).dump(), "curve.json");
  EXPECT_EQ(c.label(), "bend hard");
  EXPECT_EQ(c.label(), j.label());
  EXPECT_EQ(c.deformationUnit, j.deformationUnit);
  EXPECT_EQ(c.cellLength, r.translation0);  // written with 17 digits: exact
  EXPECT_EQ(c.cellLength, j.cellLength);
  EXPECT_EQ(c.atomsPerCell, 120);
  EXPECT_EQ(c.atomsPerCell, j.atomsPerCell);
  EXPECT_EQ(c.thickness, j.thickness);
  EXPECT_EQ(c.width, j.width);
  ASSERT_EQ(c.points.size(), r.points.size());
  ASSERT_EQ(j.points.size(), r.points.size());
  for (std::size_t k = 0; k < c.points.size(); ++k) {
    EXPECT_EQ(c.points[k].deformation, j.points[k].deformation);
    EXPECT_EQ(c.points[k].energy, j.points[k].energy);
    EXPECT_EQ(c.points[k].energy, r.points[k].energy * 10);
    EXPECT_EQ(c.points[k].converged, j.points[k].converged);
    EXPECT_EQ(c.points[k].measuredCurvature, j.points[k].measuredCurvature);
  }
}

TEST(ScanCsvToBeam, ACsvWithoutTheHeaderIsStillRefusedClearly) {
  std::string csv = objective::scanCurveCsv(syntheticBend());
  const auto at = csv.find("# T0_bohr");
  csv.erase(at, csv.find('\n', at) + 1 - at);
  try {
    parseScanCsv(csv, "curve.csv");
    FAIL() << "a CSV without T0_bohr was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("T0_bohr"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace mesochain::beam
