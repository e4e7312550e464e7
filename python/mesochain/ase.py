"""An ASE calculator for objective cells (docs/python.md).

An :class:`ase.Atoms` holds the N_o atoms of an objective cell; its symmetry is in
``atoms.info`` under the keys of mesochain's extended XYZ files:

* ``mesochain:translation`` -- screw translation T (Å, 0 = closed ring)
* ``mesochain:twist`` -- twist per screw step (degrees)
* ``mesochain:rotation_order`` -- rotation order N_a

The settings of the calculation (k-points, temperature, parameter tables, dispersion, SCC) are
``mesochain:<section>.<key>`` keys with the cell file's names and units, e.g.
``mesochain:kpoints.helical=64``, ``mesochain:electrons.temperature=300`` (K),
``mesochain:parameters.set=pbc-0-3``; ``mesochain run --structure`` writes all of them, so
``ase.io.read`` of that file plus ``MesochainCalculator()`` reproduces the run's energy.

``energy`` and ``free_energy`` are the Mermin free energy F of the cell (eV), the energy the
forces belong to and the one ``mesochain run`` reports; ``forces`` are -dF/dx (eV/Å) of the cell
atoms with all their images moving along, so ASE's optimisers relax the cell at fixed symmetry.
"""
import os

import numpy as np
from ase import Atoms
from ase.calculators.calculator import Calculator, all_changes
from ase.io.extxyz import key_val_str_to_dict

from . import _mesochain as _m

SYMMETRY_KEYS = ("mesochain:translation", "mesochain:twist", "mesochain:rotation_order")
SETTINGS_SECTIONS = ("kpoints", "electrons", "parameters", "dispersion", "scc")
SOURCE = "<atoms.info>"  # errors found in atoms.info before the cell reader; "<ase.Atoms>" after

_EV_PER_ANGSTROM = _m.units.HARTREE_IN_EV * _m.units.ANGSTROM_IN_BOHR


def symmetry_info(translation, twist, rotation_order=1):
    """The atoms.info symmetry keys: translation T (Å), twist (degrees), rotation order N_a."""
    return {"mesochain:translation": translation, "mesochain:twist": twist,
            "mesochain:rotation_order": rotation_order}


def _is_settings_key(key):
    if not key.startswith("mesochain:"):
        return False
    section, _, rest = key[len("mesochain:"):].partition(".")
    return section in SETTINGS_SECTIONS and bool(rest)


def _check_keys(info, source):
    for key in info:
        if key.startswith("mesochain:") and key not in SYMMETRY_KEYS and not _is_settings_key(key):
            _m.input_error(source, f"key {key}", f"an unknown key '{key}'",
                           "mesochain:translation, mesochain:twist, mesochain:rotation_order or a "
                           "settings key mesochain:<kpoints|electrons|parameters|dispersion|scc>.<key>")


def settings_from_info(info, source=SOURCE):
    """The settings keys of an info dict as cell-file tables ({"kpoints": {"helical": 64}, ...})."""
    _check_keys(info, source)
    sections = {}
    for key, value in info.items():
        if not _is_settings_key(key):
            continue
        path = key[len("mesochain:"):].split(".")
        table = sections
        for name in path[:-1]:
            table = table.setdefault(name, {})
            if not isinstance(table, dict):
                _m.input_error(source, f"key {key}", "a value and a table under the same name",
                               "one of them")
        if isinstance(value, np.ndarray):
            value = value.tolist()
        table[path[-1]] = value
    if "parameters" in sections and "set" in sections["parameters"]:
        # ASE turns a numeric-looking set name into a number; a set name is text.
        value = sections["parameters"]["set"]
        if not isinstance(value, bool) and isinstance(value, (int, float)):
            sections["parameters"]["set"] = str(value)
    return sections


def info_from_input(cell_input):
    """The atoms.info keys (symmetry and settings) of a :class:`mesochain.CellInput`."""
    cell = cell_input.cell
    info = _symmetry_info_of(cell)
    info.update(key_val_str_to_dict(cell_input.settings_keys()))
    return info


def _symmetry_info_of(cell):
    twist = 360.0 / cell.rotation_order if cell.is_ring else cell.twist / _m.units.DEGREE
    return symmetry_info(cell.translation * _m.units.BOHR_IN_ANGSTROM, twist, cell.rotation_order)


def atoms_from_cell(cell):
    """An :class:`ase.Atoms` of a :class:`mesochain.Cell` (symmetry keys) or a
    :class:`mesochain.CellInput` (symmetry and settings keys); positions in Å."""
    if isinstance(cell, _m.CellInput):
        info = info_from_input(cell)
        cell = cell.cell
    else:
        info = _symmetry_info_of(cell)
    return Atoms(cell.symbols, positions=cell.positions * _m.units.BOHR_IN_ANGSTROM, info=info)


