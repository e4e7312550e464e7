// mesochain.load_scene / run_scene: mDEM scenes (mdem::loadScene, mdem::runScene; docs/scene-file.md)
// from Python, in the mdem unit system (nm, ns, ag, pN, zJ; docs/mdem-units.md).
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "mdem/run.hpp"
#include "mdem/scene_file.hpp"
#include "python/src/bindings.hpp"

namespace mesochain::python {

namespace {

py::dict ledgerDict(const mdem::EnergyLedger& e) {
  py::dict out;
  for (const mdem::LedgerEntry& x : e.entries()) out[py::str(x.name)] = x.value;
  return out;
}

py::dict summaryDict(const mdem::RunSummary& r) {
  py::dict out;
  out["steps"] = r.steps;
  out["time_ns"] = r.time;
  out["time_step_ns"] = r.timeStep;
  out["critical_time_step_ns"] = r.criticalTimeStep;
  out["stopped_by_criterion"] = r.stoppedByCriterion;
  out["resumed_from_step"] = r.resumedFromStep;
  out["energies_zJ"] = ledgerDict(r.finalEnergies);
  out["kinetic_zJ"] = r.finalEnergies.kinetic();
  out["potential_zJ"] = r.finalEnergies.potential();
  out["dissipated_zJ"] = r.finalEnergies.dissipated();
  out["wall_seconds"] = r.wallSeconds;
  if (r.tensile) {
    out["initial_stress_MPa"] = r.initialStress;
    out["final_strain"] = r.finalStrain;
    out["final_stress_MPa"] = r.finalStress;
    out["peak_stress_MPa"] = r.peakStress;
  }
  py::list stages;
  for (const mdem::StageSummary& s : r.stages) {
    py::dict d;
    d["name"] = s.name;
    d["steps"] = s.steps;
    d["time_ns"] = s.time;
    d["stopped_by_criterion"] = s.stoppedByCriterion;
    d["energies_zJ"] = ledgerDict(s.finalEnergies);
    stages.append(d);
  }
  out["stages"] = stages;
  return out;
}

py::dict runScene(const mdem::Scene& scene, const std::string& outputDirectory, bool resume,
                  bool overwrite, std::function<void(double)> progress) {
  mdem::RunOptions o;
  o.resume = resume;
  o.overwrite = overwrite;
  std::function<void(double)> report = [](double) {};
  if (progress)
    report = [progress](double fraction) {
      py::gil_scoped_acquire acquire;
      progress(fraction);
    };
  mdem::RunSummary r;
  {
    py::gil_scoped_release release;
    r = mdem::runScene(scene, outputDirectory, report, o);
  }
  return summaryDict(r);
}

}  // namespace

void bindDem(py::module_& m) {
  py::class_<mdem::Scene>(m, "Scene", "An mDEM scene as `mesochain dem` loads it (nm, ns, ag, pN, zJ).")
      .def_readonly("source", &mdem::Scene::source)
      .def_readonly("effects", &mdem::Scene::effects)
      .def_property_readonly("element_count", [](const mdem::Scene& s) { return s.bodies.size(); })
      .def_property_readonly("bond_count", [](const mdem::Scene& s) { return s.bonds.size(); })
      .def_property_readonly("positions", [](const mdem::Scene& s) {
            py::array_t<double> out({static_cast<py::ssize_t>(s.bodies.size()), py::ssize_t{3}});
            auto a = out.mutable_unchecked<2>();
            for (int i = 0; i < s.bodies.size(); ++i)
              for (int k = 0; k < 3; ++k) a(i, k) = s.bodies.position[i][k];
            return out;
          }, "(N, 3) element centres at the start (nm)");
  m.def("load_scene", &mdem::loadScene, py::arg("path"), "Read a scene file (docs/scene-file.md).");
  m.def("run_scene", &runScene, py::arg("scene"), py::arg("output_directory"), py::kw_only(),
        py::arg("resume") = false, py::arg("overwrite") = false, py::arg("progress") = nullptr,
        "Run a scene with its outputs into output_directory, as `mesochain dem -o DIR`; returns the "
        "summary (steps, time_ns, energies_zJ, ...). progress(fraction) is called as it runs.");
}

}  // namespace mesochain::python
