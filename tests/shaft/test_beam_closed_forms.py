"""Beam elements and the alignment model against closed forms.

References: Timoshenko & Gere (1972), *Mechanics of Materials*, for the Euler-Bernoulli
cases; the shear terms are the shear-force work of a Timoshenko beam (deflection from
shear = integral of V v_unit / (kappa G A)), e.g. Roark's Formulas for Stress and
Strain, 8th ed., Table 8.1 notes. Tolerance 1e-9 relative: the elements are exact for
end loads and uniform loads, so only round-off remains.
"""

from __future__ import annotations

import numpy as np
import pytest

from shaftline.shaft import AlignmentModel, Bearing, ShaftLine, ShaftSegment
from shaftline.shaft.fem import PinnedBeam, build_mesh, shear_coefficient, uniform_load_vector

LENGTH = 6.0
DIAMETER = 0.5
E = 206e9
NU = 0.3


def beam(theory: str, length: float = LENGTH):
    line = ShaftLine(
        segments=(ShaftSegment(length, DIAMETER, youngs_modulus=E, poisson_ratio=NU),),
        bearings=(Bearing("a", 0.25, 0.5), Bearing("b", length - 0.25, 0.5)),
        self_weight=False,
        element_length=0.3,
        beam_theory=theory,
    )
    mesh = build_mesh(line, np.array([0.0, 0.5 * length, length]))
    ei = mesh.bending_stiffness[0]
    area = np.pi / 4 * DIAMETER**2
    kga = shear_coefficient(np.array(DIAMETER), np.array(0.0), np.array(NU)) * E / (2 * (1 + NU)) * area
    return mesh, ei, (float(kga) if theory == "timoshenko" else np.inf)


@pytest.mark.parametrize("theory", ["euler_bernoulli", "timoshenko"])
def test_cantilever_tip_load(theory):
    mesh, ei, kga = beam(theory)
    fixed = PinnedBeam(mesh, (0, 1))
    force = np.zeros(2 * mesh.nodes)
    force[-2] = -1e5
    tip = fixed.solve(force)[-2]
    assert tip == pytest.approx(-1e5 * LENGTH**3 / (3 * ei) - 1e5 * LENGTH / kga, rel=1e-9)


@pytest.mark.parametrize("theory", ["euler_bernoulli", "timoshenko"])
def test_simply_supported_centre_load_and_moment(theory):
    mesh, ei, kga = beam(theory)
    pinned = PinnedBeam(mesh, (0, 2 * mesh.nodes - 2))
    middle = int(mesh.node_at(0.5 * LENGTH))
    force = np.zeros(2 * mesh.nodes)
    force[2 * middle] = -2e5
    u = pinned.solve(force)
    assert u[2 * middle] == pytest.approx(-2e5 * LENGTH**3 / (48 * ei) - 2e5 * LENGTH / (4 * kga), rel=1e-9)
    ends = pinned.end_forces(u, np.zeros(mesh.nodes - 1))
    # sagging moment under the load: P L / 4
    assert ends[middle - 1, 3] == pytest.approx(2e5 * LENGTH / 4, rel=1e-9)


@pytest.mark.parametrize("theory", ["euler_bernoulli", "timoshenko"])
def test_propped_cantilever_uniform_load(theory):
    """Prop reaction 3 w L / 8 without shear; with shear from compatibility of the tip:
    R = (w L^4 / 8EI + w L^2 / 2kGA) / (L^3 / 3EI + L / kGA)."""
    mesh, ei, kga = beam(theory)
    w = 5e4
    propped = PinnedBeam(mesh, (0, 1, 2 * mesh.nodes - 2))
    force = uniform_load_vector(mesh, np.full(mesh.nodes - 1, -w))
    u = propped.solve(force)
    prop = propped.reactions(u, force)[2]
    expected = (w * LENGTH**4 / (8 * ei) + w * LENGTH**2 / (2 * kga)) / (LENGTH**3 / (3 * ei) + LENGTH / kga)
    assert prop == pytest.approx(expected, rel=1e-9)
    if theory == "euler_bernoulli":
        assert prop == pytest.approx(3 * w * LENGTH / 8, rel=1e-9)


def three_support_line(theory: str) -> AlignmentModel:
    span = 5.0
    line = ShaftLine(
        segments=(ShaftSegment(2 * span, 0.4, youngs_modulus=E, poisson_ratio=NU),),
        bearings=(Bearing("a", 5e-7, 1e-6), Bearing("b", span, 1e-6), Bearing("c", 2 * span - 5e-7, 1e-6)),
        element_length=0.25,
        beam_theory=theory,
    )
    return AlignmentModel(line)


@pytest.mark.parametrize("theory", ["euler_bernoulli", "timoshenko"])
def test_three_equidistant_supports(theory):
    """Two equal spans under self-weight: reactions 3/8, 10/8, 3/8 w L (Euler-Bernoulli);
    with shear, the middle reaction from compatibility over the double span 2L:
    R = (5 w (2L)^4 / 384EI + w (2L)^2 / 8kGA) / ((2L)^3 / 48EI + 2L / 4kGA)."""
    model = three_support_line(theory)
    span = 5.0
    result = model.solve()[0]
    w = model.mesh.weight_per_length[0]
    ei = model.mesh.bending_stiffness[0]
    kga = (
        shear_coefficient(np.array(0.4), np.array(0.0), np.array(NU)) * E / (2 * (1 + NU)) * model.mesh.area[0]
        if theory == "timoshenko"
        else np.inf
    )
    two = 2 * span
    middle = (5 * w * two**4 / (384 * ei) + w * two**2 / (8 * kga)) / (two**3 / (48 * ei) + two / (4 * kga))
    reactions = [b.reaction_y for b in result.bearings]
    assert reactions[1] == pytest.approx(middle, rel=1e-9)
    assert reactions[0] == pytest.approx(0.5 * (w * two - middle), rel=1e-9)
    if theory == "euler_bernoulli":
        assert np.allclose(np.array(reactions) / (w * span), [3 / 8, 10 / 8, 3 / 8], rtol=1e-9)
    # Influence matrix: raising the middle support by d adds d / ((2L)^3/48EI + 2L/4kGA) there.
    stiffness = 1.0 / (two**3 / (48 * ei) + two / (4 * kga))
    expected = stiffness * np.array([[0.25, -0.5, 0.25], [-0.5, 1.0, -0.5], [0.25, -0.5, 0.25]])
    assert np.allclose(model.influence_matrix().matrix, expected, rtol=1e-8)
