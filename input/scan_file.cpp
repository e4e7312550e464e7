#include "input/scan_file.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "input/cell_calculator.hpp"
#include "common/toml_file.hpp"
#include "common/units.hpp"
#include "common/toml_table.hpp"
#include "objective/drivers/scan_reference.hpp"

namespace mesochain::objective {

namespace fs = std::filesystem;

namespace {

std::vector<double> numberList(const TomlTable& t, const std::string& key,
                               const std::string& expected) {
  const std::vector<double> out = t.numbers(key, expected);
  if (out.empty()) t.fail(key, "an empty array", expected);
  return out;
}

std::string relativeTo(const std::string& scanFile, const std::string& path) {
  return (fs::path(scanFile).parent_path() / path).lexically_normal().string();
}


}  // namespace

ScanInput readScanFile(const std::string& path, const std::string& outputDir) {
  ScanInput in;
  in.source = path;
  const toml::value data = parseTomlFile(path, "scan file");
  std::error_code ec;
  const TomlTable root(path, data, "");
  root.allowOnly({"format", "cell", "kind", "strains", "twist_deg_per_cell", "rotation_orders",
                  "direction", "ring_angular", "relax", "dimensions", "output", "reference"});
  const long format = root.integer("format", "format = 1");
  if (format != 1) root.fail("format", std::to_string(format), "format = 1");

  const std::string cellFile = root.string("cell", "the path of an objective-cell file (TOML)");
  const std::string cellPath = relativeTo(path, cellFile);
  if (!fs::is_regular_file(cellPath, ec))
    root.fail("cell", "\"" + cellFile + "\", which does not exist (looked for " + cellPath + ")",
              "an existing cell file (the path is relative to the scan file)");
  in.cell = readCellFile(cellPath);

  ScanSettings& s = in.settings;
  const std::string kind = root.oneOf("kind", {"stretch", "twist", "bend"});
  const std::vector<std::pair<std::string, std::string>> listKeys = {
      {"stretch", "strains"}, {"twist", "twist_deg_per_cell"}, {"bend", "rotation_orders"}};
  std::string listKey;
  for (const auto& [k, key] : listKeys)
    if (k == kind) listKey = key;
  for (const auto& [k, key] : listKeys)
    if (key != listKey && root.has(key))
      root.fail(key, key + " with kind = \"" + kind + "\"", listKey + " (the list of this kind)");
  if (!root.has(listKey)) root.missing(listKey, "the list of deformations of this scan");
  if (kind != "bend")
    for (const char* key : {"direction", "ring_angular"})
      if (root.has(key)) root.fail(key, std::string(key) + " with kind = \"" + kind + "\"",
                                   "direction and ring_angular only with kind = \"bend\"");
  if (kind == "stretch") {
    s.kind = ScanKind::Stretch;
    s.values = numberList(root, "strains", "a non-empty array of strains (dimensionless, > -1)");
  } else if (kind == "twist") {
    s.kind = ScanKind::Twist;
    for (double deg : numberList(root, "twist_deg_per_cell",
                                 "a non-empty array of twist angles (degrees per cell)"))
      s.values.push_back(deg * units::kDegree);
  } else {
    s.kind = ScanKind::Bend;
    const char* expected = "a non-empty array of ring rotation orders N_a (integers from 2 to 100000000)";
    const std::vector<long> orders = root.integers("rotation_orders", expected);
    if (orders.empty()) root.fail("rotation_orders", "an empty array", expected);
    for (long n : orders) {
      if (n < 2 || n > 100000000L) root.fail("rotation_orders", "an array holding " + std::to_string(n), expected);
      s.rotationOrders.push_back(static_cast<int>(n));
    }
    const std::string dir = root.oneOfOr("direction", {"soft", "hard"}, "soft");
    s.direction = dir == "soft" ? BendDirection::Soft : BendDirection::Hard;
    if (root.has("ring_angular"))
      s.ringAngular.samples = static_cast<int>(
          root.integerOrWord("ring_angular", "all", 1, 1000000000L, "sampled angular quantum numbers").value_or(0));
    if (!in.cell.cell.symmetry.isRing() && std::abs(in.cell.cell.symmetry.twist()) > 1e-12)
      root.fail("cell", "a twisted cell (" + cellFile + ")",
                "for kind = \"bend\" a cell with twist 0: a straight translational cell "
                "(rotation order 1, e.g. [builder] cell = \"translational\" or type = "
                "\"collapsed\"), or a ring sector (e.g. type = \"graphene_ring\")");
  }
  if (!s.values.empty() || !s.rotationOrders.empty()) {
    if (in.cell.cell.symmetry.isRing())
      root.fail("cell", "a closed ring (" + cellFile + ")", "a straight cell (translation > 0)");
  }

  s.relax.relaxTranslation = true;
  if (const auto r = root.table("relax")) {
    r->allowOnly({"force_tolerance", "max_steps", "relax_translation"});
    if (r->has("force_tolerance")) {
      s.relax.forceTolerance = r->number("force_tolerance", "a positive force (Ha/Bohr)");
      if (!(s.relax.forceTolerance > 0))
        r->fail("force_tolerance", fmt::format("{}", s.relax.forceTolerance), "a positive force (Ha/Bohr)");
    }
    if (r->has("max_steps")) {
      const long n = r->integer("max_steps", "a positive integer");
      if (n < 1 || n > 100000000L) r->fail("max_steps", std::to_string(n), "an integer from 1 to 100000000");
      s.relax.maxSteps = static_cast<int>(n);
    }
    if (r->has("relax_translation"))
      s.relax.relaxTranslation = r->boolean("relax_translation", "true or false");
  }
  s.relax.axialTolerance = s.relax.forceTolerance;

  if (const auto d = root.table("dimensions")) {
    d->allowOnly({"measure", "interlayer"});
    const bool measure = d->has("measure") && d->boolean("measure", "true or false");
    double interlayer = kDefaultCollapseInterlayerAngstrom;
    if (d->has("interlayer")) {
      interlayer = d->number("interlayer", "a positive interlayer distance (Å)");
      if (!(interlayer > 0)) d->fail("interlayer", fmt::format("{} Å", interlayer), "a positive distance (Å)");
    }
    if (measure) s.dimensionsInterlayer = interlayer * units::kAngstromInBohr;
  }

  const auto o = root.table("output");
  if (!o) root.missing("output", "a table [output] with json = \"curve.json\" (and csv, checkpoint)");
  o->allowOnly({"json", "csv", "checkpoint", "checkpoint_minutes", "structures"});
  const auto inOutputDir = [&outputDir](const std::string& p) {
    return (fs::path(outputDir) / p).lexically_normal().string();
  };
  in.jsonPath = inOutputDir(o->string("json", "the path of the curve JSON"));
  if (o->has("csv")) in.csvPath = inOutputDir(o->string("csv", "the path of the curve CSV"));
  if (o->has("checkpoint"))
    s.checkpointPath = inOutputDir(o->string("checkpoint", "the path of the checkpoint (JSON)"));
  if (o->has("checkpoint_minutes")) {
    const double minutes = o->number("checkpoint_minutes", "minutes between checkpoints inside a point (>= 0)");
    if (!(minutes >= 0) || !std::isfinite(minutes))
      o->fail("checkpoint_minutes", fmt::format("{}", minutes),
              "a number of minutes >= 0 (0: after every relaxation step)");
    if (s.checkpointPath.empty())
      o->fail("checkpoint_minutes", fmt::format("{} without a checkpoint", minutes),
              "the key checkpoint beside it (the file the point in progress is kept in)");
    s.snapshotSeconds = 60.0 * minutes;
  }
  if (o->has("structures"))
    in.structurePrefix = inOutputDir(o->string("structures", "a path prefix for the relaxed cells"));
  s.identity = parameterIdentity(in.cell);
  if (root.has("reference")) {
    // A reference relaxed before (`mesochain chain`'s reference stage): checked against this
    // scan's settings when the scan starts (runScan), relative to the scan file like `cell`.
    const std::string file = root.string("reference", "the path of a scan reference (JSON)");
    const std::string refPath = relativeTo(path, file);
    if (!fs::is_regular_file(refPath, ec))
      root.fail("reference", "\"" + file + "\", which does not exist (looked for " + refPath + ")",
                "an existing reference JSON (the path is relative to the scan file)");
    s.reference = std::make_shared<const ScanReference>(readScanReference(refPath, in.cell.cell));
  }
  return in;
}

}  // namespace mesochain::objective
