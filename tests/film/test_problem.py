"""The problem data: light to import, Literal choices defined once, results compare by identity."""

from __future__ import annotations

import ast
import os
import subprocess
import sys
import typing
from dataclasses import fields
from pathlib import Path

import numpy as np
import pytest

import shaftline
import shaftline.film
from shaftline.errors import InputError
from shaftline.film import (
    BearingGeometry,
    BentJournal,
    FilmProfile,
    JournalPosition,
    SolverOptions,
    dynamic_coefficients,
    geometry,
    problem,
)
from shaftline.film.cavitation import CAVITATION_MODELS, HalfSommerfeld, ReynoldsCondition
from tests.conftest import CLEARANCE, make_bearing

HEAVY = ("scipy", "qdldl", "shaftline.film.bearing", "shaftline.film.solver", "shaftline.film.dynamics")


def _loaded_after(code: str) -> list[str]:
    """Heavy modules loaded by ``code`` in a fresh interpreter on this source tree."""
    source = str(Path(shaftline.__file__).resolve().parents[1])
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([source, os.environ.get("PYTHONPATH", "")]))
    probe = f"{code}\nimport sys\nprint(sorted(m for m in sys.modules if m.startswith({HEAVY!r})))"
    result = subprocess.run([sys.executable, "-c", probe], env=env, capture_output=True, text=True, check=True)
    return ast.literal_eval(result.stdout.strip().splitlines()[-1])


def test_problem_dataclasses_import_without_the_solver():
    """The command line and the case schema read these; scipy and qdldl cost most of a start-up."""
    loaded = _loaded_after(
        "import shaftline.film.problem\n"
        "from shaftline.film import (BearingGeometry, BearingProblem, BentJournal, BoreSegment, FilmProfile,\n"
        "    JournalPosition, OperatingPoint, SolverOptions, SupplyGroove)\n"
        "BearingProblem(BearingGeometry(0.1, 0.1, 1e-4), OperatingPoint(speed=10.0, viscosity=0.02))"
    )
    assert loaded == []


def test_the_solver_loads_with_the_first_name_that_needs_it():
    """The film solver (``shaftline.film.solver``, with scipy) loads with ``JournalBearing``; the
    cavitation models import qdldl where they first factorise, so it is loaded by a first solve."""
    loaded = _loaded_after("from shaftline.film import JournalBearing")
    assert "scipy" in loaded and "shaftline.film.solver" in loaded
    solved = _loaded_after(
        "from shaftline.film import BearingGeometry, JournalBearing, JournalPosition, OperatingPoint\n"
        "bearing = JournalBearing(BearingGeometry(0.1, 0.1, 1e-4), OperatingPoint(speed=10.0, viscosity=0.02))\n"
        "bearing.solve_at(JournalPosition(ey=-5e-5))"
    )
    assert "qdldl" in solved and "shaftline.film.solver" in solved


def test_every_public_name_of_the_package_resolves():
    for name in shaftline.film.__all__:
        assert getattr(shaftline.film, name) is not None
    with pytest.raises(AttributeError):
        shaftline.film.NoSuchThing  # noqa: B018


