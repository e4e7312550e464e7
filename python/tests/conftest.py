"""Shared fixtures of the mesochain Python tests (run by ctest: python/CMakeLists.txt sets
PYTHONPATH to the build tree, MESOCHAIN_EXECUTABLE and MESOCHAIN_SOURCE_DIR)."""
import json
import os
import subprocess
from pathlib import Path

import pytest

SOURCE_DIR = Path(os.environ.get("MESOCHAIN_SOURCE_DIR", Path(__file__).resolve().parents[2]))
EXAMPLES = SOURCE_DIR / "examples"
CELL_DATA = SOURCE_DIR / "tests" / "data" / "cell"


def cnt55_document(helical=16, task=None):
    """The (5,5) 2-atom helical cell of examples/cnt55.toml as a cell-file dict (fewer k-points
    for speed)."""
    doc = {
        "format": 1,
        "builder": {"type": "nanotube", "n": 5, "m": 5, "cell": "helical", "bond_length": 1.42},
        "kpoints": {"helical": helical, "angular": "all"},
        "electrons": {"temperature": 300.0},
        "parameters": {"set": "pbc-0-3"},
    }
    if task is not None:
        doc["task"] = task
    return doc


def toml_text(doc):
    """A cell-file dict as TOML text (the subset the tests use: tables of scalars and arrays)."""
    def value(v):
        if isinstance(v, bool):
            return "true" if v else "false"
        if isinstance(v, str):
            return json.dumps(v)
        if isinstance(v, (list, tuple)):
            return "[" + ", ".join(value(x) for x in v) + "]"
        return repr(v)

    lines = [f"{k} = {value(v)}" for k, v in doc.items() if not isinstance(v, dict)]
    for name, table in doc.items():
        if isinstance(table, dict):
            lines.append(f"\n[{name}]")
            lines += [f"{json.dumps(k)} = {value(v)}" for k, v in table.items()]
    return "\n".join(lines) + "\n"


@pytest.fixture
def mesochain_cli():
    """Runs the mesochain program; returns the CompletedProcess (text)."""
    exe = os.environ.get("MESOCHAIN_EXECUTABLE")
    if not exe:
        pytest.fail("MESOCHAIN_EXECUTABLE is not set (run the tests through ctest)")

    def run(*args, check=True):
        p = subprocess.run([exe, *map(str, args)], capture_output=True, text=True)
        if check and p.returncode != 0:
            raise AssertionError(f"mesochain {' '.join(map(str, args))} failed ({p.returncode}):\n{p.stderr}")
        return p

    return run
