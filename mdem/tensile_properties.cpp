#include "mdem/tensile_properties.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <nlohmann/json.hpp>

#include "common/atomic_file.hpp"
#include "common/build_info.hpp"

namespace mesochain::mdem {

namespace {

// The strain where f changes sign from f0 >= 0 at e0 to f1 < 0 at e1 (linear between them).
double crossing(double e0, double f0, double e1, double f1) { return e0 + (e1 - e0) * f0 / (f0 - f1); }

// The trapezoid sum of stress d(strain) over the samples, up to strain `upTo` (the interval that
// holds it cut there, linearly).
double workUpTo(const std::vector<TensileSample>& s, double upTo) {
  double w = 0.0;
  for (std::size_t k = 1; k < s.size() && s[k - 1].strain < upTo; ++k) {
    const double e0 = s[k - 1].strain, e1 = std::min(s[k].strain, upTo);
    if (e1 == e0) continue;  // a repeated strain: no width, no work
    const double s1 = s[k - 1].stress + (e1 - e0) / (s[k].strain - e0) * (s[k].stress - s[k - 1].stress);
    w += 0.5 * (s[k - 1].stress + s1) * (e1 - e0);
  }
  return w;
}

nlohmann::json numberOrNull(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

}  // namespace

TensileProperties tensileProperties(const std::vector<TensileSample>& s) {
  TensileProperties p;
  p.samples = static_cast<int>(s.size());
  p.elastic = fitElasticSlope(s, 0.0, kElasticStrain);
  if (s.empty()) return p;
  p.finalStrain = s.back().strain, p.finalStress = s.back().stress;
  std::size_t peak = 0;
  for (std::size_t k = 1; k < s.size(); ++k)
    if (s[k].stress > s[peak].stress) peak = k;
  p.ultimateStress = s[peak].stress, p.ultimateStrain = s[peak].strain;
  if (p.elastic.fitted) {
    // Above minus below the offset line: the first change of sign past the offset strain.
    const auto above = [&](const TensileSample& t) {
      return t.stress - (p.elastic.intercept + p.elastic.slope * (t.strain - kYieldOffset));
    };
    for (std::size_t k = 1; k < s.size(); ++k) {
      const double f0 = above(s[k - 1]), f1 = above(s[k]);
      if (s[k].strain > kYieldOffset && f0 >= 0.0 && f1 < 0.0) {
        p.yieldStrain = crossing(s[k - 1].strain, f0, s[k].strain, f1);
        const double w = (p.yieldStrain - s[k - 1].strain) / (s[k].strain - s[k - 1].strain);
        p.yieldStress = s[k - 1].stress + w * (s[k].stress - s[k - 1].stress);
        break;
      }
    }
  }
  const double threshold = kFailureFraction * p.ultimateStress;
  if (p.ultimateStress > 0.0)
    for (std::size_t k = peak + 1; k < s.size(); ++k)
      if (s[k].stress <= threshold) {
        p.failureStrain = crossing(s[k - 1].strain, s[k - 1].stress - threshold, s[k].strain, s[k].stress - threshold);
        break;
      }
  p.toughness = workUpTo(s, std::numeric_limits<double>::infinity());
  if (std::isfinite(p.failureStrain)) p.toughnessToFailure = workUpTo(s, p.failureStrain);
  return p;
}

void writeTensilePropertiesJson(const std::string& path, const TensileProperties& p, double crossSection,
                                double gaugeLength, double strainRate, const TensileBundles* bundles) {
  nlohmann::json j;
  j["format"] = 1;
  j["kind"] = "tensile_properties";
  j["program"] = buildInfoJson();
  j["samples"] = p.samples;
  j["cross_section_nm2"] = crossSection;
  j["gauge_length_nm"] = gaugeLength;
  j["strain_rate_per_ns"] = strainRate;
  nlohmann::json e = {{"fitted", p.elastic.fitted}, {"samples", p.elastic.samples}};
  e["youngs_modulus_MPa"] = p.elastic.fitted ? nlohmann::json(p.elastic.slope) : nlohmann::json(nullptr);
  e["intercept_MPa"] = p.elastic.fitted ? nlohmann::json(p.elastic.intercept) : nlohmann::json(nullptr);
  e["r2"] = p.elastic.fitted ? nlohmann::json(p.elastic.r2) : nlohmann::json(nullptr);
  e["strain_from"] = p.elastic.samples > 0 ? nlohmann::json(p.elastic.from) : nlohmann::json(nullptr);
  e["strain_to"] = p.elastic.samples > 0 ? nlohmann::json(p.elastic.to) : nlohmann::json(nullptr);
  e["fitted_below_strain"] = kElasticStrain;
  j["elastic"] = e;
  j["yield"] = {{"strain", numberOrNull(p.yieldStrain)}, {"stress_MPa", numberOrNull(p.yieldStress)},
                {"offset_strain", kYieldOffset}};
  j["ultimate"] = {{"stress_MPa", numberOrNull(p.ultimateStress)}, {"strain", numberOrNull(p.ultimateStrain)}};
  j["failure"] = {{"strain", numberOrNull(p.failureStrain)}, {"stress_fraction_of_ultimate", kFailureFraction}};
  j["toughness_MJ_per_m3"] = {{"to_last_sample", p.toughness}, {"to_failure", numberOrNull(p.toughnessToFailure)}};
  j["final"] = {{"strain", numberOrNull(p.finalStrain)}, {"stress_MPa", numberOrNull(p.finalStress)}};
  j["definitions"] = {
      {"elastic", "least-squares line of stress against strain below fitted_below_strain"},
      {"yield", "first crossing below the elastic line shifted right by offset_strain (linear between samples)"},
      {"ultimate", "largest engineering stress and the strain of the first sample reaching it"},
      {"failure", "first strain after the ultimate where the stress falls to stress_fraction_of_ultimate of it"},
      {"toughness", "trapezoid sum of stress d(strain); 1 MPa = 1 MJ/m^3"}};
  if (bundles) {
    nlohmann::json b;
    b["definition"] =
        "connected groups of elements joined by contacts (wall gap < contact_gap_nm) whose axes cross below aligned_angle_deg; "
        "sizes in elements, classes [from, to) with the bundles in each and the fraction of all elements they hold";
    b["contact_gap_nm"] = bundles->contactGap;
    b["aligned_angle_deg"] = bundles->alignedAngle * 180.0 / 3.14159265358979323846;
    b["stage_start"] = bundleSizesJson(bundles->start);
    b["stage_start"]["strain"] = bundles->startStrain;
    b["stage_end"] = bundleSizesJson(bundles->end);
    b["stage_end"]["strain"] = bundles->endStrain;
    j["bundle_size_distribution"] = b;
  }
  writeFileAtomically(path, j.dump(2) + "\n");
}

}  // namespace mesochain::mdem
