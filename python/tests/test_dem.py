"""mDEM scenes from Python: the cantilever example run as `mesochain dem` runs it, and its static
state checked against Clapeyron's theorem."""
import re

import numpy as np
import pytest

import mesochain as mc
from conftest import EXAMPLES


def test_cantilever_scene_runs_as_the_command_line_does(tmp_path, mesochain_cli):
    scene = mc.load_scene(str(EXAMPLES / "cantilever.toml"))
    assert scene.element_count == 11 and scene.bond_count == 10
    assert scene.effects == ["bonds", "local_damping"]
    # The filament: 11 centres on the z axis from the origin.
    np.testing.assert_allclose(scene.positions[:, :2], 0.0, atol=1e-15)
    assert np.all(np.diff(scene.positions[:, 2]) > 0)
    fractions = []
    out = mc.run_scene(scene, str(tmp_path / "py"), progress=fractions.append)
    assert out["stopped_by_criterion"] and out["steps"] > 0
    assert fractions and 0 < fractions[-1] <= 1
    assert (tmp_path / "py" / "energies.csv").exists()
    e = out["energies_zJ"]
    # Static state of a linear elastic structure under a constant load (Clapeyron): the stored
    # energy is half the work of the load, E_elastic = -E_load / 2. The tip turns by a few
    # hundredths of a radian, so the geometric nonlinearity stays below 1e-4 (measured: 4e-6).
    elastic = sum(e[k] for k in ("stretching", "shearing", "twisting", "bending"))
    assert elastic == pytest.approx(-e["load_potential"] / 2, rel=1e-4)
    assert out["kinetic_zJ"] < 1e-9 * elastic
    # The command line prints the same energies (8 significant digits).
    p = mesochain_cli("dem", EXAMPLES / "cantilever.toml", "-o", tmp_path / "cli")
    printed = dict(re.findall(r"(\w+) (-?[0-9.e+-]+)[,;]", p.stdout))
    for key in ("twisting", "bending", "load_potential"):
        assert float(printed[key]) == pytest.approx(e[key], rel=1e-7)


def test_scene_errors_name_the_file(tmp_path):
    with pytest.raises(mc.InputError) as err:
        mc.load_scene(str(tmp_path / "missing.toml"))
    assert err.value.source == str(tmp_path / "missing.toml")
    bad = tmp_path / "bad.toml"
    bad.write_text((EXAMPLES / "cantilever.toml").read_text().replace("count = 11", "count = -3")
                   .replace('model = "cnt-model.toml"', f'model = "{EXAMPLES / "cnt-model.toml"}"'))
    with pytest.raises(mc.InputError, match="count"):
        mc.load_scene(str(bad))
