"""film.sweep: many cases grouped by problem, warm-started, spread over processes.

Two claims are tested. (1) The answer does not depend on where the sweep runs: serial, a
process pool of two and a real Dask LocalCluster give the same numbers (to 1e-12; they are
the same operations in the same order on a fresh bearing per chunk). (2) The answer is the
one each case gets alone (cold start, new bearing) within the solver's tolerance: both
positions leave a force residual below ``tolerance * |load|``, so they differ by at most
``2 * tolerance * |load| * ||K^-1||`` with K the film stiffness there.
"""

from __future__ import annotations

import json
import random
from dataclasses import replace

import numpy as np
import pytest

from shaftline import parallel
from shaftline.errors import InputError
from shaftline.film import BearingGeometry, OperatingPoint, SolverOptions, sweep
from shaftline.film.solve import solve_case
from shaftline.film.study import BearingCase
from tests.conftest import MINIMAL_CASE, invoke

GEOMETRY = BearingGeometry(length=0.1, diameter=0.1, radial_clearance=1e-4)
OPTIONS = SolverOptions(axial_nodes=21, circumferential_nodes=72)


def cases() -> list[BearingCase]:
    """2 speeds x 2 tilts x 5 loads, listed in a shuffled order (fixed seed)."""
    out = [
        BearingCase(
            f"{speed:g} rad/s, tilt {tilt:g}, {load:g} N",
            GEOMETRY,
            OperatingPoint(speed=speed, viscosity=0.02),
            OPTIONS,
            load_y=-load,
            load_z=0.1 * load,
            tilt_y=tilt,
        )
        for speed in (60.0, 100.0)
        for tilt in (0.0, 5e-4)
        for load in np.linspace(2e3, 8e3, 5)
    ]
    random.Random(4).shuffle(out)
    return out


@pytest.fixture(scope="module")
def scheduler():
    from dask.distributed import LocalCluster

    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0") as cluster:
        yield cluster.scheduler_address


@pytest.fixture(scope="module")
def alone() -> list:
    return [solve_case(case) for case in cases()]


class _Recorded(Exception):
    """Raised by the recording ``parallel.map`` of :func:`_chunk_count`, so nothing is solved."""


def _chunk_count(monkeypatch: pytest.MonkeyPatch, given: list[BearingCase], chunk_size: int) -> int:
    """How many chunks ``sweep(given, chunk_size=chunk_size)`` hands to ``shaftline.parallel.map``
    (the work items its workers receive), recorded there without solving them."""
    counted: list[int] = []

    def record(function: object, items: list, **options: object) -> object:
        counted.append(len(items))
        raise _Recorded

    with monkeypatch.context() as patch:
        patch.setattr(parallel, "map", record)
        with pytest.raises(_Recorded):
            sweep(given, chunk_size=chunk_size, coefficients=True)
    return counted[0]


def _numbers(result) -> np.ndarray:
    state = result.equilibrium.state
    return np.concatenate(
        [
            [state.position.ey, state.position.ez, state.max_pressure, state.power_loss, state.side_leakage],
            result.coefficients.stiffness.ravel(),
            result.coefficients.damping.ravel(),
        ]
    )


def test_serial_process_pool_and_dask_give_the_same_numbers(scheduler, monkeypatch):
    given = cases()
    serial = sweep(given, backend="serial", chunk_size=4)
    pooled = sweep(given, workers=2, chunk_size=4)
    on_dask = sweep(given, scheduler=scheduler, chunk_size=4)
    assert _chunk_count(monkeypatch, given, 4) == 6  # two problems (speeds) of ten cases: three chunks each
    for a, b, c, case in zip(serial, pooled, on_dask, given, strict=True):
        assert a.case is case and b.case is case and c.case is case  # input order, the caller's objects
        np.testing.assert_allclose(_numbers(b), _numbers(a), rtol=1e-12, atol=0)
        np.testing.assert_allclose(_numbers(c), _numbers(a), rtol=1e-12, atol=0)


def test_a_sweep_agrees_with_each_case_alone_within_the_tolerance(alone):
    swept = sweep(cases(), workers=2)
    for one, many in zip(alone, swept, strict=True):
        assert one.case.name == many.case.name
        a, b = one.equilibrium, many.equilibrium
        assert a.converged and b.converged and not (a.contact or b.contact)
        load = np.hypot(a.load_y, a.load_z)
        assert b.residual <= OPTIONS.tolerance * load
        bound = 2 * OPTIONS.tolerance * load * np.linalg.norm(np.linalg.inv(one.coefficients.stiffness), 2)
        shift = np.hypot(a.state.position.ey - b.state.position.ey, a.state.position.ez - b.state.position.ez)
        assert shift <= bound
        np.testing.assert_allclose(many.coefficients.stiffness, one.coefficients.stiffness, rtol=1e-6)


