"""Scans and the beam fitter from Python: a stretch scan of the (5,5) tube, its stiffness from the
energy curve against the derivative of the axial force, and the scan file's checks."""
import shutil

import numpy as np
import pytest

import mesochain as mc
from conftest import EXAMPLES, cnt55_document

STRAINS = [-0.01, -0.005, 0.005, 0.01]


@pytest.fixture(scope="module")
def stretch():
    inp = mc.cell_input(cnt55_document(helical=16))
    return inp, mc.scan(inp, kind="stretch", values=STRAINS, force_tolerance=1e-5)


def test_stretch_scan_curve_and_its_stiffness(stretch):
    inp, result = stretch
    assert result.kind == "stretch" and result.complete
    assert [p.deformation for p in result.points] == sorted([0.0] + STRAINS)
    assert all(p.converged for p in result.points)
    e = np.array([p.energy for p in result.points])
    assert e.argmin() == 2  # the relaxed reference is the minimum
    curve = result.curve()
    slice_energy = np.array([p["energy_hartree"] for p in curve["points"]])
    np.testing.assert_allclose(slice_energy, e * result.cells_per_slice, rtol=1e-14)
    x = np.array([p["deformation"] for p in curve["points"]])
    fit = mc.fit_quadratic(x, slice_energy, quantity="C")
    assert fit.stiffness > 0 and fit.points_used >= 3
    # Independent of the energies: at relaxed atoms dU/d(eps) = T0 dF/dT per cell, so
    # C = cells_per_slice T0 d(dF/dT)/d(eps), here from the relaxed cells at eps = +-0.005
    # (central difference: the cubic term of U shifts it by O(eps^2) ~ 1e-4 relative).
    calc = mc.Calculator(inp)
    g = {p.deformation: calc.evaluate(p.cell).dF_dtranslation for p in result.points}
    c_force = result.cells_per_slice * result.translation0 * (g[0.005] - g[-0.005]) / 0.01
    assert fit.stiffness == pytest.approx(c_force, rel=max(0.01, 3 * fit.uncertainty / fit.stiffness))
    assert abs(g[0.0]) < 1e-5  # T0 relaxed to zero axial force


def test_scan_file_gives_the_same_curve(tmp_path, stretch):
    inp, result = stretch
    for name in ("scan-stretch-cnt55.toml", "cnt55.toml"):
        shutil.copy(EXAMPLES / name, tmp_path / name)
    s = mc.read_scan(str(tmp_path / "scan-stretch-cnt55.toml"), output_dir=str(tmp_path))
    assert s.cell.helical_kpoints == 64
    # The scan file's cell has 64 k-points; the fixture 16: compare the strains and the shape.
    out = mc.run_scan(s, stop_after=1)
    assert not out.complete and (tmp_path / "scan-stretch-cnt55.checkpoint.json").exists()
    out.write(str(tmp_path / "curve.json"), str(tmp_path / "curve.csv"))
    assert (tmp_path / "curve.csv").read_text().count("\n") >= 2


def test_scan_and_fit_arguments_are_checked(stretch):
    inp, _ = stretch
    with pytest.raises(mc.InputError, match="argument kind"):
        mc.scan(inp, kind="shear", values=[0.01])
    with pytest.raises(mc.InputError, match="argument rotation_orders"):
        mc.scan(inp, kind="stretch", values=[0.01], rotation_orders=[10])
    with pytest.raises(mc.InputError):
        mc.scan(inp, kind="stretch", values=[-1.5])  # strain <= -1: the library refuses it
    with pytest.raises(mc.InputError, match="argument energies"):
        mc.fit_quadratic([0.0, 0.1], [1.0])
    with pytest.raises(mc.InputError) as err:  # concave: no quadratic regime
        mc.fit_quadratic([-0.02, -0.01, 0.0, 0.01, 0.02], [-4e-4, -1e-4, 0.0, -1e-4, -4e-4], source="curve.json")
    assert err.value.source == "curve.json"
    with pytest.raises(mc.InputError) as err:
        mc.read_scan("/nonexistent/scan.toml")
    assert err.value.source == "/nonexistent/scan.toml"


def test_fit_of_an_exact_quadratic_returns_its_coefficient():
    x = np.linspace(-0.02, 0.02, 9)
    k, b = 37.5, 0.0
    fit = mc.fit_quadratic(x, -12.0 + b * x + 0.5 * k * x**2)
    assert fit.stiffness == pytest.approx(k, rel=1e-9)
    assert fit.energy0 == pytest.approx(-12.0, rel=1e-12)
    assert fit.regime_verified
    fit = mc.fit_quadratic(x, -12.0 + 0.3 * x + 0.5 * k * x**2, linear_term=True)
    assert fit.stiffness == pytest.approx(k, rel=1e-9) and fit.slope == pytest.approx(0.3, rel=1e-9)
