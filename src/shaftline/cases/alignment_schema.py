"""Case-file sections of a shaft alignment and their conversion to SI domain objects."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from shaftline.cases._base import Quantity, Strict
from shaftline.csvio import read_columns
from shaftline.errors import InputError
from shaftline.shaft.model import (
    Bearing,
    Condition,
    DistributedLoad,
    PointLoad,
    PointMass,
    Propeller,
    ShaftLine,
    ShaftSegment,
)
from shaftline.shaft.rules import Rule, load_rules, rule_from_dict
from shaftline.units import to_si


class SegmentIn(Strict):
    length: Quantity
    outer_diameter: Quantity
    inner_diameter: Quantity = 0.0
    outer_diameter_end: Quantity | None = None
    inner_diameter_end: Quantity | None = None
    youngs_modulus: Quantity | None = None
    shear_modulus: Quantity | None = None
    poisson_ratio: float | None = None
    density: Quantity | None = None
    shear_area_factor: float | None = None
    name: str = ""


class ShaftIn(Strict):
    segments: list[SegmentIn]
    beam_theory: str = "timoshenko"
    element_length: Quantity = 0.25
    self_weight: bool = True
    gravity: Quantity = 9.80665
    youngs_modulus: Quantity = 206e9
    poisson_ratio: float = 0.3
    density: Quantity = 7850.0


class PropellerIn(Strict):
    x: Quantity
    mass: Quantity
    material_density: Quantity = 7600.0
    water_density: Quantity = 1025.0
    immersed_fraction: float = 1.0


class AlignmentBearingIn(Strict):
    name: str
    x: Quantity
    length: Quantity
    offset_y: Quantity = 0.0
    offset_z: Quantity = 0.0
    vertical_clearance: Quantity | None = None
    material: str = "white_metal"
    support: str = "point"
    stiffness: Quantity | None = None
    points: int = 1
    position: str = "centre"
    one_sided: bool = True
    slope: Quantity = 0.0


class PointLoadIn(Strict):
    x: Quantity
    force_y: Quantity = 0.0
    force_z: Quantity = 0.0
    moment_vertical: Quantity = 0.0
    moment_horizontal: Quantity = 0.0
    name: str = ""


class MassIn(Strict):
    x: Quantity
    mass: Quantity
    name: str = ""


class DistributedLoadIn(Strict):
    x_start: Quantity
    x_end: Quantity
    load_y: Quantity = 0.0
    load_z: Quantity = 0.0
    name: str = ""


class ConditionIn(Strict):
    name: str
    offsets_y: dict[str, Quantity] = {}
    offsets_z: dict[str, Quantity] = {}
    propeller_immersion: float | None = None
    loads: list[PointLoadIn] = []


class OptimiseIn(Strict):
    objective: str = "aft_slope"
    adjustable: list[str] | None = None
    bound: Quantity = 5e-3


class TemporarySupportIn(Strict):
    name: str
    x: Quantity
    offset_y: Quantity = 0.0


class SagGapIn(Strict):
    flange_x: Quantity
    flange_diameter: Quantity | None = None
    condition: str | None = None
    temporary_supports: list[TemporarySupportIn] = []


class JackUpIn(Strict):
    bearing: str
    jack_x: Quantity
    condition: str | None = None
    measured_curve: str | None = None


class MeasuredReactionsIn(Strict):
    condition: str | None = None
    values: dict[str, Quantity]
    reference: list[str] | None = None


class AlignmentIn(Strict):
    rules_file: str | None = None
    rules: list[dict] = []
    optimise: OptimiseIn | None = None
    sag_gap: SagGapIn | None = None
    jack_up: JackUpIn | None = None
    measured_reactions: MeasuredReactionsIn | None = None


@dataclass(frozen=True)
class AlignmentCase:
    """An alignment problem in SI units and the procedures asked for.

    Attributes
    ----------
    line : ShaftLine
    rules : list of Rule
    optimise : dict or None
        ``objective``, ``adjustable``, ``bound`` (m).
    sag_gap : dict or None
        ``flange_x`` (m), ``flange_diameter`` (m or None), ``condition``, ``temporary_supports``.
    jack_up : dict or None
        ``bearing``, ``jack_x`` (m), ``condition``, ``measured`` ((loads N, lifts m) or None).
    measured_reactions : dict or None
        ``condition``, ``values`` (N per bearing), ``reference``.
    """

    line: ShaftLine
    rules: list[Rule]
    optimise: dict | None = None
    sag_gap: dict | None = None
    jack_up: dict | None = None
    measured_reactions: dict | None = field(default=None)


def _q(value: Quantity | None, kind: str, where: str) -> float | None:
    return None if value is None else to_si(value, kind, where)


def _point_load(data: PointLoadIn, where: str) -> PointLoad:
    return PointLoad(
        x=to_si(data.x, "length", f"{where}.x"),
        force_y=to_si(data.force_y, "force", f"{where}.force_y"),
        force_z=to_si(data.force_z, "force", f"{where}.force_z"),
        moment_vertical=to_si(data.moment_vertical, "moment", f"{where}.moment_vertical"),
        moment_horizontal=to_si(data.moment_horizontal, "moment", f"{where}.moment_horizontal"),
        name=data.name,
    )


def _condition_name(name: str | None, line: ShaftLine, where: str) -> Condition:
    conditions = line.all_conditions()
    if name is None:
        return conditions[0]
    for condition in conditions:
        if condition.name == name:
            return condition
    raise InputError(where, name, "", "the name of a condition: " + ", ".join(c.name for c in conditions))


def read_jack_curve(path: Path) -> tuple[np.ndarray, np.ndarray]:
    """A measured jack-up curve from CSV: columns ``load`` (N) and ``lift`` (m)."""
    table = read_columns(path, ["load", "lift"], "alignment.jack_up.measured_curve")
    return table["load"], table["lift"]


def build_alignment(
    shaft: ShaftIn,
    bearings: list[AlignmentBearingIn],
    loads: list[PointLoadIn],
    masses: list[MassIn],
    distributed: list[DistributedLoadIn],
    propeller: PropellerIn | None,
    conditions: list[ConditionIn],
    alignment: AlignmentIn | None,
    base_dir: Path | None,
) -> AlignmentCase:
    """Convert the alignment sections of a case file into SI domain objects."""
    defaults = {
        "youngs_modulus": to_si(shaft.youngs_modulus, "pressure", "shaft.youngs_modulus"),
        "density": to_si(shaft.density, "density", "shaft.density"),
    }
    segments = []
    for k, s in enumerate(shaft.segments):
        where = f"shaft.segments[{k}]"
        segments.append(
            ShaftSegment(
                length=to_si(s.length, "length", f"{where}.length"),
                outer_diameter=to_si(s.outer_diameter, "length", f"{where}.outer_diameter"),
                inner_diameter=to_si(s.inner_diameter, "length", f"{where}.inner_diameter"),
                outer_diameter_end=_q(s.outer_diameter_end, "length", f"{where}.outer_diameter_end"),
                inner_diameter_end=_q(s.inner_diameter_end, "length", f"{where}.inner_diameter_end"),
                youngs_modulus=_q(s.youngs_modulus, "pressure", f"{where}.youngs_modulus")
                or defaults["youngs_modulus"],
                shear_modulus=_q(s.shear_modulus, "pressure", f"{where}.shear_modulus"),
                poisson_ratio=shaft.poisson_ratio if s.poisson_ratio is None else s.poisson_ratio,
                density=_q(s.density, "density", f"{where}.density") or defaults["density"],
                shear_area_factor=s.shear_area_factor,
                name=s.name,
            )
        )
    bearing_objects = []
    for k, b in enumerate(bearings):
        where = f"bearings[{k}]"
        stiffness = _q(b.stiffness, "stiffness", f"{where}.stiffness")
        bearing_objects.append(
            Bearing(
                name=b.name,
                x=to_si(b.x, "length", f"{where}.x"),
                length=to_si(b.length, "length", f"{where}.length"),
                offset_y=to_si(b.offset_y, "length", f"{where}.offset_y"),
                offset_z=to_si(b.offset_z, "length", f"{where}.offset_z"),
                vertical_clearance=_q(b.vertical_clearance, "length", f"{where}.vertical_clearance") or math.inf,
                material=b.material,
                support=b.support,
                stiffness=math.inf if stiffness is None else stiffness,
                points=b.points,
                position=b.position,
                one_sided=b.one_sided,
                slope=to_si(b.slope, "angle", f"{where}.slope"),
            )
        )
    condition_objects = tuple(
        Condition(
            name=c.name,
            offsets_y={n: to_si(v, "length", f"conditions[{k}].offsets_y.{n}") for n, v in c.offsets_y.items()},
            offsets_z={n: to_si(v, "length", f"conditions[{k}].offsets_z.{n}") for n, v in c.offsets_z.items()},
            propeller_immersion=c.propeller_immersion,
            loads=tuple(_point_load(p, f"conditions[{k}].loads[{j}]") for j, p in enumerate(c.loads)),
        )
        for k, c in enumerate(conditions)
    )
    names = [c.name for c in condition_objects]
    if len(set(names)) != len(names):
        raise InputError("conditions.name", names, "", "names used once each")
    propeller_object = None
    if propeller is not None:
        propeller_object = Propeller(
            x=to_si(propeller.x, "length", "propeller.x"),
            mass=to_si(propeller.mass, "mass", "propeller.mass"),
            material_density=to_si(propeller.material_density, "density", "propeller.material_density"),
            water_density=to_si(propeller.water_density, "density", "propeller.water_density"),
            immersed_fraction=propeller.immersed_fraction,
        )
    line = ShaftLine(
        segments=tuple(segments),
        bearings=tuple(bearing_objects),
        point_loads=tuple(_point_load(p, f"loads[{k}]") for k, p in enumerate(loads)),
        masses=tuple(
            PointMass(to_si(m.x, "length", f"masses[{k}].x"), to_si(m.mass, "mass", f"masses[{k}].mass"), m.name)
            for k, m in enumerate(masses)
        ),
        distributed_loads=tuple(
            DistributedLoad(
                to_si(d.x_start, "length", f"distributed_loads[{k}].x_start"),
                to_si(d.x_end, "length", f"distributed_loads[{k}].x_end"),
                to_si(d.load_y, "force_per_length", f"distributed_loads[{k}].load_y"),
                to_si(d.load_z, "force_per_length", f"distributed_loads[{k}].load_z"),
                d.name,
            )
            for k, d in enumerate(distributed)
        ),
        propeller=propeller_object,
        conditions=condition_objects,
        self_weight=shaft.self_weight,
        gravity=to_si(shaft.gravity, "acceleration", "shaft.gravity"),
        element_length=to_si(shaft.element_length, "length", "shaft.element_length"),
        beam_theory=shaft.beam_theory,
    )
    alignment = alignment or AlignmentIn()
    base = base_dir or Path.cwd()
    if alignment.rules_file is not None:
        rules_path = Path(alignment.rules_file)
        rules = load_rules(rules_path if rules_path.is_absolute() else base / rules_path)
    else:
        rules = load_rules()
    rules += [rule_from_dict(entry, f"alignment.rules[{k}]") for k, entry in enumerate(alignment.rules)]
    bearing_names = [b.name for b in bearing_objects]
    optimise = None
    if alignment.optimise is not None:
        optimise = {
            "objective": alignment.optimise.objective,
            "adjustable": alignment.optimise.adjustable,
            "bound": to_si(alignment.optimise.bound, "length", "alignment.optimise.bound"),
        }
    sag_gap = None
    if alignment.sag_gap is not None:
        sg = alignment.sag_gap
        sag_gap = {
            "flange_x": to_si(sg.flange_x, "length", "alignment.sag_gap.flange_x"),
            "flange_diameter": _q(sg.flange_diameter, "length", "alignment.sag_gap.flange_diameter"),
            "condition": _condition_name(sg.condition, line, "alignment.sag_gap.condition"),
            "temporary_supports": tuple(
                Bearing(
                    name=t.name,
                    x=to_si(t.x, "length", f"alignment.sag_gap.temporary_supports[{k}].x"),
                    length=1e-3,
                    offset_y=to_si(t.offset_y, "length", f"alignment.sag_gap.temporary_supports[{k}].offset_y"),
                )
                for k, t in enumerate(sg.temporary_supports)
            ),
        }
    jack = None
    if alignment.jack_up is not None:
        ju = alignment.jack_up
        if ju.bearing not in bearing_names:
            raise InputError("alignment.jack_up.bearing", ju.bearing, "", "bearing names: " + ", ".join(bearing_names))
        measured = None
        if ju.measured_curve is not None:
            path = Path(ju.measured_curve)
            measured = read_jack_curve(path if path.is_absolute() else base / path)
        jack = {
            "bearing": ju.bearing,
            "jack_x": to_si(ju.jack_x, "length", "alignment.jack_up.jack_x"),
            "condition": _condition_name(ju.condition, line, "alignment.jack_up.condition"),
            "measured": measured,
        }
    reverse = None
    if alignment.measured_reactions is not None:
        mr = alignment.measured_reactions
        for name in mr.values:
            if name not in bearing_names:
                raise InputError("alignment.measured_reactions.values", name, "", "bearing names")
        reverse = {
            "condition": _condition_name(mr.condition, line, "alignment.measured_reactions.condition"),
            "values": {n: to_si(v, "force", f"alignment.measured_reactions.values.{n}") for n, v in mr.values.items()},
            "reference": tuple(mr.reference) if mr.reference else None,
        }
    return AlignmentCase(
        line=line, rules=rules, optimise=optimise, sag_gap=sag_gap, jack_up=jack, measured_reactions=reverse
    )
