"""Every front end exposes every declared setting of its commands (hooke.settings; docs/architecture.md, "Settings"):
the CLI's --help, hooke.calibrate's and hooke.tetrahedralize's keywords and docstrings, and the batch table's columns.
The viewer's live settings (its panel and its scripts' `set`) are checked in tests/interactive."""
import os
import re
import subprocess

import pytest

import hooke
from hooke import batch

CLI = os.environ.get("HOOKE_CLI")
COMMANDS = {  # a command's settings -> the CLI words that run it
    "calibrate": ["calibrate"],
    "compare": ["compare"],
    "simulate": ["simulate"],
    "view": ["view"],
    "mesh": ["mesh", "tetrahedralize"],
    "bench": ["bench"],
}


def _typed(d):
    """The declared default as the Python value a user would pass."""
    text = d["default"]
    if d["type"] == "flag":
        return text == "on"
    if d["type"] == "integer":
        return int(text)
    if d["type"] == "number":
        return float(text)
    return text


def test_every_command_declares_settings():
    for command in list(COMMANDS) + ["batch"]:
        assert hooke.settings(command), command
    with pytest.raises(hooke.InvalidArgument, match="unknown command"):
        hooke.settings("nonsense")


@pytest.mark.skipif(not CLI, reason="HOOKE_CLI not set")
@pytest.mark.parametrize("command", sorted(COMMANDS))
def test_every_declared_setting_is_a_cli_option(command):
    run = subprocess.run([CLI, *COMMANDS[command], "--help"], capture_output=True, text=True)
    if command == "view" and run.returncode != 0:
        pytest.skip("hooke built without the viewer")
    assert run.returncode == 0, run.stderr
    for d in hooke.settings(command):
        assert re.search(r"(?<![\w-])--%s(?![\w-])" % re.escape(d["name"]), run.stdout), (command, d["name"])


def test_every_calibrate_setting_is_a_python_keyword_with_its_help():
    doc = hooke.calibrate.__doc__
    for d in hooke.settings("calibrate"):
        assert re.search(r"^\s+%s\s" % d["keyword"], doc, re.M), d["keyword"]
    for d in hooke.settings("mesh"):
        assert re.search(r"^\s+%s\s" % d["keyword"], hooke.tetrahedralize.__doc__, re.M), d["keyword"]
    # Every keyword is accepted at its declared default, all at once.
    box = hooke.tet_box(0.01, 0.01, 0.02, 1, 1, 2)
    model = hooke.calibrate(box, hooke.Material(1e4, 0.3), **{d["keyword"]: _typed(d) for d in hooke.settings("calibrate")})
    assert model.method in hooke.methods() and model.choice  # auto's pick, and why
    with pytest.raises(hooke.InvalidArgument, match="unknown setting 'densty'"):
        hooke.calibrate(box, hooke.Material(1e4, 0.3), densty=1.0)


def test_every_batch_setting_is_a_study_column():
    columns = {c for c, _, _ in batch.STUDY_COLUMNS}
    for d in hooke.settings("batch"):
        assert d["keyword"] in columns, d["keyword"]
    job = batch.normalise_job({"mesh": "a.msh", "young": "1e4", "poisson": "0.3", "fit_refinements": "2"})
    assert job["fit_refinements"] == 2 and job["density"] == 1000.0 and job["method"] == "auto"
    with pytest.raises(batch.StudyError, match="fit_refinements.*not an integer"):
        batch.normalise_job({"mesh": "a.msh", "young": "1e4", "poisson": "0.3", "fit_refinements": "x"})


def test_ranges_are_checked_once_for_every_front_end():
    box = hooke.tet_box(0.01, 0.01, 0.02, 1, 1, 2)
    message = r"density must be in \(0, inf\] kg/m\^3, not -1"
    with pytest.raises(hooke.InvalidArgument, match=message):
        hooke.calibrate(box, hooke.Material(1e4, 0.3), density=-1.0)
    with pytest.raises(hooke.InvalidArgument, match="fit-refinements must be in \\[0, 8\\], not 9"):
        hooke.calibrate(box, hooke.Material(1e4, 0.3), fit_refinements=9)
    with pytest.raises(hooke.InvalidArgument, match="fit-refinements: '1.5' is not an integer"):
        hooke.calibrate(box, hooke.Material(1e4, 0.3), fit_refinements=1.5)
    if CLI:
        run = subprocess.run([CLI, "calibrate", os.devnull, "--young", "1e4", "--poisson", "0.3", "--density", "-1",
                              "-o", os.devnull], capture_output=True, text=True)
        assert run.returncode == 2 and re.search(message, run.stderr), run.stderr


def test_fit_refinements_sets_the_range_fits_resolution():
    box = hooke.tet_box(0.01, 0.01, 0.02, 1, 1, 2)
    material = hooke.Material(1e4, 0.3)
    grid = hooke.calibrate(box, material, "any-nu-tet", law="neohookean", strain_range=0.1, fit_refinements=0)
    fine = hooke.calibrate(box, material, "any-nu-tet", law="neohookean", strain_range=0.1, fit_refinements=4)
    laws = [int(re.search(r"(\d+) laws measured", m.choice).group(1)) for m in (grid, fine)]
    assert laws[0] < laws[1], laws
    # The grid alone lands on integers; the refined fit may not, and is never worse (its error is in the choice).
    assert grid.spring_exponent == round(grid.spring_exponent)
    worst = [float(re.search(r"worst error ([\d.e+-]+)", m.choice).group(1)) for m in (grid, fine)]
    assert worst[1] <= worst[0]
