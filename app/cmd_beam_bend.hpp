#pragma once
// `mesochain beam bend-curve TABLES...`: the bending stiffness against curvature beyond the
// quadratic regime (beam/bend_curve.hpp, docs/beam.md). Attached under `beam` by cmd_beam.cpp.
#include <functional>

namespace CLI {
class App;
class Validator;
}

namespace mesochain::app {

struct SubcommandHooks {
  std::function<bool()> selected;
  std::function<int()> run;
};

SubcommandHooks attachBendCurveCommand(CLI::App& beam);

// Any finite number (an energy in Hartree may have either sign).
CLI::Validator anyFiniteNumber();

}  // namespace mesochain::app
