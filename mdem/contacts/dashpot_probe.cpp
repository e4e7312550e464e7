#include "mdem/contacts/dashpot_probe.hpp"

namespace mesochain::mdem {

DashpotProbe probeDashpots(const ContactDampingSpec& spec, double vdwCutoffGap,
                           const std::vector<ProbeElement>& elements, const Vec3& pivot) {
  DashpotProbe probe;
  const int n = static_cast<int>(elements.size());
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      const ProbeElement &a = elements[i], &b = elements[j];
      if (a.filament == b.filament) continue;
      double sa, sb;
      closestPoints(a.segment, b.segment, &sa, &sb);
      const Vec3 pa = a.segment.centre + sa * a.segment.axis, pb = b.segment.centre + sb * b.segment.axis;
      const double gap = (pa - pb).norm() - a.radius - b.radius;
      if (gap >= vdwCutoffGap && gap >= spec.cutoffGap) continue;
      // The dashpot's contact point and relative velocity (contact_dashpot.hpp).
      const Vec3 c = 0.5 * (pa + pb);
      const Vec3 vrel = (b.velocity + b.angularVelocity.cross(c - b.segment.centre)) -
                        (a.velocity + a.angularVelocity.cross(c - a.segment.centre));
      const double v2 = vrel.squaredNorm();
      ContactBandProbe& band = gap < spec.fullGap ? probe.full : gap < spec.cutoffGap ? probe.ramp : probe.vdwOnly;
      ++band.pairs;
      band.sumSpeedSquared += v2;
      const double lw = dashpotContact(spec, a.segment, b.segment, a.radius, b.radius).weightedLength;
      probe.weightedLength += lw;
      probe.translationalRate += lw * v2;
      probe.weightedLengthMoment += lw * (c - pivot).squaredNorm();
      probe.rotationalRate += lw * (b.angularVelocity - a.angularVelocity).squaredNorm();
    }
  return probe;
}

}  // namespace mesochain::mdem