def test_choices_are_literal_types_defined_once():
    """A schema reads the choices from the annotations; the checks use the same tuples."""
    options = typing.get_type_hints(SolverOptions)
    names = ("reynolds", "jfo", "half_sommerfeld")
    assert typing.get_args(options["cavitation"]) == tuple(problem.CAVITATION_MODELS) == names
    assert typing.get_args(options["film_start"]) == problem.FILM_STARTS == ("periodic", "max_film")
    assert typing.get_args(options["cavitated_shear"]) == problem.CAVITATED_SHEARS == ("film_fraction", "full_film")
    shape = typing.get_type_hints(BearingGeometry)
    assert typing.get_args(shape["bore_anchor"]) == geometry.BORE_ANCHORS == ("fore", "aft", "mid")
    assert typing.get_args(shape["rotation"]) == geometry.ROTATIONS == (1, -1)
    # one registry: the problem's names are the cavitation package's, a read-only mapping of
    # each name to its model class
    assert problem.CAVITATION_MODELS is CAVITATION_MODELS
    assert all(model.name == name for name, model in CAVITATION_MODELS.items())
    with pytest.raises(TypeError):
        CAVITATION_MODELS["mine"] = ReynoldsCondition  # type: ignore[index]
    # every choice a schema would offer is accepted, and one outside them is not
    for cavitation, model in CAVITATION_MODELS.items():
        assert SolverOptions(cavitation=cavitation).cavitation == cavitation
        assert SolverOptions(cavitation=cavitation).cavitation_model is model
    for start in problem.FILM_STARTS:
        SolverOptions(film_start=start)
    for shear in problem.CAVITATED_SHEARS:
        SolverOptions(cavitated_shear=shear)
    for anchor in geometry.BORE_ANCHORS:
        BearingGeometry(0.1, 0.1, 1e-4, bore_anchor=anchor)


def test_an_unknown_cavitation_model_is_refused_naming_the_registry():
    """A name outside :data:`CAVITATION_MODELS` is bad input, named as the field, with every name
    of the registry in the message: from Python (``SolverOptions``) and from a case file (the
    field placed under its table); a class that is no cavitation model names what it lacks."""
    with pytest.raises(InputError) as error:
        SolverOptions(cavitation="nope")  # type: ignore[arg-type]
    assert error.value.field == "cavitation" and error.value.value == "nope"
    assert all(name in str(error.value) for name in CAVITATION_MODELS)
    from shaftline.cases import parse_case

    case = {
        "bearing": {
            "length": "0.1 m",
            "diameter": "0.1 m",
            "radial_clearance": "0.1 mm",
            "operation": {"speed": "600 rpm", "load": "5 kN"},
            "lubricant": {"viscosity": "0.02 Pa*s"},
            "solver": {"cavitation": "nope"},
        }
    }
    with pytest.raises(InputError) as error:
        parse_case(case)
    assert error.value.field == "bearing.solver.cavitation"
    assert all(name in str(error.value) for name in CAVITATION_MODELS)
    with pytest.raises(InputError) as error:
        SolverOptions(cavitation=dict)  # type: ignore[arg-type]
    assert error.value.field == "cavitation" and "solve" in str(error.value)


@pytest.mark.parametrize("model", [ReynoldsCondition, HalfSommerfeld])
def test_a_cavitation_model_class_serves_as_its_name(model):
    """``SolverOptions(cavitation=...)`` takes a model class as well as a name: the class given
    is the one that solves, and the film solution and equilibrium are those of its name bit for
    bit (the same model, the same arithmetic)."""
    by_class = make_bearing(1.0, axial_nodes=21, circumferential_nodes=48, cavitation=model)
    by_name = make_bearing(1.0, axial_nodes=21, circumferential_nodes=48, cavitation=model.name)
    assert by_class.options.cavitation_model is model and by_class.options.cavitation is model
    assert type(by_class.solver.cavitation) is model and type(by_name.solver.cavitation) is model
    assert by_class.options.estimated_memory == by_name.options.estimated_memory
    position = JournalPosition.from_polar(0.6 * CLEARANCE, 2.5)
    one, other = by_class.solve_at(position), by_name.solve_at(position)
    assert one.cavitation == other.cavitation == model.name
    np.testing.assert_array_equal(one.pressure, other.pressure)
    np.testing.assert_array_equal(one.cavitated, other.cavitated)
    first, second = by_class.equilibrium(-2e3), by_name.equilibrium(-2e3)
    assert first.converged and second.converged
    assert (first.state.position.ey, first.state.position.ez) == (second.state.position.ey, second.state.position.ez)
    np.testing.assert_array_equal(first.state.pressure, second.state.pressure)


