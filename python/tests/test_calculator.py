"""The calculator from Python: energies and NumPy arrays against the command line, forces and
strain derivatives against finite differences, SCC charges, relaxation."""
import json

import numpy as np
import pytest

import mesochain as mc
from conftest import EXAMPLES, cnt55_document, toml_text


@pytest.fixture(scope="module")
def cnt55():
    inp = mc.cell_input(cnt55_document(helical=16, task={"type": "forces"}))
    return inp, mc.Calculator(inp)


def test_energy_and_forces_equal_the_command_line(tmp_path, mesochain_cli, cnt55):
    inp, calc = cnt55
    r = calc.evaluate(inp.cell)
    path = tmp_path / "cnt55.toml"
    path.write_text(toml_text(cnt55_document(helical=16, task={"type": "forces"})))
    mesochain_cli("run", path, "--json", tmp_path / "out.json")
    j = json.loads((tmp_path / "out.json").read_text())
    # The results JSON of `run` holds the same numbers (Hartree, Hartree/Bohr).
    f_cli = j["energies_hartree"]["mermin_free"]["per_cell"]
    np.testing.assert_allclose(r.forces, j["forces_hartree_per_bohr"], rtol=1e-12, atol=1e-15)
    assert r.dF_dtranslation == pytest.approx(-j["axial_force_hartree_per_bohr"], rel=1e-12)
    assert r.free_energy == pytest.approx(f_cli, rel=1e-13, abs=0)
    assert r.forces.shape == (2, 3) and r.gradient.shape == (2, 3)
    np.testing.assert_array_equal(r.forces, -r.gradient)
    assert r.total_energy - r.entropy_term == pytest.approx(r.free_energy, rel=1e-14)
    assert r.band_energy + r.repulsive + r.scc + r.dispersion == pytest.approx(r.total_energy, rel=1e-14)


def test_forces_are_minus_the_finite_difference_gradient(cnt55):
    inp, calc = cnt55
    cell = inp.cell
    x0 = cell.positions
    rng = np.random.default_rng(7)
    cell = cell.with_positions(x0 + 0.02 * rng.standard_normal(x0.shape))  # off equilibrium
    r = calc.evaluate(cell)
    h = 1e-4  # Bohr; central differences: error ~ h^2 F''' ~ 1e-9 Ha/Bohr
    for atom in range(len(cell)):
        for k in range(3):
            xp, xm = cell.positions, cell.positions
            xp[atom, k] += h
            xm[atom, k] -= h
            fd = (calc.evaluate(cell.with_positions(xp), forces=False, strain=False).free_energy
                  - calc.evaluate(cell.with_positions(xm), forces=False, strain=False).free_energy) / (2 * h)
            assert r.gradient[atom, k] == pytest.approx(fd, abs=2e-7)


def test_strain_derivatives_are_finite_differences(cnt55):
    inp, calc = cnt55
    cell = inp.cell
    r = calc.evaluate(cell)
    ht, hg = 1e-4, 1e-5  # Bohr, rad
    def f(c):
        return calc.evaluate(c, forces=False, strain=False).free_energy
    dT = (f(cell.with_symmetry(translation=cell.translation + ht))
          - f(cell.with_symmetry(translation=cell.translation - ht))) / (2 * ht)
    dg = (f(cell.with_symmetry(twist=cell.twist + hg)) - f(cell.with_symmetry(twist=cell.twist - hg))) / (2 * hg)
    assert abs(r.dF_dtranslation) > 1e-4  # the roll-up is not at zero axial force
    assert r.dF_dtranslation == pytest.approx(dT, rel=1e-5)
    assert r.dF_dtwist == pytest.approx(dg, abs=1e-6 * max(1.0, abs(dg)))


def test_scc_charges_are_neutral_and_symmetric():
    inp = mc.read_cell(str(EXAMPLES / "benzene_scc.toml"))
    r = mc.Calculator(inp).evaluate(inp.cell)
    q = r.charges
    assert q.shape == (2,)
    # One CH unit of C_6 benzene: the cell is neutral, carbon takes electrons from hydrogen.
    assert q.sum() == pytest.approx(0.0, abs=1e-8)
    assert q[0] < 0 < q[1]
    assert r.extras["scc_converged"] == 1.0
    assert mc.Calculator(mc.read_cell(str(EXAMPLES / "cnt55.toml"))).evaluate(
        mc.read_cell(str(EXAMPLES / "cnt55.toml")).cell, forces=False).charges is None


