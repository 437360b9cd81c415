"""A new capability joins by registration alone: its case-file table, its verb, JSON and
report section appear without any change to the command line, the pipeline or the report."""

from __future__ import annotations

import json
from dataclasses import dataclass
from typing import Any

import pytest

from shaftline import registry
from shaftline.cases import parse_case
from shaftline.cases.types import Force, PositiveLength, Section
from shaftline.registry import BuildContext, Capability, Progress, Verb, no_progress
from shaftline.report.blocks import Block, Figure, Paragraph, Table
from shaftline.report.plotting import figure_function
from tests.conftest import invoke


class PinSection(Section):
    """A steel pin in shear (a toy)."""

    diameter: PositiveLength
    """Pin diameter."""
    force: Force
    """Shear force."""


@dataclass(frozen=True)
class Pin:
    diameter: float
    force: float


@dataclass(frozen=True)
class PinResult:
    stress: float


@figure_function(size=(4, 3))
def stress_bar(result: PinResult, *, ax: Any) -> Any:
    ax.bar(["pin"], [result.stress / 1e6])
    return ax


class PinShear(Capability[PinSection, Pin, PinResult]):
    key = "pin"
    title = "Pin <shear>"
    verbs = (Verb(("pin", "shear"), "Mean shear stress of the pin."),)

    def schema(self) -> type[PinSection]:
        return PinSection

    def build(self, section: PinSection, context: BuildContext) -> Pin:
        return Pin(section.diameter, section.force)

    def solve(self, study: Pin, progress: Progress = no_progress, **options: Any) -> PinResult:
        progress("pin")
        return PinResult(study.force / (3.141592653589793 * study.diameter**2 / 4))

    def to_json(self, result: PinResult) -> dict[str, Any]:
        return {"units": {"stress": "Pa"}, "stress": result.stress}

    def summary(self, result: PinResult) -> list[Block]:
        return [Table(["quantity", "value"], [["mean shear stress [MPa]", f"{result.stress / 1e6:.2f}"]], "Pin")]

    def report(self, result: PinResult) -> list[Block]:
        return [Paragraph("<b>not bold</b>"), *self.summary(result), Figure("pin.png", stress_bar, (result,))]


@pytest.fixture
def pin():
    with registry.registered(PinShear()) as capability:
        yield capability


def test_the_case_schema_grows_a_table(pin):
    case = parse_case({"pin": {"diameter": "20 mm", "force": 1e4}})
    assert case["pin"] == Pin(0.02, 1e4)
    with pytest.raises(Exception) as error:
        parse_case({"pin": {"diameter": "-20 mm", "force": 1e4}})
    assert str(error.value) == "pin.diameter = -0.02 m: allowed > 0"


def test_the_verb_json_and_report_appear(pin, tmp_path):
    case = tmp_path / "pin.toml"
    case.write_text('[case]\nname = "pin"\n[pin]\ndiameter = "20 mm"\nforce = "10 kN"\n')
    result = invoke("pin", "shear", str(case), "--json", "-", "--out", str(tmp_path / "out"))
    assert result.exit_code == 0, result.output
    assert json.loads(result.stdout)["pin"]["stress"] == pytest.approx(1e4 / (3.141592653589793 * 1e-4))
    html = (tmp_path / "out" / "report.html").read_text()
    assert "Pin &lt;shear&gt;" in html and "&lt;b&gt;not bold&lt;/b&gt;" in html
    assert (tmp_path / "out" / "figures" / "pin.png").stat().st_size > 1000
    schema = json.loads(invoke("schema").stdout)
    assert "pin" in schema["properties"]


def test_the_registry_is_restored_and_keys_are_unique(pin):
    with pytest.raises(ValueError):
        registry.register(PinShear())
    registry.unregister("pin")
    assert "pin" not in registry.capabilities()
    registry.register(pin)  # the fixture removes it again


def test_a_verb_cannot_shadow_another(pin):
    from shaftline.cli import make_app

    class Shadow(PinShear):
        key = "shadow"
        verbs = (Verb(("bearing", "solve"), "a second bearing solve"),)

    with registry.registered(Shadow()), pytest.raises(ValueError, match="bearing solve"):
        make_app()