def _settings_argument(settings):
    if settings is None:
        return None
    if isinstance(settings, (str, os.PathLike)):
        settings = _m.read_cell(os.fspath(settings))
    if isinstance(settings, _m.CellInput):
        return settings_from_info(key_val_str_to_dict(settings.settings_keys()), settings.source)
    if isinstance(settings, dict):
        for name in settings:
            if name not in SETTINGS_SECTIONS:
                _m.input_error("<MesochainCalculator settings>", f"key {name}",
                               f"an unknown table '{name}'",
                               "the settings tables of the cell file: " + ", ".join(SETTINGS_SECTIONS))
        return settings
    _m.input_error("<MesochainCalculator settings>", "argument settings",
                   f"a {type(settings).__name__}",
                   "None (settings from atoms.info), a cell-file path, a mesochain.CellInput or a "
                   "dict of cell-file tables")


class MesochainCalculator(Calculator):
    """mesochain's DFTB energy and forces of an objective cell, in ASE's units.

    settings: None takes the settings from the ``mesochain:<section>.<key>`` keys of
    ``atoms.info`` (as ``mesochain run --structure`` writes them); a cell-file path or a
    :class:`mesochain.CellInput` takes its k-points, temperature, tables, dispersion and SCC;
    a dict gives those tables directly in the cell-file layout, e.g.
    ``{"kpoints": {"helical": 32}, "electrons": {"temperature": 300},
    "parameters": {"set": "pbc-0-3"}}``. Given settings replace those of atoms.info.
    The symmetry always comes from atoms.info.
    """

    implemented_properties = ["energy", "free_energy", "forces", "charges"]

    def __init__(self, settings=None, **kwargs):
        super().__init__(**kwargs)
        self._settings = _settings_argument(settings)
        self._calculators = {}
        self._last_info = None
        self.mesochain_input = None
        self.mesochain_result = None

    def _info_subset(self, atoms):
        return {k: v for k, v in atoms.info.items() if k.startswith("mesochain:")}

    def check_state(self, atoms, tol=1e-15):
        changes = super().check_state(atoms, tol)
        if self._last_info is not None and repr(sorted(self._info_subset(atoms).items(), key=str)) != self._last_info:
            changes = list(changes) + ["info"]
        return changes

    def document(self, atoms):
        """The cell-file document (dict) that this calculator evaluates for `atoms`."""
        info = atoms.info
        _check_keys(info, SOURCE)
        for key in SYMMETRY_KEYS:
            if key not in info:
                _m.input_error(SOURCE, f"key {key}", "no such key (it is required)",
                               "the symmetry of the cell: mesochain:translation (Å), mesochain:twist "
                               "(degrees) and mesochain:rotation_order, as mesochain's extended XYZ "
                               "files have them (mesochain.ase.symmetry_info makes them)")
        if self._settings is None and not any(_is_settings_key(k) for k in info):
            _m.input_error(SOURCE, "atoms.info", "no settings keys mesochain:<section>.<key>",
                           "the settings keys that `mesochain run --structure` writes "
                           "(mesochain:kpoints.helical, mesochain:electrons.temperature, "
                           "mesochain:parameters.set, ...) or MesochainCalculator(settings)")
        settings = self._settings if self._settings is not None else settings_from_info(info)
        doc = {
            "format": 1,
            "geometry": {"unit": "angstrom",
                         "atoms": [[s, float(x), float(y), float(z)]
                                   for s, (x, y, z) in zip(atoms.get_chemical_symbols(), atoms.positions)]},
            "symmetry": {"translation": info["mesochain:translation"], "twist": info["mesochain:twist"],
                         "rotation_order": info["mesochain:rotation_order"]},
        }
        doc.update(settings)
        return doc

    def calculate(self, atoms=None, properties=("energy",), system_changes=all_changes):
        super().calculate(atoms, properties, system_changes)
        doc = self.document(self.atoms)
        inp = _m.cell_input(doc, "<ase.Atoms>")
        key = repr((tuple(inp.cell.symbols), sorted((k, repr(v)) for k, v in doc.items()
                                                     if k in SETTINGS_SECTIONS)))
        calc = self._calculators.get(key)
        if calc is None:
            calc = self._calculators[key] = _m.Calculator(inp)
        r = calc.evaluate(inp.cell, forces=True, strain=True)
        self.mesochain_input, self.mesochain_result = inp, r
        self._last_info = repr(sorted(self._info_subset(self.atoms).items(), key=str))
        f = r.free_energy * _m.units.HARTREE_IN_EV
        self.results = {
            "energy": f,
            "free_energy": f,
            "forces": r.forces * _EV_PER_ANGSTROM,
            "extrapolated_energy": r.extrapolated_energy * _m.units.HARTREE_IN_EV,
            "dF_dtranslation": r.dF_dtranslation * _EV_PER_ANGSTROM,  # eV/Å
            "dF_dtwist": r.dF_dtwist * _m.units.HARTREE_IN_EV * _m.units.DEGREE,  # eV/degree
        }
        if r.charges is not None:
            self.results["charges"] = r.charges
