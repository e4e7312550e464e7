// The PNG of `mesochain beam plate`: bending rigidity against the number of layers (log axis),
// the bonded plate curve, the sliding lower bound N D1, and the stacks with their uncertainties.
#include <algorithm>

#include "beam/plate_run.hpp"
#include "common/plot/figure.hpp"
#include "common/units.hpp"

namespace mesochain::beam {

plot::Image renderPlatePlot(const PlateRun& run, int width, int height) {
  constexpr double kEv = units::kHartreeInEv;
  plot::Figure f("Bending rigidity of N layers: bonded plate and sliding bound");
  const int nMax = run.layers.empty() ? 1 : run.layers.back();
  f.x = {"layers N", plot::Scale::Linear, 0.5, nMax + 0.5};
  f.y = {"bending rigidity per unit width D (eV)", plot::Scale::Log10, std::nullopt, std::nullopt};
  std::vector<double> n(run.layers.begin(), run.layers.end()), bonded, sliding;
  for (std::size_t i = 0; i < n.size(); ++i) {
    bonded.push_back(run.bonded[i] * kEv);
    sliding.push_back(run.sliding[i] * kEv);
  }
  f.add("bonded plate", n, bonded,
        {.marker = plot::Marker::Circle, .color = plot::paletteColor(0)});
  f.add("sliding layers: N D1", n, sliding,
        {.marker = plot::Marker::Triangle, .dashed = true, .color = plot::paletteColor(2)});
  std::vector<double> sn, sd;
  for (const PlateStackResult& s : run.stacks) {
    sn.push_back(s.layers);
    sd.push_back(s.rigidity * kEv);
    if (s.uncertainty > 0.0) {  // error bar (kept positive on the log axis)
      const double lo = std::max(s.rigidity - s.uncertainty, 1e-3 * s.rigidity) * kEv;
      f.add("", {sn.back(), sn.back()}, {lo, (s.rigidity + s.uncertainty) * kEv},
            {.color = plot::paletteColor(1)});
    }
  }
  if (!sn.empty())
    f.add("stacks", sn, sd,
          {.line = false, .marker = plot::Marker::Diamond, .color = plot::paletteColor(1), .markerSize = 12.0});
  return f.render(width, height);
}

}  // namespace mesochain::beam
