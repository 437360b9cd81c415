"""Failure says so: a result that is not acceptable is flagged at the top of the terminal
output and of the report, listed in the JSON, and ends the command with exit status 3; a
failed design criterion does so with --strict."""

from __future__ import annotations

import json
from pathlib import Path

from tests.conftest import MINIMAL_CASE, invoke

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


def test_an_overloaded_film_is_not_acceptable(tmp_path):
    """50 MN on the small bearing (a mean pressure of 5 GPa): the journal reaches the film floor;
    the run reports it first, in the JSON and in the report, and exits 3."""
    case = tmp_path / "case.toml"
    # 5 GPa is no real stern tube's mean pressure: the plausibility guard is lowered on purpose
    unusual = '[case]\nname = "small bearing"\nunusual = ["bearing.operation.load"]\n'
    case.write_text(
        MINIMAL_CASE.replace('load = "5 kN"', 'load = "50 MN"').replace('[case]\nname = "small bearing"\n', unusual)
    )
    out = tmp_path / "out"
    result = invoke("bearing", "solve", str(case), "--out", str(out), "--json", str(tmp_path / "r.json"))
    assert result.exit_code == 3, result.output
    lines = result.stdout.splitlines()
    assert lines[0] == "accepted outside the plausible range ([case] unusual): bearing.operation.load"
    assert lines[1].startswith("NOT ACCEPTABLE: Stern-tube bearing film: small bearing: the film does not carry")
    findings = json.loads((tmp_path / "r.json").read_text())["findings"]
    assert findings and findings[0]["capability"] == "bearing" and findings[0]["criterion"] is False
    html = (out / "report.html").read_text()
    assert html.index("The result is not acceptable") < html.index("Stern-tube bearing film</h2>")
    assert "bearing.operation.load" in html[: html.index("Stern-tube bearing film</h2>")]  # the lowered guard


def test_a_sound_film_exits_0_with_no_findings(tmp_path):
    case = tmp_path / "case.toml"
    case.write_text(MINIMAL_CASE)
    result = invoke("bearing", "solve", str(case), "--json", "-")
    assert result.exit_code == 0 and json.loads(result.stdout)["findings"] == []


def test_failed_rule_checks_are_a_criterion_exit_3_only_when_strict():
    example = str(EXAMPLES / "single_screw_alignment.toml")
    plain = invoke("align", example, "--json", "-")
    assert plain.exit_code == 0
    findings = json.loads(plain.stdout)["findings"]
    assert [f["criterion"] for f in findings] == [True] and "class-rule checks fail" in findings[0]["text"]
    assert "class-rule checks fail" in plain.stderr  # with the JSON on stdout, the banner goes to stderr
    assert invoke("align", example, "--strict", "--json", "-").exit_code == 3


def test_an_optimiser_on_its_bound_says_so(tmp_path):
    """The example's offsets need up to 3.7 mm; with a 1 mm bound the optimiser sits on it."""
    text = (EXAMPLES / "single_screw_alignment.toml").read_text().replace('bound = "4 mm"', 'bound = "1 mm"')
    case = tmp_path / "case.toml"
    case.write_text(text)
    result = invoke("align", str(case), "--json", "-")
    texts = [f["text"] for f in json.loads(result.stdout)["findings"]]
    assert any("sits on its bound of ±1 mm" in t for t in texts), texts


def test_a_solver_failure_is_one_line_and_exit_3(tmp_path, monkeypatch):
    """A numerical method that does not settle on accepted inputs: one line, exit 3, no output."""
    import shaftline.film.solve as solve
    from shaftline.film.cavitation import CavitationConvergenceError

    def fails(*args, **kwargs):
        raise CavitationConvergenceError("Reynolds-condition active set did not settle")

    monkeypatch.setattr(solve, "solve_case", fails)
    case = tmp_path / "case.toml"
    case.write_text(MINIMAL_CASE)
    result = invoke("run", str(case), "--out", str(tmp_path / "out"))
    assert result.exit_code == 3
    assert result.stderr.strip() == "not solved: Reynolds-condition active set did not settle; nothing was written"
    assert not (tmp_path / "out").exists()


def test_a_film_within_three_roughnesses_is_mixed_lubrication(tmp_path):
    """The small bearing runs at h_min of a few tens of µm; with a composite roughness of 20 µm
    (three times: 60 µm) the asperities touch and the smooth-film result is not acceptable."""
    case = tmp_path / "case.toml"
    case.write_text(
        MINIMAL_CASE.replace('radial_clearance = "0.1 mm"', 'radial_clearance = "0.1 mm"\nsurface_roughness = "20 um"')
    )
    result = invoke("bearing", "solve", str(case), "--json", "-")
    assert result.exit_code == 3
    texts = [f["text"] for f in json.loads(result.stdout)["findings"] if not f["criterion"]]
    assert any("mixed lubrication" in t for t in texts), texts
    case.write_text(MINIMAL_CASE)
    assert invoke("bearing", "solve", str(case), "--json", "-").exit_code == 0  # default 2.2 µm: 6.6 µm < h_min


def _strict_helps() -> dict[str, str]:
    """``--strict`` help of every command that has the option, by command line."""
    import typer

    from shaftline.cli import make_app

    def commands(command, path):
        for name, sub in (getattr(command, "commands", None) or {}).items():
            yield from commands(sub, [*path, name])
        if not getattr(command, "commands", None):
            yield " ".join(path), command

    helps = {}
    for path, command in commands(typer.main.get_command(make_app()), []):
        for parameter in command.params:
            if "--strict" in parameter.opts:
                helps[path] = " ".join(parameter.help.split())
    return helps


def test_each_verb_says_what_strict_judges_there():
    # `--strict` had one text on every verb ("a rule check, an allowable wear"); each verb's own
    # now names what its capability's findings judge as design criteria (then exit 3) and what
    # exits with 3 without it. The generic text is `run`'s alone, and verbs of different
    # capabilities never share one.
    helps = _strict_helps()
    assert len(helps) >= 13
    generic = helps.pop("run")
    assert "each verb's --strict help names its own" in generic
    assert all(text != generic for text in helps.values())
    assert helps["bearing solve"] == helps["bearing stribeck"] and helps["cpp fretting"] == helps["cpp motion"]
    distinct = {helps[path] for path in ("align", "bearing solve", "contact ehl", "cpp fretting", "gears scuffing")}
    distinct |= {helps[f"monitor {verb}"] for verb in ("simulate", "identify")}
    distinct |= {helps[f"design {verb}"] for verb in ("slopes", "robustness", "sweep")}
    assert len(distinct) == 10
    # Checked against what the findings do (the cases of the tests above): failed rule checks
    # are a criterion of align, a film at its floor makes a bearing run not acceptable anyway,
    # a rejected window makes an identify run not acceptable anyway and an alarm needs --strict.
    criteria, always = helps["align"].split(" Without it, ")
    assert "a class-rule check fails" in criteria and "a film at its floor" in always
    criteria, always = helps["bearing solve"].split(" Without it, ")
    assert "h_min is below 30 µm" in criteria and "a film at its floor (contact)" in always
    criteria, always = helps["monitor identify"].split(" Without it, ")
    assert "a lambda alarm" in criteria and "could not be identified (rejected)" in always
    assert helps["design sweep"].startswith("No effect here")
