"""Cells and cell inputs from files, dicts and arrays: the same reader and the same errors as the
command line."""
import json
import math
import re

import numpy as np
import pytest

import mesochain as mc
from conftest import CELL_DATA, EXAMPLES, SOURCE_DIR, cnt55_document, toml_text

U = mc.units


def test_cell_file_gives_the_roll_up_of_the_55_tube():
    inp = mc.read_cell(str(EXAMPLES / "cnt55.toml"))
    cell = inp.cell
    assert len(cell) == 2 and cell.symbols == ["C", "C"]
    assert cell.rotation_order == 5
    # Armchair (n,n): screw T = a/2 = sqrt(3) b / 2, twist = pi/n, radius = a |C| / (2 pi) with
    # a = sqrt(3) b, |C| = sqrt(3) n: R = 3 b n / (2 pi)
    # (b = 1.42 Å, the ideal roll-up).
    b = 1.42 * U.ANGSTROM_IN_BOHR
    assert cell.translation == pytest.approx(math.sqrt(3) * b / 2, rel=1e-12)
    assert cell.twist == pytest.approx(math.pi / 5, rel=1e-12)
    radius = np.hypot(cell.positions[:, 0], cell.positions[:, 1])
    np.testing.assert_allclose(radius, 3 * b * 5 / (2 * math.pi), rtol=1e-12)
    assert inp.helical_kpoints == 64 and inp.angular_samples == 0
    assert inp.electronic_temperature == pytest.approx(300 * U.BOLTZMANN_HARTREE_PER_KELVIN, rel=1e-15)
    assert inp.parameter_set == "pbc-0-3"
    assert set(inp.parameter_files) == {"C-C"}
    assert inp.task["type"] == "relax" and inp.task["relax_translation"] is True


def test_dict_and_file_read_to_the_same_input(tmp_path):
    doc = cnt55_document(helical=12, task={"type": "forces"})
    doc["dispersion"] = {"model": "lj", "epsilon": 0.07, "cutoff": 20}
    path = tmp_path / "cell.toml"
    path.write_text(toml_text(doc))
    a, b = mc.read_cell(str(path)), mc.cell_input(doc)
    assert b.source == "<dict>"
    np.testing.assert_array_equal(a.cell.positions, b.cell.positions)
    assert (a.helical_kpoints, a.parameter_files, a.dispersion, a.task) == \
        (b.helical_kpoints, b.parameter_files, b.dispersion, b.task)
    assert b.dispersion["epsilon"] == pytest.approx(0.07 / U.HARTREE_IN_KCAL_PER_MOL, rel=1e-15)


def test_arrays_give_the_same_input_as_inline_atoms():
    ref = mc.read_cell(str(CELL_DATA / "ch_chain_bohr.toml"))
    positions = ref.cell.positions * U.BOHR_IN_ANGSTROM
    inp = mc.make_input(ref.cell.symbols, positions, translation=2.5, twist=0, kpoints=8,
                        temperature=300, parameters="pbc-0-3")
    np.testing.assert_allclose(inp.cell.positions, ref.cell.positions, rtol=0, atol=1e-14)
    assert inp.cell.translation == ref.cell.translation
    assert inp.parameter_files == ref.parameter_files
    cell = mc.Cell(ref.cell.symbols, ref.cell.positions, ref.cell.translation, 0.0, 1)
    np.testing.assert_array_equal(cell.positions, ref.cell.positions)


def _found_expected(message):
    return message[message.index(": found ") :]


@pytest.mark.parametrize("section, key, bad", [
    ("kpoints", "helical", 0),
    ("electrons", "temperature", -5.0),
    ("parameters", "set", "no-such-set"),
    ("builder", "n", 0),
])
def test_errors_are_those_of_the_command_line(tmp_path, mesochain_cli, section, key, bad):
    doc = cnt55_document(task={"type": "energy"})
    doc[section][key] = bad
    with pytest.raises(mc.InputError) as err:
        mc.cell_input(doc)
    e = err.value
    assert isinstance(e, ValueError)
    assert e.source == "<dict>" and e.where == f"key {section}.{key}"
    path = tmp_path / "bad.toml"
    path.write_text(toml_text(doc))
    p = mesochain_cli("run", path, check=False)
    assert p.returncode != 0
    cli = p.stderr.strip().splitlines()[-1]
    assert re.search(rf"key {section}\.{key} \(line \d+\)", cli), cli
    # The same finding and expectation, word for word.
    assert _found_expected(str(e)) == _found_expected(cli)


def test_file_errors_carry_the_file():
    with pytest.raises(mc.InputError) as err:
        mc.read_cell("/nonexistent/cell.toml")
    assert err.value.source == "/nonexistent/cell.toml"
    doc = cnt55_document()
    doc["kpoints"]["helical"] = {1, 2}
    with pytest.raises(mc.InputError, match=r"key kpoints\.helical: found a Python set"):
        mc.cell_input(doc)
    doc = cnt55_document()
    doc["electrons"]["temprature"] = 300
    with pytest.raises(mc.InputError, match="unknown key 'temprature'"):
        mc.cell_input(doc)


