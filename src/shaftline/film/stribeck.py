"""The Stribeck curve of a bearing: friction coefficient against speed, through boundary,
mixed and full-film lubrication, and the transition speed a stern-tube bearing maker quotes.

The speeds of a curve are solved in ascending order in contiguous chunks; within a chunk each
equilibrium starts from the previous speed's position and cavitated set (a warm start: the
position moves smoothly with the speed). The chunks depend on the speeds only, never on the
number of workers, and are spread over cores with :func:`shaftline.parallel.map` (one
mechanism with :func:`shaftline.film.sweep`), so the curve is the same on any backend. Unless
the caller names a backend, workers or a scheduler, a curve whose estimated work is small
(:func:`estimated_seconds` below :data:`POOL_MIN_SECONDS`) runs here, serially: a process pool's
start-up costs more than it saves on a few dozen speeds.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, Any

import numpy as np

from shaftline import export
from shaftline.errors import InputError
from shaftline.export import quantity
from shaftline.film.study import BearingCase

if TYPE_CHECKING:
    import pandas as pd
    from matplotlib.axes import Axes

__all__ = [
    "POOL_MIN_SECONDS",
    "TRANSITION_SHARE",
    "StribeckCurve",
    "estimated_seconds",
    "solved_transition",
    "stribeck_curve",
    "transition_speed",
]

#: Asperity load share below which the bearing counts as lifted off (issue 15: 1 %).
TRANSITION_SHARE = 0.01
#: Speeds solved one after the other, warm-started, by one worker.
CHUNK_SIZE = 10
#: Time of one equilibrium per grid node, s, on a rigid bore: 0.05-0.1 s on 41 x 120 and on
#: 100 x 60 (seed 001's rig and the NTUA bearing, rough, 4-5 Newton iterations warm-started;
#: 0.25-0.7 s where the film reaches the floor), on the shared 2-core machine of
#: docs/validation.md. The estimate of :func:`estimated_seconds`.
EQUILIBRIUM_SECONDS_PER_NODE = 2e-5
#: An elastic liner's coupled Newton multiplies an equilibrium's time by 3.5-12 (bench_mixed).
LINER_FACTOR = 5.0
#: The elastic-layer liner's GMRES costs 1.0-2.4 times the column model's equilibrium
#: (bench_liner_work.py, docs/validation.md "Elastic layer"): 2 on top of LINER_FACTOR.
LAYER_FACTOR = 2.0
#: A curve estimated below this many seconds serially runs serially by default: the pool's
#: start-up and the cold start of every chunk pay off only on longer curves. Measured on 30
#: speeds when this was set to 20 s (docs/validation.md): pool of 2 workers 7.1 s, serial 4.1 s
#: (seed 001's rig); 5.9 s against 2.8 s (NTUA, rough). Lowered to 10 s (2026-11-25): the pool
#: now starts in well under a second, and the lined rig (estimate 14.8 s) took 5.4 s serially
#: against 4.4 s on the pool through the CLI; the rigid rig (estimate 3 s) stays serial (1.6 s
#: against 1.2-1.9 s on a fresh pool).
POOL_MIN_SECONDS = 10.0


def _numbers(values: np.ndarray) -> list[float | None]:
    return [float(v) if math.isfinite(v) else None for v in values]


def _flags(values: np.ndarray) -> list[bool]:
    return [bool(v) for v in values]


def _rpm(speed: float) -> float:
    return float(speed * 30.0 / math.pi)


def _rpm_list(speeds: np.ndarray) -> list[float | None]:
    return _numbers(speeds * 30.0 / math.pi)


@dataclass(frozen=True, eq=False)
class StribeckCurve:
    """Equilibria of one bearing case over a range of speeds (the case's load and tilt).

    Attributes
    ----------
    speed : ndarray (n,)
        Shaft speeds, rad/s, ascending.
    friction_coefficient, asperity_load_share, min_film_thickness, min_film_ratio : ndarray (n,)
        Friction force over load (-), share of the load on the asperities (-), h_min (m) and
        h_min / sigma (-; inf for smooth surfaces).
    regime : tuple of str or None
        Lubrication regime at each speed (None for smooth surfaces).
    converged, contact : ndarray of bool (n,)
        Whether each equilibrium converged and whether it reached the film floor.
    transition_speed : float or None
        Speed above which the asperities carry less than :data:`TRANSITION_SHARE` of the load,
        rad/s (:func:`transition_speed` over the speeds that were solved: converged, or at the
        film floor, where the film does not carry the load, counted as a share of 1); None when
        no speed of the range crosses it.
    transition_uncertain : bool
        A speed that did not converge lies where the transition could be (between the last
        solved speed whose asperities carry the limit or more and the next solved speed): the
        transition speed then rests on speeds that are not solutions.
    max_reynolds_number : ndarray (n,) or None
        Largest local Reynolds number at each speed (with ``options.turbulence`` on or auto;
        None when off).
    turbulent : ndarray of bool (n,) or None
        Whether the turbulence coefficients applied at each speed (None when off).
    """

    speed: np.ndarray = quantity(
        "rpm", "speeds of the sweep (the base case's load and tilt)", key="speed_rpm", convert=_rpm_list
    )
    friction_coefficient: np.ndarray = quantity(
        "-", "friction force / load at each speed (the Stribeck curve)", convert=_numbers
    )
    asperity_load_share: np.ndarray = quantity(
        "-", "share of the load on the asperities at each speed", convert=_numbers
    )
    min_film_thickness: np.ndarray = quantity("m", "h_min at each speed", convert=_numbers)
    min_film_ratio: np.ndarray = quantity(
        "-", "h_min / sigma at each speed (null for smooth surfaces)", convert=_numbers
    )
    regime: tuple[str | None, ...] = quantity(
        "-",
        "boundary, mixed or full film at each speed (null when smooth, and at a speed that did not converge)",
        key="lubrication_regime",
        convert=list,
    )
    converged: np.ndarray = quantity("-", "equilibrium reached at each speed", convert=_flags)
    contact: np.ndarray = quantity("-", "load not carried within the clearance at each speed", convert=_flags)
    transition_speed: float | None = quantity(
        "rpm",
        "speed above which the asperities carry less than 1 % of the load, from the converged speeds and "
        "those in contact (share 1) (null: not crossed in the range)",
        key="transition_speed_rpm",
        convert=_rpm,
    )
    max_reynolds_number: np.ndarray | None = quantity(
        "-",
        "largest local Reynolds number at each speed (with [bearing.solver] turbulence on or auto only)",
        convert=_numbers,
        optional=True,
        default=None,
    )
    turbulent: np.ndarray | None = quantity(
        "-",
        "whether the turbulence coefficients applied at each speed (with turbulence on or auto only)",
        convert=_flags,
        optional=True,
        default=None,
    )
    transition_uncertain: bool = quantity(
        "-",
        "true where a speed that did not converge lies where the transition could be: the transition "
        "speed is then not a result (exit 3)",
        default=False,
    )

    def to_dict(self) -> dict[str, Any]:
        """The curve for results.json (speeds in rpm, non-finite values as null)."""
        return export.to_dict(self)

    def to_pandas(self) -> pd.DataFrame:
        """One row per speed (rpm, the index) with friction, asperity share, h_min (m), lambda, the
        regime and the flags (with the local Reynolds numbers where the turbulence model is on)."""
        import pandas as pd

        columns = {key: value for key, value in self.to_dict().items() if isinstance(value, list)}
        return pd.DataFrame(columns).set_index("speed_rpm")

    def plot(self, ax: Axes | tuple[Axes, ...] | None = None, name: str = "") -> Any:
        """The Stribeck figure (:func:`shaftline.film.figures.stribeck`: friction and h_min against
        speed with the regimes) into ``ax`` (a new figure without it); returns the axes."""
        from shaftline.film.figures import stribeck

        return stribeck(self, name, ax=ax)

    @property
    def stalled(self) -> np.ndarray:
        """Speeds whose equilibrium did not converge and did not reach the film floor: their
        points are not solutions."""
        return np.asarray(~self.converged.astype(bool) & ~self.contact.astype(bool))


def transition_speed(speed: np.ndarray, share: np.ndarray, limit: float = TRANSITION_SHARE) -> float | None:
    """The speed at which the asperity load share falls below ``limit`` for good, rad/s.

    Between the last speed at or above the limit and the next (below it) the share is taken
    linear in log(speed). None when the share is below the limit at the lowest speed or
    never falls below it.
    """
    above = np.flatnonzero(share >= limit)
    if above.size == 0 or above[-1] == share.size - 1:
        return None
    k = int(above[-1])
    s0, s1 = float(share[k]), float(share[k + 1])
    w = (s0 - limit) / (s0 - s1)
    return float(math.exp((1 - w) * math.log(speed[k]) + w * math.log(speed[k + 1])))


def solved_transition(
    speed: np.ndarray,
    share: np.ndarray,
    converged: np.ndarray,
    contact: np.ndarray,
    limit: float = TRANSITION_SHARE,
) -> tuple[float | None, bool]:
    """:func:`transition_speed` over the solved speeds (converged, or at the film floor, where
    the film does not carry the load: counted as a share of 1), and whether a speed that did not
    converge lies where the transition could be (between the last solved speed at or above
    the limit and the next solved speed, or below the first solved speed if none is above).
    """
    solved = converged | contact
    effective = np.where(contact, 1.0, share)
    above = solved & (effective >= limit)
    last_above = float(speed[above].max()) if above.any() else -math.inf
    after = solved & (speed > last_above)
    first_below = float(speed[after].min()) if after.any() else math.inf
    stalled = ~solved & (speed > last_above) & (speed < first_below)
    if solved.sum() < 2:
        return None, bool((~solved).any())
    return transition_speed(speed[solved], effective[solved], limit), bool(stalled.any())


def estimated_seconds(case: BearingCase, speeds: int) -> float:
    """Rough serial time of a curve of ``speeds`` speeds of ``case``, s: the grid's nodes times
    :data:`EQUILIBRIUM_SECONDS_PER_NODE` per speed (times :data:`LINER_FACTOR` with a liner, and
    :data:`LAYER_FACTOR` more for the layer model)."""
    nodes = case.options.axial_nodes * case.options.circumferential_nodes
    liner = case.geometry.liner
    factor = 1.0 if liner is None else LINER_FACTOR * (LAYER_FACTOR if liner.model == "layer" else 1.0)
    return speeds * nodes * EQUILIBRIUM_SECONDS_PER_NODE * factor


def _solve_chunk(case: BearingCase, speeds: Sequence[float]) -> list[tuple[float, ...]]:
    """Equilibria at ``speeds`` (ascending), each warm-started from the previous one."""
    from shaftline.film.bearing import JournalBearing

    out: list[tuple[float, ...]] = []
    previous = None
    for speed in speeds:
        operating = replace(case.operating, speed=float(speed))
        bearing = JournalBearing(case.geometry, operating, case.options)
        equilibrium = bearing.equilibrium(
            case.load_y,
            case.load_z,
            tilt_y=case.tilt_y,
            tilt_z=case.tilt_z,
            initial=None if previous is None else previous.position,
            initial_cavitated=None if previous is None else previous.cavitated,
            initial_deformation=None if previous is None or previous.liner is None else previous.liner.deformation,
        )
        if previous is not None and not (equilibrium.converged and not equilibrium.contact):
            # A warm start from a neighbour in boundary lubrication (its film below the mean plane)
            # can keep the journal there when this speed's film is thicker, or stall: the cold start
            # then (docs/theory.md Sect. 17, "Boundary lubrication"), kept if it converges.
            cold = bearing.equilibrium(case.load_y, case.load_z, tilt_y=case.tilt_y, tilt_z=case.tilt_z)
            if cold.converged and not cold.contact:
                equilibrium = cold
        state = equilibrium.state
        if equilibrium.converged and not equilibrium.contact:
            previous = state
        turbulence = state.turbulence
        out.append(
            (
                state.friction_coefficient,
                state.asperity_load_share,
                state.min_film_thickness,
                state.min_film_ratio,
                float(equilibrium.converged),
                float(equilibrium.contact),
                0.0 if turbulence is None else turbulence.max_reynolds_number,
                float(turbulence is not None and turbulence.turbulent),
            )
        )
    return out


def stribeck_curve(
    case: BearingCase,
    speeds: Sequence[float],
    *,
    backend: str | None = None,
    workers: int | None = None,
    scheduler: str | None = None,
    progress: Callable[[int, int], None] | None = None,
    chunk_size: int = CHUNK_SIZE,
) -> StribeckCurve:
    """Friction coefficient, asperity share and h_min of ``case`` at each of ``speeds`` (rad/s),
    in warm-started chunks of ``chunk_size`` speeds over :func:`shaftline.parallel.map`
    (``backend``, ``workers``, ``scheduler`` as there; ``progress(done, total)`` per chunk).
    With none of the three given, a curve of :func:`estimated_seconds` below
    :data:`POOL_MIN_SECONDS` runs serially (the same curve, bit for bit: the chunks do not
    depend on the backend).

    Raises
    ------
    InputError
        ``"speeds"`` for fewer than two speeds or a speed that is not finite and positive.
    """
    from shaftline import parallel
    from shaftline.film.roughness import lubrication_regime

    values = np.sort(np.asarray(speeds, dtype=float))
    if values.size < 2 or not np.all(np.isfinite(values)) or values[0] <= 0.0:
        raise InputError("speeds", list(map(float, values)), "rad/s", "two or more finite speeds > 0")
    chunks = [values[k : k + chunk_size] for k in range(0, values.size, chunk_size)]
    if backend is None and workers is None and scheduler is None:
        if estimated_seconds(case, values.size) < POOL_MIN_SECONDS:
            backend = "serial"
    solved = parallel.map(
        functools.partial(_solve_chunk, case),
        chunks,
        backend=backend,
        workers=workers,
        scheduler=scheduler,
        progress=progress,
        work_here=True,
    )
    rows = np.array([row for chunk in solved for row in chunk])
    share = rows[:, 1]
    ratio = rows[:, 3]
    converged, contact = rows[:, 4].astype(bool), rows[:, 5].astype(bool)
    rough = case.geometry.surface is not None
    transition, uncertain = solved_transition(values, share, converged, contact) if rough else (None, False)
    return StribeckCurve(
        speed=values,
        friction_coefficient=rows[:, 0],
        asperity_load_share=share,
        min_film_thickness=rows[:, 2],
        min_film_ratio=ratio,
        # no regime for a speed that is not a solution
        regime=tuple(
            lubrication_regime(float(v)) if rough and (c or t) else None
            for v, c, t in zip(ratio, converged, contact, strict=True)
        ),
        converged=converged,
        contact=contact,
        transition_speed=transition,
        max_reynolds_number=rows[:, 6] if case.options.turbulence != "off" else None,
        turbulent=rows[:, 7].astype(bool) if case.options.turbulence != "off" else None,
        transition_uncertain=uncertain,
    )
