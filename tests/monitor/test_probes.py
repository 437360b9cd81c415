"""Probe layout checks and calibration (issue 13: bad input gives one-line errors)."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

from shaftline.errors import InputError
from shaftline.monitor.probes import Probe, ProbeLayout, Section, seed001_layout, within_range


def _one_line(error: pytest.ExceptionInfo[InputError]) -> str:
    message = str(error.value)
    assert "\n" not in message
    return message


def test_seed_layout_is_accepted_and_ordered():
    layout = seed001_layout()
    assert layout.positions.tolist() == [0.292, 0.4295, 0.856]
    assert layout.channels[:3] == ("D1_1", "D1_2", "D1_3")
    assert [s.stop - s.start for s in layout.section_columns()] == [3, 3, 3]


def test_clearance_in_millimetres_for_metres_is_refused():
    layout = seed001_layout()
    with pytest.raises(InputError) as error:
        replace(layout, radial_clearance=0.55)  # 0.55 m: the unit was mm
    message = _one_line(error)
    assert message.startswith("radial_clearance = 0.55 m: allowed in [")
    with pytest.raises(InputError, match="radial_clearance = 5.5e-07 m"):
        replace(layout, radial_clearance=0.55e-6)  # um taken for mm


def test_mounting_distance_off_by_1000_names_the_probe():
    layout = seed001_layout()
    section = layout.sections[1]
    probes = (replace(section.probes[0], mounting_distance=1.2),) + section.probes[1:]
    sections = (layout.sections[0], replace(section, probes=probes), layout.sections[2])
    with pytest.raises(InputError) as error:
        replace(layout, sections=sections)
    assert _one_line(error).startswith("sections[1].probes[0].mounting_distance = 1.2 m: allowed in [0, 0.0275]")


def test_sections_out_of_order_or_outside_the_bearing():
    layout = seed001_layout()
    swapped = (layout.sections[1], layout.sections[0], layout.sections[2])
    with pytest.raises(InputError, match=r"^sections\[1\]\.position = 0.292 m: allowed > 0.4295"):
        replace(layout, sections=swapped)
    outside = layout.sections[:2] + (replace(layout.sections[2], position=1.3),)
    with pytest.raises(InputError, match=r"^sections\[2\]\.position = 1.3 m: allowed inside the bearing, \[0, 1.2\]"):
        replace(layout, sections=outside)


def test_a_section_needs_two_probes_not_on_one_line():
    layout = seed001_layout()
    top, _, bottom = layout.sections[0].probes
    one = (replace(layout.sections[0], probes=(top,)),) + layout.sections[1:]
    with pytest.raises(InputError, match=r"^sections\[0\]\.probes = 1: allowed at least 2"):
        replace(layout, sections=one)
    opposite = replace(bottom, angle=math.radians(135.0))  # 315 and 135 deg: one diameter
    collinear = (replace(layout.sections[0], probes=(top, opposite)),) + layout.sections[1:]
    with pytest.raises(InputError, match=r"^sections\[0\]\.probes = \[315.0, 135.0\] deg"):
        replace(layout, sections=collinear)


def test_roughness_rq_factor_and_channel_names():
    layout = seed001_layout()
    with pytest.raises(InputError, match=r"^roughness_bearing = 0.0016 m: allowed <="):
        replace(layout, roughness_bearing=1.6e-3)  # 1.6 mm: um taken for mm
    with pytest.raises(InputError, match=r"^rq_factor = 1.5: allowed in \[1.2, 1.26\]"):
        replace(layout, rq_factor=1.5)
    renamed = tuple(replace(p, name="D1_1") for p in layout.sections[1].probes[:1]) + layout.sections[1].probes[1:]
    sections = (layout.sections[0], replace(layout.sections[1], probes=renamed), layout.sections[2])
    with pytest.raises(InputError, match=r"^sections\[1\]\.probes\[0\]\.name = 'D1_1'"):
        replace(layout, sections=sections)


def test_calibration_round_trip_and_sign():
    probe = Probe("p", 0.0, 1e-3, sensitivity=8000.0, zero=0.3e-3, sign=-1)
    gaps = np.array([0.3e-3, 1.0e-3, 2.5e-3])
    volts = probe.signal(gaps)
    assert volts[0] == 0.0 and volts[1] == pytest.approx(-5.6)  # 8 mV/um over 0.7 mm, falling
    assert probe.gap(volts) == pytest.approx(gaps, abs=1e-15)


def test_layout_gaps_checks_the_block_shape():
    layout = seed001_layout()
    with pytest.raises(InputError, match=r"^signals = \(10, 8\) V: allowed \(samples, 9\)"):
        layout.gaps(np.zeros((10, 8)))


def test_two_probe_section_is_valid():
    probes = (Probe("a", math.radians(315.0), 1e-3), Probe("b", math.radians(45.0), 1e-3))
    layout = ProbeLayout((Section("S", 0.5, probes),), length=1.0, radius=0.1, radial_clearance=2e-4)
    assert layout.journal_radius == pytest.approx(0.0998)


def test_readings_beyond_a_probes_range_are_flagged():
    layout = seed001_layout()
    gaps = np.tile([1.5e-3, 1.5e-3, 0.2e-3] * 3, (4, 1))
    gaps[1, 0] = 3.31e-3  # probe 1: zero 0.3 mm + range 3 mm = 3.3 mm
    gaps[2, 2] = 0.04e-3  # probe 3: below its zero point 0.05 mm
    gaps[3, 5] = np.nan
    mask = within_range(layout, gaps)
    assert (~mask).sum() == 3 and not mask[1, 0] and not mask[2, 2] and not mask[3, 5]