def test_defaults_are_read_from_the_dataclass():
    defaults = {item.name: item.default for item in fields(SolverOptions)}
    assert defaults["cavitation"] == "reynolds" and defaults["axial_nodes"] == 41
    assert SolverOptions() == SolverOptions(**defaults)


@pytest.mark.parametrize(
    "kwargs, field",
    [
        ({"axial_nodes": 4}, "axial_nodes"),
        ({"axial_nodes": 20.5}, "axial_nodes"),
        ({"circumferential_nodes": 12}, "circumferential_nodes"),
        ({"max_iterations": 0}, "max_iterations"),
        ({"min_film_floor": float("nan")}, "min_film_floor"),
    ],
)
def test_solver_options_check_the_grid_themselves(kwargs, field):
    """A SolverOptions is valid data once made, before any grid is built from it."""
    with pytest.raises(InputError) as error:
        SolverOptions(**kwargs)
    assert error.value.field == field


def test_results_holding_arrays_compare_by_identity(square_bearing):
    """== on a dataclass of arrays would raise ("truth value of an array is ambiguous")."""
    position = JournalPosition.from_polar(0.5 * CLEARANCE, 2.0)
    first, second = square_bearing.solve_at(position), square_bearing.solve_at(position)
    assert first == first and first != second
    assert len({first, second}) == 2
    linearisation = square_bearing.linearise(position)
    coefficients = dynamic_coefficients(square_bearing, first)
    assert linearisation == linearisation and coefficients == coefficients
    assert len({linearisation, coefficients}) == 2
    bent = BentJournal(z=[0.0, 0.1], dy=[0.0, 1e-6], dz=[0.0, 0.0])
    profile = FilmProfile(theta=[0.0, np.pi], z=[0.0], delta=[[0.0, 1e-6]])
    assert bent != BentJournal(z=[0.0, 0.1], dy=[0.0, 1e-6], dz=[0.0, 0.0])
    # a geometry compares its parts: equal when they are the same objects
    one = BearingGeometry(0.1, 0.1, 1e-4, bent_journal=bent, film_profile=profile)
    assert one == BearingGeometry(0.1, 0.1, 1e-4, bent_journal=bent, film_profile=profile)
    assert hash(one) == hash(BearingGeometry(0.1, 0.1, 1e-4, bent_journal=bent, film_profile=profile))


def test_linearisation_is_the_negated_dynamic_coefficients(square_bearing):
    """Signs: K = -dF/dq and C = -dF/dv; a journal moved further down meets a larger upward force."""
    position = JournalPosition.from_polar(0.5 * CLEARANCE, np.pi)
    linearisation = square_bearing.linearise(position)
    coefficients = dynamic_coefficients(square_bearing, square_bearing.solve_at(position))
    assert np.array_equal(coefficients.stiffness, -linearisation.offset_derivative)
    assert np.array_equal(coefficients.damping, -linearisation.velocity_derivative)
    assert linearisation.offset_derivative[0, 0] < 0 < linearisation.stiffness[0, 0]
    assert linearisation.velocity_derivative[0, 0] < 0 < linearisation.damping[0, 0]


def test_linearise_outside_the_clearance_is_bad_input(square_bearing):
    with pytest.raises(InputError) as error:
        square_bearing.linearise(JournalPosition(ey=-2 * CLEARANCE))
    assert error.value.field == "position"


def test_grid_follows_the_film_start(square_bearing):
    """Periodic film: one grid from theta = 0; max_film: the first node on the line of maximum film."""
    position = JournalPosition.from_polar(0.5 * CLEARANCE, 2.0)
    assert square_bearing.grid(position).theta_start == 0.0
    charted = make_bearing(1.0, axial_nodes=11, circumferential_nodes=36, film_start="max_film")
    grid = charted.grid(position)
    assert grid.theta_start == pytest.approx(2.0 + np.pi)
    film = charted.film(position)
    assert film.shape == grid.shape and np.argmax(film[5]) == 0