def test_warm_starts_save_newton_iterations():
    """Along a load line (ten loads 4-6 kN, one problem) each case starts from its solved
    neighbours: 19 Newton iterations in all against 30 from ten cold starts (measured); the
    first case starts cold, so it takes what it takes alone."""
    operating = OperatingPoint(speed=100.0, viscosity=0.02)
    line = [
        BearingCase(f"{w:g}", GEOMETRY, operating, OPTIONS, load_y=-w, tilt_y=3e-4) for w in np.linspace(4e3, 6e3, 10)
    ]
    swept = [r.equilibrium.iterations for r in sweep(line, backend="serial", coefficients=False)]
    cold = [solve_case(case, coefficients=False).equilibrium.iterations for case in line]
    assert swept[0] == cold[0]
    assert sum(swept) <= 0.7 * sum(cold), (swept, cold)


def test_equal_problems_built_apart_share_a_bearing(monkeypatch):
    """Cases compare by the value of their problem, not by the identity of its objects."""
    given = [
        BearingCase(
            str(k), replace(GEOMETRY), OperatingPoint(speed=100.0, viscosity=0.02), replace(OPTIONS), load_y=-1e3 * k
        )
        for k in range(1, 4)
    ]
    assert _chunk_count(monkeypatch, given, 32) == 1
    assert _chunk_count(monkeypatch, given, 2) == 2
    other = replace(given[0], operating=OperatingPoint(speed=101.0, viscosity=0.02))
    assert _chunk_count(monkeypatch, [*given, other], 32) == 2


def test_a_case_at_the_film_floor_gets_its_answer_alone():
    """A load the film cannot carry, between loads it can: contact, as when solved alone."""
    base = OperatingPoint(speed=100.0, viscosity=0.02)
    given = [BearingCase(str(w), GEOMETRY, base, OPTIONS, load_y=-w) for w in (4e3, 5e3, 5e7, 6e3)]
    swept = sweep(given, backend="serial")
    heavy = solve_case(given[2])
    assert heavy.equilibrium.contact and swept[2].equilibrium.contact
    assert swept[2].equilibrium.state.position == heavy.equilibrium.state.position
    assert all(r.equilibrium.converged for k, r in enumerate(swept) if k != 2)


def test_an_input_error_in_a_worker_names_the_case_file_field():
    """A tilt that does not fit in the clearance is found while solving, in a worker."""
    good = BearingCase("good", GEOMETRY, OperatingPoint(speed=100.0, viscosity=0.02), OPTIONS, load_y=-4e3)
    bad = replace(
        good,
        name="bad",
        geometry=replace(GEOMETRY, diameter=0.11),
        tilt_y=0.01,
        error_fields={"tilt_y": "variants[0].tilt_vertical"},
    )
    with pytest.raises(InputError, match=r"^variants\[0\]\.tilt_vertical = 0\.01 rad"):
        sweep([good, bad], workers=2)
    with pytest.raises(InputError, match="chunk_size = 0"):
        sweep([good], chunk_size=0)


def test_progress_names_cases_here_and_counts_them_from_a_pool():
    given = cases()[:4]
    told: list[str] = []
    sweep(given, backend="serial", progress=told.append)
    names = [t for t in told if ":" not in t]
    assert sorted(names) == sorted(c.name for c in given)
    assert any("Newton iteration 1, force residual" in t for t in told)
    counted: list[str] = []
    sweep(given, workers=2, chunk_size=1, progress=counted.append)
    assert counted[-1] == "bearing cases, 4 of 4 done" and len(counted) == 4


def test_the_command_line_runs_variants_on_a_pool_a_cluster_or_here(tmp_path, scheduler):
    """--workers and --scheduler choose where; the JSON is the same."""
    case = tmp_path / "case.toml"
    variants = "".join(
        f'\n[[bearing.variants]]\nname = "v{k}"\n[[bearing.variants.bore]]\nlength_fraction = 1.0\nslope = {k}e-4\n'
        for k in range(1, 4)
    )
    case.write_text(MINIMAL_CASE + variants)
    runs = [
        invoke("bearing", "solve", str(case), "--json", "-", *where)
        for where in ((), ("--workers", "1"), ("--scheduler", scheduler))
    ]
    assert all(r.exit_code == 0 for r in runs), [r.output for r in runs]
    documents = [json.loads(r.stdout) for r in runs]
    assert len(documents[0]["bearing"]["cases"]) == 4
    assert documents[1] == documents[0] and documents[2] == documents[0]
    bad = invoke("run", str(case), "--workers", "0")
    assert bad.exit_code == 2 and bad.stderr.strip() == "error: --workers = 0: allowed an integer >= 1"
    both = invoke("run", str(case), "--workers", "2", "--scheduler", scheduler)
    assert both.exit_code == 2 and "no --workers with --scheduler" in both.stderr