def test_relaxation_lowers_the_energy_to_the_force_tolerance(cnt55):
    inp, calc = cnt55
    start = inp.cell.with_positions(inp.cell.positions + [[0.05, -0.03, 0.02], [-0.04, 0.02, 0.0]])
    seen = []
    out = mc.relax(calc, start, force_tolerance=1e-5, progress=lambda n, f, fmax: seen.append((n, f, fmax)))
    assert out.converged
    # progress reports accepted steps, numbered by the evaluation count (line-search trials
    # are evaluations too): increasing numbers up to the total, the last at the final energy.
    steps = [n for n, _, _ in seen]
    assert steps == sorted(set(steps)) and 0 < steps[-1] <= out.evaluations
    assert seen[-1][1] == pytest.approx(out.result.free_energy, rel=1e-13)
    assert seen[-1][2] <= 1e-5
    f0 = calc.evaluate(start, forces=False).free_energy
    assert out.result.free_energy < f0
    check = calc.evaluate(out.cell)
    assert np.abs(check.forces).max() <= 1e-5 * 1.0001
    assert check.free_energy == pytest.approx(out.result.free_energy, rel=1e-14)
    with pytest.raises(mc.InputError, match="argument force_tolerance"):
        mc.relax(calc, start, force_tolerance=-1)
    with pytest.raises(mc.InputError, match="argument algorithm"):
        mc.relax(calc, start, algorithm="newton")


def test_a_python_exception_in_progress_stops_the_relaxation(cnt55):
    inp, calc = cnt55
    def stop(n, f, fmax):
        raise RuntimeError("stop here")
    with pytest.raises(RuntimeError, match="stop here"):
        mc.relax(calc, inp.cell, progress=stop)


def test_run_follows_the_task_of_the_input():
    inp = mc.cell_input(cnt55_document(helical=8, task={"type": "relax", "force_tolerance": 1e-4,
                                                          "relax_translation": True}))
    out = mc.run(inp)
    assert isinstance(out, mc.RelaxOutcome) and out.converged
    assert abs(out.result.dF_dtranslation) < 1e-4
    assert out.cell.translation != inp.cell.translation
    energy = mc.run(mc.cell_input(cnt55_document(helical=8)))
    assert isinstance(energy, mc.Result) and energy.gradient is None


def test_eigenvalues_refill_to_the_band_energy_electrons_and_entropy(cnt55):
    inp, calc = cnt55
    r = calc.evaluate(inp.cell, forces=False, strain=False)
    e, w = r.eigenvalues, r.series["kpoint_weight"]
    assert e.shape == (len(w), int(r.extras["orbitals"])) and len(w) == int(r.extras["kpoints"])
    assert np.all(np.diff(e, axis=1) >= 0)
    assert w.sum() == pytest.approx(1.0, rel=1e-14)
    assert set(r.series["kpoint_mu"]) <= set(range(inp.cell.rotation_order))
    # Fermi-Dirac filling of the levels at the reported Fermi level, two electrons per level:
    # the electron count, sum f e and -TS = 2 kT sum w [f ln f + (1 - f) ln(1 - f)].
    kT, mu = inp.electronic_temperature, r.extras["fermi_level"]
    f = 0.5 * (1.0 - np.tanh((e - mu) / (2 * kT)))  # 1 / (1 + exp((e - mu) / kT)), no overflow
    assert 2 * (w[:, None] * f).sum() == pytest.approx(r.extras["electrons"], rel=1e-12)
    assert 2 * (w[:, None] * f * e).sum() == pytest.approx(r.band_energy, rel=1e-12)
    fc = np.clip(f, 1e-300, 1 - 1e-16)
    ts = -2 * kT * (w[:, None] * (fc * np.log(fc) + (1 - fc) * np.log1p(-fc))).sum()
    assert ts == pytest.approx(r.entropy_term, rel=1e-9)
