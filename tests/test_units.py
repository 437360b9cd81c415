"""Quantities at the case-file boundary."""

from __future__ import annotations

import math

import pytest

from shaftline.errors import InputError
from shaftline.units import to_si


@pytest.mark.parametrize(
    "value, kind, expected",
    [
        ("0.45 mm", "length", 0.45e-3),
        (0.52, "length", 0.52),
        ("90 rpm", "speed", 3 * math.pi),
        ("1.5 Hz", "speed", 3 * math.pi),
        ("9.42 rad/s", "speed", 9.42),
        ("40 degC", "temperature", 40.0),
        ("313.15 K", "temperature", 40.0),
        ("70 cP", "viscosity", 0.07),
        ("68 cSt", "kinematic_viscosity", 68e-6),
        ("309.86 kN", "force", 309860.0),
        ("0.3 mrad", "angle", 3e-4),
        ("2 bar", "pressure", 2e5),
        # an exponent before a unit that does not start with a letter (was read as 5 "e9 /m^2")
        ("5e9 /m^2", "areal_density", 5e9),
        ("4e2 1/mm^2", "areal_density", 4e8),
        ("3e2 1/min", "frequency", 5.0),
        ("1.5e-3 m", "length", 1.5e-3),
    ],
)
def test_conversion(value, kind, expected):
    assert to_si(value, kind, "x") == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize(
    "value, kind, fragment",
    [
        ("0.5 kg", "length", "quantity of length"),
        ("3 furlongz", "length", "known unit"),
        ("nan mm", "length", "finite"),
        (float("nan"), "length", "finite"),
        (True, "length", "number"),
    ],
)
def test_bad_quantities(value, kind, fragment):
    with pytest.raises(InputError) as error:
        to_si(value, kind, "bearing.length")
    assert error.value.field == "bearing.length"
    assert fragment in str(error.value)


@pytest.mark.parametrize(
    "value, kind",
    [
        ("0.45 mm", "length"),
        ("-3.5 mm", "length"),
        ("90 rpm", "speed"),
        ("1.5 Hz", "speed"),
        ("40 degC", "temperature"),
        ("313.15 K", "temperature"),
        ("68 cSt", "kinematic_viscosity"),
        ("2.5e-2 MPa", "pressure"),
        ("0.3 mrad", "angle"),
    ],
)
def test_remembered_conversion_equals_pint(value, kind, tmp_path, monkeypatch):
    """The remembered affine map of a unit gives pint's result for any number (here: the
    first number, which stores the map, and another one with the same unit)."""
    import shaftline.units as units

    monkeypatch.setenv("SHAFTLINE_CACHE_DIR", str(tmp_path))
    units._remembered.cache_clear()
    number, unit = value.split(" ")
    first = to_si(value, kind, "x")
    assert units._remembered()[f"{kind}|{unit}"]  # stored
    other = f"{float(number) * 7.25} {unit}"
    assert to_si(other, kind, "x") == pytest.approx(units._parse_with_unit(other, kind, "x"), rel=1e-12, abs=1e-12)
    assert first == pytest.approx(units._parse_with_unit(value, kind, "x"), rel=1e-12, abs=1e-12)
    units._remembered.cache_clear()


def test_a_known_unit_needs_no_pint(tmp_path):
    """After one run has converted "mm", another converts "0.45 mm" without importing pint;
    a damaged cache file only means pint is used again."""
    import os
    import subprocess
    import sys

    script = (
        "import sys; from shaftline.units import to_si; print(to_si('0.45 mm', 'length', 'x'), 'pint' in sys.modules)"
    )
    env = {**os.environ, "SHAFTLINE_CACHE_DIR": str(tmp_path)}
    run = lambda: subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, env=env, check=True)  # noqa: E731
    for cache, pint_imported in (("first run", "True"), ("remembered", "False"), ("damaged", "True")):
        if cache == "damaged":
            (tmp_path / "unit-conversions-1.json").write_text("{not json")
        value, imported = run().stdout.split()
        assert float(value) == pytest.approx(0.45e-3, rel=1e-15) and imported == pint_imported, cache


def test_a_refused_unit_is_refused_again_without_pint(tmp_path):
    """A unit of the wrong dimension ("0.1 kg" for a length) gives the same one-line message
    the second time without importing pint, and a remembered refusal holds for that kind only
    ("kg" stays a mass)."""
    import os
    import subprocess
    import sys

    script = (
        "import sys\n"
        "from shaftline.errors import InputError\n"
        "from shaftline.units import to_si\n"
        "try:\n"
        "    to_si(sys.argv[1], sys.argv[2], 'bearing.radial_clearance')\n"
        "except InputError as error:\n"
        "    print(error, '|', 'pint' in sys.modules)\n"
        "else:\n"
        "    print('accepted |', 'pint' in sys.modules)\n"
    )
    env = {**os.environ, "SHAFTLINE_CACHE_DIR": str(tmp_path)}

    def run(text: str, kind: str) -> list[str]:
        done = subprocess.run([sys.executable, "-c", script, text, kind], capture_output=True, text=True, env=env)
        return [part.strip() for part in done.stdout.split("|")]

    first, pint_first = run("0.1 kg", "length")
    again, pint_again = run("0.2 kg", "length")
    assert "a quantity of length (got unit kg)" in first and pint_first == "True"
    assert again == first.replace("0.1 kg", "0.2 kg") and pint_again == "False"
    assert run("3 kg", "mass") == ["accepted", "True"]
