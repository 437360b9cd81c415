"""The wear verbs of the command line."""

from __future__ import annotations

import json
from pathlib import Path

from typer.testing import Result

from tests.conftest import invoke

ROOT = Path(__file__).resolve().parents[1]


def shaftline(*args: str) -> Result:
    return invoke(*args)


def test_pitchlog_with_case(tmp_path):
    out = tmp_path / "out"
    result = shaftline(
        "wear",
        "pitchlog",
        str(ROOT / "examples" / "ferry_pitch_log.csv"),
        "--case",
        str(ROOT / "examples" / "ferry_wear.toml"),
        "--out",
        str(out),
        "--json",
        "-",
    )
    assert result.exit_code == 0, result.stderr
    wear = json.loads(result.stdout)["wear"]
    names = [s["name"] for s in wear["scenarios"]]
    assert names == [
        "standard control",
        "uncorrected signal",
        "active (MIMO) control",
        "standard control with fretting",
    ]
    assert wear["pitch_travel_raw"] > wear["pitch_travel_corrected"] > 0
    for name in ("wear_pitch_log", "wear_depth", "wear_weibull"):
        assert (out / "figures" / f"{name}.png").stat().st_size > 10_000


def test_weibull_verb(tmp_path):
    data = tmp_path / "depths.csv"
    data.write_text(
        "depth_mm\n" + "\n".join(map(str, [0.09, 0.10, 0.06, 0.08, 0.097, 0.073, 0.077, 0.048, 0.043, 0.107]))
    )
    result = shaftline("wear", "weibull", str(data), "--threshold", "0.12", "--json", "-")
    assert result.exit_code == 0, result.stderr
    document = json.loads(result.stdout)
    assert abs(document["shape"] - 4.43) < 0.005
    assert 0 < document["exceedance"]["estimate"] < document["exceedance"]["upper"] < 1


def test_weibull_bad_data(tmp_path):
    data = tmp_path / "bad.csv"
    data.write_text("x\n0.1\n0.2\n")
    result = shaftline("wear", "weibull", str(data))
    assert result.exit_code == 2 and "at least 3" in result.stderr
    data.write_text("x\n0.1\nabc\n0.3\n")
    result = shaftline("wear", "weibull", str(data))
    assert result.exit_code == 2 and "row 3" in result.stderr


def test_pitchlog_with_gap(tmp_path):
    log = tmp_path / "log.csv"
    log.write_text("time,pitch\n0,1\n0.1,1\n0.2,1\n5.0,1\n5.1,1\n")
    result = shaftline(
        "wear",
        "pitchlog",
        str(log),
        "--case",
        str(ROOT / "examples" / "ferry_wear.toml"),
        "--out",
        str(tmp_path / "out"),
    )
    assert result.exit_code == 2 and "gap" in result.stderr
    assert not (tmp_path / "out").exists()
