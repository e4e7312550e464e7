"""mesochain.ase: ASE's optimisers on helical cells, and the extended XYZ of `run --structure`
read by ASE reproducing the run's energy."""
import json

import ase.io
import numpy as np
import pytest
from ase.optimize import BFGS

import mesochain as mc
from mesochain.ase import MesochainCalculator, atoms_from_cell, info_from_input, symmetry_info
from conftest import CELL_DATA, EXAMPLES, cnt55_document, toml_text

U = mc.units
EV_PER_ANGSTROM = U.HARTREE_IN_EV * U.ANGSTROM_IN_BOHR


def _free_energy(j):
    return j["energies_hartree"]["mermin_free"]["per_cell"]


def test_ase_bfgs_relaxes_a_helical_cell_as_mesochain_does():
    inp = mc.cell_input(cnt55_document(helical=16))
    atoms = atoms_from_cell(inp)  # symmetry and settings keys in atoms.info
    atoms.positions += [[0.03, -0.02, 0.01], [-0.02, 0.01, 0.0]]  # Å, off the roll-up
    start = inp.with_cell(inp.cell.with_positions(atoms.positions * U.ANGSTROM_IN_BOHR))
    atoms.calc = MesochainCalculator()
    e0 = atoms.get_potential_energy()
    calc = mc.Calculator(start)
    assert e0 == pytest.approx(calc.evaluate(start.cell).free_energy * U.HARTREE_IN_EV, rel=1e-13)
    np.testing.assert_allclose(atoms.get_forces(), calc.evaluate(start.cell).forces * EV_PER_ANGSTROM,
                               rtol=1e-12, atol=1e-12)
    fmax = 1e-3  # eV/Å (2e-5 Ha/Bohr)
    assert BFGS(atoms, logfile=None).run(fmax=fmax, steps=200)
    e1 = atoms.get_potential_energy()
    assert e1 < e0 - 1e-3
    own = mc.relax(calc, start.cell, force_tolerance=fmax / EV_PER_ANGSTROM)
    assert own.converged
    # Both stop within the force tolerance of the same minimum: the energies differ by about
    # f^2 / k (f = 2e-5 Ha/Bohr, k ~ 0.1 Ha/Bohr^2: ~1e-8 Ha = 3e-7 eV); the geometry up to the
    # zero modes (rigid rotation about and translation along the axis): the radius and the
    # bond lengths agree.
    assert e1 == pytest.approx(own.result.free_energy * U.HARTREE_IN_EV, abs=3e-6)
    r_ase = np.hypot(*atoms.positions[:, :2].T)
    r_own = np.hypot(*(own.cell.positions[:, :2].T * U.BOHR_IN_ANGSTROM))
    np.testing.assert_allclose(np.sort(r_ase), np.sort(r_own), atol=2e-4)
    d_ase = np.linalg.norm(atoms.positions[0] - atoms.positions[1])
    d_own = np.linalg.norm(own.cell.positions[0] - own.cell.positions[1]) * U.BOHR_IN_ANGSTROM
    assert d_ase == pytest.approx(d_own, abs=2e-4)


@pytest.mark.parametrize("name, doc", [
    ("cnt55-relax", dict(cnt55_document(helical=16, task={"type": "relax", "force_tolerance": 1e-4,
                                                             "relax_translation": True}))),
    ("cnt55-lj-ewald", dict(cnt55_document(helical=8, task={"type": "forces"}),
                            dispersion={"model": "lj", "summation": "ewald", "cutoff": 15.0},
                            kpoints={"helical": 8, "angular": 3})),
    ("ring-tables-lj", None),
    ("benzene-scc", None),
])
def test_run_structure_file_reproduces_the_run_energy(tmp_path, mesochain_cli, name, doc):
    if doc is None:
        cell = {"ring-tables-lj": CELL_DATA / "inline_ring.toml",
                "benzene-scc": EXAMPLES / "benzene_scc.toml"}[name]
    else:
        cell = tmp_path / f"{name}.toml"
        cell.write_text(toml_text(doc))
    prefix = tmp_path / name
    p = mesochain_cli("run", cell, "--json", tmp_path / f"{name}.json", "--structure", prefix)
    f_run = _free_energy(json.loads((tmp_path / f"{name}.json").read_text()))
    atoms = ase.io.read(f"{prefix}.xyz")
    e_file = atoms.get_potential_energy()  # ASE's SinglePointCalculator: the file's energy
    f_file = atoms.get_forces()
    assert e_file == pytest.approx(f_run * U.HARTREE_IN_EV, rel=1e-14)
    assert "mesochain:electrons.temperature" in atoms.info
    atoms.calc = MesochainCalculator()  # settings from atoms.info
    e = atoms.get_potential_energy()
    assert e == pytest.approx(e_file, rel=1e-10, abs=0)
    np.testing.assert_allclose(atoms.get_forces(), f_file, rtol=0, atol=1e-8 + 1e-8 * np.abs(f_file).max())
    # The file's settings are the cell file's: the calculator built from the cell file agrees.
    atoms.calc = MesochainCalculator(str(cell))
    assert atoms.get_potential_energy() == pytest.approx(e_file, rel=1e-10, abs=0)
    assert p.returncode == 0


def test_settings_and_symmetry_errors_name_the_key():
    inp = mc.cell_input(cnt55_document(helical=8))
    atoms = atoms_from_cell(inp)
    del atoms.info["mesochain:twist"]
    atoms.calc = MesochainCalculator()
    with pytest.raises(mc.InputError) as err:
        atoms.get_potential_energy()
    assert err.value.source == "<atoms.info>" and err.value.where == "key mesochain:twist"
    atoms = atoms_from_cell(inp)
    atoms.info["mesochain:kpoints.helical"] = 0
    atoms.calc = MesochainCalculator()
    with pytest.raises(mc.InputError) as err:
        atoms.get_potential_energy()
    assert err.value.source == "<ase.Atoms>" and err.value.where == "key kpoints.helical"
    atoms = atoms_from_cell(inp.cell)  # symmetry only: no settings
    atoms.calc = MesochainCalculator()
    with pytest.raises(mc.InputError, match="atoms.info: found no settings keys"):
        atoms.get_potential_energy()
    atoms.info.update(info_from_input(inp))
    assert atoms.get_potential_energy() < 0
    atoms.info["mesochain:kpoint.helical"] = 4
    with pytest.raises(mc.InputError, match="unknown key 'mesochain:kpoint.helical'"):
        atoms.get_potential_energy()


def test_explicit_settings_replace_those_of_the_atoms():
    inp = mc.cell_input(cnt55_document(helical=8))
    atoms = atoms_from_cell(inp)
    ref = mc.Calculator(mc.cell_input(cnt55_document(helical=24))).evaluate(inp.cell).free_energy
    atoms.calc = MesochainCalculator({"kpoints": {"helical": 24, "angular": "all"},
                                      "electrons": {"temperature": 300.0},
                                      "parameters": {"set": "pbc-0-3"}})
    assert atoms.get_potential_energy() == pytest.approx(ref * U.HARTREE_IN_EV, rel=1e-13)
    # A change of the symmetry in atoms.info is a new calculation.
    info = info_from_input(inp)
    assert info["mesochain:kpoints.helical"] == 8
    atoms.info.update(symmetry_info(info["mesochain:translation"] * 1.01, info["mesochain:twist"], 5))
    assert atoms.get_potential_energy() != pytest.approx(ref * U.HARTREE_IN_EV, rel=1e-9)
