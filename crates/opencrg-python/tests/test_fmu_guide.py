"""The user guide's FMU examples (docs/fmu.md) run as written, with FMPy."""

import os
import pathlib
import re

REPO = pathlib.Path(__file__).resolve().parents[3]


def run_example(tmp_path, first, end):
    """Runs the Python block of the guide's section from `first` to `end` in `tmp_path`."""
    text = (REPO / "docs/fmu.md").read_text()
    section = text[text.index(first):text.index(end)]
    code = re.search(r"```python\n(.*?)```", section, re.S)[1]
    (tmp_path / "examples").symlink_to(REPO / "examples")
    here = os.getcwd()
    os.chdir(tmp_path)
    try:
        exec(compile(code, "docs/fmu.md", "exec"), {})
    finally:
        os.chdir(here)


def test_the_guides_fmpy_example_runs(tmp_path, capsys):
    run_example(tmp_path, "## Driving it with FMPy", "## A road outside the FMU")
    printed = capsys.readouterr().out
    assert printed.strip().endswith("True"), printed
    assert (tmp_path / "demo_road.fmu").stat().st_size > 0


def test_the_guides_road_outside_example_runs(tmp_path, capsys):
    run_example(tmp_path, "## A road outside the FMU", "## Variables")
    printed = capsys.readouterr().out.strip().splitlines()
    assert printed[0] == repr([str(tmp_path / "demo_road_krbi.crg")]), printed
    assert printed[-1] == "True", printed
    assert not [n for n in __import__("zipfile").ZipFile(tmp_path / "outside.fmu").namelist() if n.endswith(".crg")]
