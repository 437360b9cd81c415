"""Minimum speed for hydrodynamic operation (shaftline.shaft.lift_off) on the seed 004 line.

Checks: the film limit is the larger of 3 x the composite roughness sqrt(Rq_j^2 + Rq_b^2)
(Hamrock & Dowson 1981; Hamrock, Schmid & Jacobson 2004 Ch. 1; Rq = sqrt(pi/2) Ra for a
Gaussian profile, ISO 4287) and the class value; hmin falls monotonically with the speed on the NTUA line (a
journal bearing's film grows with the Sommerfeld number, which is proportional to the
speed); the bisection brackets the limit to its tolerance, checked against the curve it
returns and against an independent coupled solution at each end of the bracket. The 41 x 30
film grid keeps each coupled solution near 0.07 s; the speeds differ from the 100 x 60 grid
by under 5 % (docs/validation.md).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from matplotlib.figure import Figure

from shaftline.errors import InputError
from shaftline.shaft.coupled import CoupledAlignment
from shaftline.shaft.figures import lift_off_curve
from shaftline.shaft.lift_off import FilmLimit, _at_speed, minimum_speed
from shaftline.shaft.ntua import ntua_shaft_line

GRID = (41, 30)


@pytest.fixture(scope="module")
def line_and_film():
    return ntua_shaft_line(0.3, grid=GRID)


@pytest.fixture(scope="module")
def sweep(line_and_film):
    line, film = line_and_film
    return minimum_speed(line, [film], FilmLimit(class_value=30e-6), tolerance=0.01)


def test_limit_is_the_larger_of_roughness_and_class_value():
    limit = FilmLimit(journal_roughness=1e-6, bore_roughness=2e-6)
    assert limit.composite_roughness == pytest.approx(math.sqrt(5.0) * 1e-6, rel=1e-12)
    assert limit.value == pytest.approx(3.0 * math.sqrt(5.0) * 1e-6, rel=1e-12)
    ra = FilmLimit(journal_roughness=1e-6, bore_roughness=2e-6, roughness_parameter="Ra")
    assert ra.composite_roughness == pytest.approx(math.sqrt(math.pi / 2.0) * limit.composite_roughness, rel=1e-12)
    assert FilmLimit(class_value=30e-6).value == 30e-6
    assert FilmLimit(class_value=1e-6).value == limit.value


def test_curve_is_monotonic_and_the_bracket_holds_the_limit(sweep, line_and_film):
    result = sweep
    assert result.message == "" and result.governing == "aft stern tube"
    assert result.solutions >= 8
    hmin = result.min_film[0]
    assert np.all(np.diff(result.speeds) > 0)
    assert np.all(np.diff(hmin) > 0)  # smaller film at every lower speed
    low, high = result.bracket
    assert result.speed == high
    assert high <= low * 1.01
    at = {float(s): h for s, h in zip(result.speeds, hmin, strict=True)}
    assert at[low] < 30e-6 <= at[high]
    # Independently: a fresh coupled solution at each end of the bracket.
    line, film = line_and_film
    for speed, above in ((high, True), (low, False)):
        again = CoupledAlignment(line, _at_speed([film], speed)).solve().films[0].state.min_film_thickness
        assert (again >= 30e-6) is above
    # About 62 rpm on this grid (61.5 on 100 x 60): well below the seed's 90 rpm.
    assert 55.0 < high * 30.0 / math.pi < 70.0


def test_roughness_limit_gives_a_lower_speed(line_and_film, sweep):
    line, film = line_and_film
    rough = minimum_speed(line, [film], tolerance=0.02)
    assert rough.limit == pytest.approx(FilmLimit().value)
    assert rough.bracket[1] <= rough.bracket[0] * 1.02
    assert rough.speed < sweep.speed


def test_messages_at_the_ends(line_and_film):
    line, film = line_and_film
    calls = []
    above = minimum_speed(line, [film], 200e-6, points=2, progress=lambda *args: calls.append(args))
    assert math.isnan(above.speed) and "operating speed" in above.message
    top = film.problem.operating.speed
    # the documented bracket (nan, top), and the message in the units of the report
    assert math.isnan(above.bracket[0]) and above.bracket[1] == top
    assert f"(200 µm) at the operating speed ({top * 30 / math.pi:.4g} rpm)" in above.message
    assert [c[0] for c in calls] == [1] and calls[0][1] == film.problem.operating.speed
    low = minimum_speed(line, [film], 1e-6, lowest=0.8, points=2)
    assert low.bracket[0] == 0.0 and "lowest speed" in low.message and low.governing == ""


def test_figure_draws_curve_limit_and_speed(sweep):
    ax = Figure().add_subplot()  # not pyplot's: the session's backend stays as it is
    assert lift_off_curve(sweep, ax=ax) is ax
    labels = [line.get_label() for line in ax.get_lines()]
    assert "aft stern tube" in labels
    assert any(label.startswith("limit") for label in labels)
    assert any(label.startswith("minimum speed") for label in labels)


def test_bad_input(line_and_film):
    line, film = line_and_film
    with pytest.raises(InputError, match="films"):
        minimum_speed(line, [])
    with pytest.raises(InputError, match="lowest"):
        minimum_speed(line, [film], lowest=1.0)
    with pytest.raises(InputError, match="tolerance"):
        minimum_speed(line, [film], tolerance=0.0)
    with pytest.raises(InputError, match="journal_roughness"):
        FilmLimit(journal_roughness=2e-3)
    with pytest.raises(InputError, match="roughness_parameter"):
        FilmLimit(roughness_parameter="Rz")  # type: ignore[arg-type]
