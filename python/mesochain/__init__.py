"""mesochain from Python: objective cells, the DFTB calculator and relaxation.

The native part (``_mesochain``) binds the C++ library; quantities are the library's atomic
units (Bohr, Hartree, radians) except where a function says otherwise: the dictionaries of
:func:`cell_input` and :func:`make_input` are laid out as the cell file and use its units
(Å, degrees, K, kcal/mol), and :mod:`mesochain.ase` works in ASE's units (Å, eV).
Bad input raises :class:`InputError` (a ``ValueError`` with ``source`` and ``where``) with the
same message as the command line. See docs/python.md.
"""
from ._mesochain import (  # noqa: F401
    Calculator,
    Cell,
    CellInput,
    InputError,
    NumericalError,
    RelaxOutcome,
    RelaxStep,
    Result,
    ScanInput,
    ScanPoint,
    ScanResult,
    QuadraticFit,
    Scene,
    cell_input,
    fit_quadratic,
    input_error,
    load_scene,
    read_cell,
    read_scan,
    read_structure,
    relax,
    run_scan,
    run_scene,
    scan,
    units,
)

__all__ = [
    "Calculator", "Cell", "CellInput", "InputError", "NumericalError", "QuadraticFit",
    "RelaxOutcome", "RelaxStep", "Result", "ScanInput", "ScanPoint", "ScanResult", "Scene",
    "cell_input", "document", "fit_quadratic", "load_scene", "make_input", "read_cell",
    "read_scan", "read_structure", "relax", "run", "run_scan", "run_scene", "scan", "units",
]


def make_input(symbols, positions, *, translation, twist, rotation_order=1, kpoints=None,
               angular="all", temperature, parameters, dispersion=None, scc=None, task=None,
               source="<python>"):
    """A :class:`CellInput` from arrays, checked as the cell file is.

    symbols: element per atom; positions: (N, 3) in Å; translation: screw translation T (Å,
    0 = closed ring); twist: degrees per screw step; kpoints: number of helical k-points (None
    for a ring); angular: "all" or a number of sampled angular quantum numbers; temperature:
    electronic temperature (K); parameters: a parameter-set name such as "pbc-0-3" or a dict
    laid out as the cell file's [parameters] table; dispersion, scc, task: dicts laid out as the
    cell file's tables (None leaves them out: no dispersion, no SCC, task "energy").
    """
    import numpy as np

    positions = np.asarray(positions, dtype=float)
    symbols = list(symbols)
    if positions.ndim != 2 or positions.shape[1] != 3 or positions.shape[0] != len(symbols):
        input_error(source, "argument positions", f"an array of shape {positions.shape}",
                    f"shape ({len(symbols)}, 3): one row (x, y, z in Å) per symbol")
    doc = {
        "format": 1,
        "geometry": {"unit": "angstrom",
                     "atoms": [[s, *map(float, x)] for s, x in zip(symbols, positions)]},
        "symmetry": {"translation": translation, "twist": twist,
                     "rotation_order": rotation_order},
        "electrons": {"temperature": temperature},
        "parameters": {"set": parameters} if isinstance(parameters, str) else parameters,
    }
    k = {"angular": angular}
    if kpoints is not None:
        k["helical"] = kpoints
    doc["kpoints"] = k
    for name, table in (("dispersion", dispersion), ("scc", scc), ("task", task)):
        if table is not None:
            doc[name] = table
    return cell_input(doc, source)


def document(input):
    """The cell-file dict of a :class:`CellInput` (what ``input.write`` writes, read back with
    tomllib): change a key and read it with :func:`cell_input` for a parameter study, e.g.
    ``doc = mesochain.document(inp); doc["kpoints"]["helical"] = 32``. Inline atoms in Å,
    tables as absolute paths."""
    import os
    import tempfile
    import tomllib

    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "cell.toml")
        input.write(path)
        with open(path, "rb") as f:
            return tomllib.load(f)


CellInput.document = document


def run(input, progress=None):
    """What ``mesochain run`` computes for a cell input: its task (energy, forces or relax).

    Returns a :class:`Result` (energy, forces) or a :class:`RelaxOutcome` (relax, with the
    relaxation settings of the input's [task] table).
    """
    calc = Calculator(input)
    task = input.task
    if task["type"] == "relax":
        return relax(calc, input.cell, force_tolerance=task["force_tolerance"],
                     max_steps=task["max_steps"], relax_translation=task["relax_translation"],
                     progress=progress)
    forces = task["type"] == "forces"
    return calc.evaluate(input.cell, forces=forces, strain=forces)