def test_array_arguments_are_checked():
    with pytest.raises(mc.InputError, match=r"argument positions \(Bohr\): found an array of shape \(2, 2\)"):
        mc.Cell(["C", "C"], np.zeros((2, 2)), 2.0, 0.1, 1)
    with pytest.raises(mc.InputError) as err:  # two atoms 0.1 Bohr apart
        mc.Cell(["C", "C"], [[3.0, 0, 0], [3.1, 0, 0]], 5.0, 0.0, 1)
    assert err.value.source == "<python>"
    with pytest.raises(mc.InputError, match="non-finite"):
        mc.Cell(["C"], [[np.nan, 0, 0]], 5.0, 0.0, 1)
    with pytest.raises(mc.InputError, match="element symbol"):
        mc.Cell(["c1"], [[3.0, 0, 0]], 5.0, 0.0, 1)
    with pytest.raises(mc.InputError, match="argument positions"):
        mc.make_input(["C"], [[1, 2]], translation=2, twist=0, kpoints=4, temperature=300,
                      parameters="pbc-0-3")


def test_structure_files_and_cell_copies(tmp_path):
    cell = mc.read_structure(str(EXAMPLES / "cnt55.gen"))
    assert len(cell) == 2 and cell.rotation_order == 5
    moved = cell.with_positions(cell.positions * 1.01)
    np.testing.assert_allclose(moved.positions, cell.positions * 1.01)
    stretched = cell.with_symmetry(translation=cell.translation * 1.02)
    assert stretched.translation == pytest.approx(cell.translation * 1.02)
    assert stretched.twist == cell.twist
    path = tmp_path / "c.xyz"
    cell.write_xyz(str(path))
    back = mc.read_structure(str(path))
    np.testing.assert_allclose(back.positions, cell.positions, atol=1e-12)
    assert len(cell.unrolled(0, 2)) == 3 * 5 * 2
    ring = mc.read_cell(str(CELL_DATA / "inline_ring.toml")).cell
    with pytest.raises(mc.InputError, match="argument twist"):
        ring.with_symmetry(twist=0.1)
    with pytest.raises(mc.InputError, match="argument translation"):
        ring.with_symmetry(translation=1.0)


def test_document_of_an_input_reads_back_and_edits():
    inp = mc.read_cell(str(CELL_DATA / "inline_ring.toml"))
    doc = inp.document()
    back = mc.cell_input(doc)
    np.testing.assert_allclose(back.cell.positions, inp.cell.positions, rtol=0, atol=1e-14)
    assert (back.parameter_files, back.max_angular_momentum, back.dispersion, back.task) == \
        (inp.parameter_files, inp.max_angular_momentum, inp.dispersion, inp.task)
    assert back.electronic_temperature == pytest.approx(inp.electronic_temperature, rel=1e-15)
    doc["electrons"]["temperature"] = 500
    doc["task"] = {"type": "energy"}  # a relax task would need its keys removed by hand in a template
    hot = mc.cell_input(doc)
    assert hot.electronic_temperature == pytest.approx(500 * U.BOLTZMANN_HARTREE_PER_KELVIN, rel=1e-15)
    assert hot.task["type"] == "energy"


def test_dftbplus_input_reads_as_the_command_line_runs_it(tmp_path, mesochain_cli):
    # The same reader as `mesochain run dftb_in.hsd`: HelicalUniform { 40 0.5 } is helical = 80,
    # the UFF Lennard-Jones dispersion comes along, and the energy is the command line's.
    hsd = EXAMPLES / "dftbplus-cnt55" / "dftb_in.hsd"
    inp = mc.read_cell(str(hsd))
    assert inp.helical_kpoints == 80
    assert inp.dispersion["model"] == "lj"
    r = mc.Calculator(inp).evaluate(inp.cell)
    mesochain_cli("run", hsd, "--json", tmp_path / "out.json")
    j = json.loads((tmp_path / "out.json").read_text())
    assert r.free_energy == pytest.approx(j["energies_hartree"]["mermin_free"]["per_cell"], rel=1e-13, abs=0)
    assert r.dispersion != 0.0
    # A keyword outside the subset is the command line's error, naming the file and the line.
    bad = tmp_path / "dftb_in.hsd"
    text = hsd.read_text().replace("SCC = No", "SCC = No\n  ThirdOrderFull = Yes")
    bad.write_text(text.replace('"../../params/', '"' + str(SOURCE_DIR / "params") + "/"))
    (tmp_path / "geo.gen").write_text((hsd.parent / "geo.gen").read_text())
    with pytest.raises(mc.InputError) as err:
        mc.read_cell(str(bad))
    assert err.value.source == str(bad)
    assert "ThirdOrderFull" in err.value.where and "line" in err.value.where
