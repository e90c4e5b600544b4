"""The guide's matplotlib recipe (docs/python.md, "Figures") runs on the demo road and
draws what it says: a section, a top view and the roughness figure, text kept as text."""

import re

import opencrg


def test_the_guides_matplotlib_recipe_draws_the_figures(tmp_path, monkeypatch):
    from conftest import REPO

    text = (REPO / "docs/python.md").read_text()
    section = text.split("## Figures\n", 1)[1]
    code = section.split("```python\n", 1)[1].split("```", 1)[0]
    code = code.replace("examples/data/demo_road.crg", str(REPO / "examples/data/demo_road.crg"))
    monkeypatch.chdir(tmp_path)
    exec(compile(code, "docs/python.md", "exec"), {})

    def svg_texts(name):
        return " ".join(re.findall(r"<text[^>]*>([^<]*)</text>", (tmp_path / name).read_text()))

    assert "v [m]" in svg_texts("section.svg") and "z [m]" in svg_texts("section.svg")
    rough = svg_texts("roughness.svg")
    for words in ["n [cycles/m]", "Gd(n) [m³]", "IRI [m/km]", "v = -0.85 m (class"]:
        assert words in rough, words
    assert (tmp_path / "top.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert opencrg.ISO8608_CLASSES == "ABCDEFGH" and len(opencrg.ISO8608_LIMITS) == 7
