"""The user guide's FMU example (docs/fmu.md) runs as written, with FMPy."""

import os
import pathlib
import re

REPO = pathlib.Path(__file__).resolve().parents[3]


def test_the_guides_fmpy_example_runs(tmp_path, capsys):
    text = (REPO / "docs/fmu.md").read_text()
    section = text[text.index("## Driving it with FMPy"):text.index("## Variables")]
    code = re.search(r"```python\n(.*?)```", section, re.S)[1]
    (tmp_path / "examples").symlink_to(REPO / "examples")
    here = os.getcwd()
    os.chdir(tmp_path)
    try:
        exec(compile(code, "docs/fmu.md", "exec"), {})
    finally:
        os.chdir(here)
    printed = capsys.readouterr().out
    assert printed.strip().endswith("True"), printed
    assert (tmp_path / "demo_road.fmu").stat().st_size > 0
