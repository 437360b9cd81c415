"""A gear scuffing study: a pair at torque steps x pinion speeds, rated by seed 002's scuffing
parameter and by ISO/TS 6336-20's flash temperature (what ``[gears]`` becomes; notebooks can
build one directly)."""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from shaftline.contact.rheology import ExtrapolationWarning
from shaftline.csvio import read_columns
from shaftline.errors import InputError
from shaftline.gears.flash import IsoScuffing, IsoScuffingData, iso_scuffing
from shaftline.gears.integral import IntegralRating, integral_temperature
from shaftline.gears.scuffing import GearMesh, MeshState, calibrate, evaluate_mesh, scuffing_parameter

#: Columns of a torque-step test record.
TEST_COLUMNS = ["torque_Nm", "speed_rpm", "oil_temperature_degC", "scuffed"]


@dataclass(frozen=True, eq=False)
class TorqueStepRecord:
    """A torque-step scuffing test: one row per step, in the order run (SI, degC).

    Attributes
    ----------
    source : str
    torque, speed, oil_temperature : ndarray
        N m, rad/s, degC.
    failure : int
        Index of the first step that scuffed.
    """

    source: str
    torque: np.ndarray
    speed: np.ndarray
    oil_temperature: np.ndarray
    failure: int


def read_test_record(path: str | Path, field: str = "calibrate") -> TorqueStepRecord:
    """A test record CSV (columns :data:`TEST_COLUMNS`; scuffed 0 or 1); the first scuffed row
    is the failure step."""
    columns = read_columns(path, TEST_COLUMNS, field)
    scuffed = columns["scuffed"]
    name = Path(path).name
    for column in ("torque_Nm", "speed_rpm"):
        bad = np.flatnonzero(~(columns[column] > 0))
        if bad.size:
            raise InputError(f"{name}: row {bad[0] + 2}, {column}", float(columns[column][bad[0]]), "", "> 0", True)
    bad = np.flatnonzero((scuffed != 0) & (scuffed != 1))
    if bad.size:
        raise InputError(f"{name}: row {bad[0] + 2}, scuffed", float(scuffed[bad[0]]), "", "0 or 1", True)
    if not np.any(scuffed == 1):
        raise InputError(field, str(path), "", "a test record with a scuffed step (scuffed = 1) to calibrate on")
    return TorqueStepRecord(
        str(path),
        columns["torque_Nm"],
        columns["speed_rpm"] * math.pi / 30.0,
        columns["oil_temperature_degC"],
        int(np.flatnonzero(scuffed == 1)[0]),
    )


@dataclass(frozen=True, eq=False)
class GearStudy:
    """A gear pair rated for scuffing (SI; temperatures degC).

    Attributes
    ----------
    mesh : GearMesh
    oil_temperature, critical_temperature : float
        T_0 and T_cr.
    thermal_coefficient : float or None
        C of Eq. 7, W/(m K) (None: from ``calibration``).
    calibration : TorqueStepRecord or None
        A test to calibrate C on (replaces ``thermal_coefficient``).
    torques : ndarray
        Pinion torque steps, N m.
    speeds : ndarray
        Pinion speeds, rad/s (the first is the test speed).
    fzg_load_stages : tuple of int or None
        The FZG stages the torques stand for.
    iso : IsoScuffingData or None
        ISO's flash-temperature method beside SP.
    """

    mesh: GearMesh
    oil_temperature: float
    critical_temperature: float
    thermal_coefficient: float | None
    torques: np.ndarray
    speeds: np.ndarray
    calibration: TorqueStepRecord | None = None
    fzg_load_stages: tuple[int, ...] | None = None
    iso: IsoScuffingData | None = None


@dataclass(frozen=True, eq=False)
class GearResult:
    """SP and ISO's rating at every torque step x speed, and the mesh along the path.

    Attributes
    ----------
    study : GearStudy
    state : MeshState
        Arrays of shape (torques, speeds, points).
    coefficient : float
        C used, W/(m K).
    calibrated_at : tuple or None
        (torque N m, speed rad/s, oil temperature degC, max integral W/m) of the failure step.
    sp : ndarray
        (torques, speeds).
    iso : IsoScuffing or None
    integral : IntegralRating or None
        ISO/TS 6336-21 (with ``iso``).
    warnings : tuple of str
    """

    study: GearStudy
    state: MeshState
    coefficient: float
    calibrated_at: tuple[float, float, float, float] | None
    sp: np.ndarray
    iso: IsoScuffing | None
    integral: IntegralRating | None = None
    warnings: tuple[str, ...] = ()


def solve_gears(study: GearStudy, progress: Callable[[str], None] = lambda _: None) -> GearResult:
    """Evaluate the mesh on the torque x speed x path map (one vectorised call), calibrate C
    when a test record is given, and rate by SP and ISO."""
    mesh = study.mesh
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", ExtrapolationWarning)
        calibrated_at = None
        coefficient = study.thermal_coefficient
        record = study.calibration
        if record is not None:
            progress("calibrating C on the test record")
            k = record.failure
            t0 = float(record.oil_temperature[k])
            at = evaluate_mesh(mesh, float(record.torque[k]), float(record.speed[k]), t0)
            power = float(at.power_integral)
            coefficient = calibrate(power, study.critical_temperature, t0)
            calibrated_at = (float(record.torque[k]), float(record.speed[k]), t0, power)
        assert coefficient is not None  # the case requires one or the other
        progress("the mesh along the path: torque steps x speeds")
        state = evaluate_mesh(mesh, study.torques[:, None, None], study.speeds[None, :, None], study.oil_temperature)
        sp = scuffing_parameter(state.power_integral, coefficient, study.critical_temperature, study.oil_temperature)
        iso: IsoScuffing | None = None
        integral: IntegralRating | None = None
        if study.iso is not None:
            progress("ISO flash temperature")
            rho = mesh.positions()
            viscosity = float(mesh.model.lubricant.dynamic_viscosity(study.oil_temperature, mesh.model.extrapolate))
            iso = iso_scuffing(
                mesh.pair,
                study.iso,
                study.torques[:, None, None],
                study.speeds[None, :, None],
                study.oil_temperature,
                viscosity,
                state.share,
                rho,
            )
            lubricant = mesh.model.lubricant.viscosity
            integral = integral_temperature(
                mesh.pair,
                study.iso,
                study.torques[:, None],
                study.speeds[None, :],
                study.oil_temperature,
                viscosity,
                float(lubricant.kinematic_viscosity(40.0)),
            )
    notes = tuple(dict.fromkeys(str(w.message) for w in caught if issubclass(w.category, ExtrapolationWarning)))
    return GearResult(study, state, float(coefficient), calibrated_at, sp, iso, integral, notes)
