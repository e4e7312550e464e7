// mesochain.fit_quadratic: the beam fitter's stiffness of an energy curve in its quadratic
// regime (beam::fitQuadraticRegime, docs/beam.md), e.g. C from a stretch scan.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "beam/curve_fit.hpp"
#include "common/errors.hpp"
#include "python/src/bindings.hpp"

namespace mesochain::python {

namespace {

beam::QuadraticFit fit(const std::vector<double>& x, const std::vector<double>& energy, bool linearTerm,
                       double relativeTolerance, double zScore, const std::string& source,
                       const std::string& quantity) {
  if (x.size() != energy.size())
    throw InputError(source, "argument energies",
                     std::to_string(energy.size()) + " energies for " + std::to_string(x.size()) + " deformations",
                     "one energy per deformation");
  if (!(relativeTolerance > 0))
    throw InputError(source, "argument relative_tolerance", std::to_string(relativeTolerance), "a positive number");
  if (!(zScore > 0)) throw InputError(source, "argument z_score", std::to_string(zScore), "a positive number");
  std::vector<beam::CurvePoint> points;
  for (std::size_t i = 0; i < x.size(); ++i) {
    requireFinite(x[i], source, "argument deformations");
    requireFinite(energy[i], source, "argument energies");
    points.push_back({x[i], energy[i]});
  }
  beam::FitOptions o;
  o.linearTerm = linearTerm;
  o.relativeTolerance = relativeTolerance;
  o.zScore = zScore;
  o.source = source;
  o.quantity = quantity;
  return beam::fitQuadraticRegime(std::move(points), o);
}

}  // namespace

void bindBeamFit(py::module_& m) {
  py::class_<beam::WindowFit>(m, "WindowFit")
      .def_readonly("half_width", &beam::WindowFit::halfWidth)
      .def_readonly("points", &beam::WindowFit::points)
      .def_readonly("stiffness", &beam::WindowFit::stiffness)
      .def_readonly("standard_error", &beam::WindowFit::standardError)
      .def_readonly("anharmonicity", &beam::WindowFit::anharmonicity)
      .def_readonly("accepted", &beam::WindowFit::accepted)
      .def_readonly("rejection", &beam::WindowFit::rejection);
  py::class_<beam::QuadraticFit>(m, "QuadraticFit")
      .def_readonly("stiffness", &beam::QuadraticFit::stiffness, "k: energy per x^2 (U = U0 + b x + k x^2 / 2)")
      .def_readonly("uncertainty", &beam::QuadraticFit::uncertainty)
      .def_readonly("statistical_error", &beam::QuadraticFit::statisticalError)
      .def_readonly("truncation_error", &beam::QuadraticFit::truncationError)
      .def_readonly("window_spread", &beam::QuadraticFit::windowSpread)
      .def_readonly("slope", &beam::QuadraticFit::slope)
      .def_readonly("energy0", &beam::QuadraticFit::energy0)
      .def_readonly("window_half_width", &beam::QuadraticFit::windowHalfWidth)
      .def_readonly("points_used", &beam::QuadraticFit::pointsUsed)
      .def_readonly("points_total", &beam::QuadraticFit::pointsTotal)
      .def_readonly("regime_verified", &beam::QuadraticFit::regimeVerified)
      .def_readonly("windows", &beam::QuadraticFit::windows)
      .def_readonly("note", &beam::QuadraticFit::note);
  m.def("fit_quadratic", &fit, py::arg("deformations"), py::arg("energies"), py::kw_only(),
        py::arg("linear_term") = false, py::arg("relative_tolerance") = 0.02, py::arg("z_score") = 3.0,
        py::arg("source") = "<python>", py::arg("quantity") = "k",
        "The stiffness k of U(x) = U0 (+ b x) + k x^2 / 2 in the curve's quadratic regime, the window "
        "found as `mesochain beam` finds it; InputError when the curve has none.");
}

}  // namespace mesochain::python
