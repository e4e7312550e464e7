#pragma once
// What a materials scientist reads off an engineering stress-strain curve (the samples of a
// tensile test, mdem/tensile.hpp), as reported for buckypapers and CNT yarns: Young's modulus
// (the elastic slope below 3 %), the offset yield point, the ultimate (tensile) strength and the
// strain at which it occurs, the strain at failure, and the toughness (work of fracture per
// volume). Written by every tensile stage to its JSON (`NAME-tensile.json`, docs/scene-file.md).
#include <limits>
#include <string>
#include <vector>

#include "mdem/tensile.hpp"

namespace mesochain::mdem {

// The offset of the yield line: 0.2 % strain (the offset method of ASTM E8 / ISO 6892-1).
inline constexpr double kYieldOffset = 0.002;
// Failure: the stress has fallen below this fraction of the ultimate strength after it.
inline constexpr double kFailureFraction = 0.5;

struct TensileProperties {
  int samples = 0;
  ElasticFit elastic;  // Young's modulus: the slope below kElasticStrain (fitElasticSlope)
  static constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
  // The first crossing of the curve below the elastic line shifted by kYieldOffset (linear
  // between samples); NaN without an elastic slope or when the curve never crosses it.
  double yieldStrain = kNone, yieldStress = kNone;  // -, MPa
  // The largest stress of the samples and the strain of the first sample that reaches it.
  double ultimateStress = kNone, ultimateStrain = kNone;  // MPa, -
  // The first strain after the ultimate where the stress falls to kFailureFraction of it
  // (linear between samples); NaN when the test ended before.
  double failureStrain = kNone;
  // Work per volume, the trapezoid sum of stress d(strain) over the samples (MPa = MJ/m^3): up
  // to the last sample, and up to failureStrain (NaN when not reached).
  double toughness = 0.0, toughnessToFailure = kNone;
  double finalStrain = kNone, finalStress = kNone;
};

// Throws nothing: too few samples give NaN entries and elastic.fitted = false.
TensileProperties tensileProperties(const std::vector<TensileSample>& samples);

// JSON with the properties (NaN as null), the cross-section (nm^2), gauge length (nm) and strain
// rate (1/ns) they refer to and the definitions used, and the bundle-size distributions when
// given; written atomically.
void writeTensilePropertiesJson(const std::string& path, const TensileProperties& p, double crossSection,
                                double gaugeLength, double strainRate, const TensileBundles* bundles = nullptr);

}  // namespace mesochain::mdem
