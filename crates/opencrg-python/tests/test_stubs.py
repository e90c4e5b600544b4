"""The type stubs that ship with the package name exactly what the modules hold: every
public class, function and constant of `opencrg` and `opencrg.odr`, and every public
method and property of their classes."""

import ast
import pathlib

import opencrg
import opencrg.odr


def stubbed(path):
    """Top-level names of a stub file, and the members of each class in it."""
    tree = ast.parse(pathlib.Path(path).read_text())
    names, members = set(), {}
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            names.add(node.name)
        if isinstance(node, ast.ClassDef):
            members[node.name] = {n.name for n in node.body if isinstance(n, ast.FunctionDef)}
        if isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            names.add(node.target.id)
        if isinstance(node, ast.ImportFrom):
            names.update(a.asname or a.name for a in node.names if a.asname)
    return {n for n in names if not n.startswith("_")}, members


def public(obj):
    return {n for n in dir(obj) if not n.startswith("_")}


def check(module, stub):
    names, members = stubbed(stub)
    runtime = {n for n in public(module) if n not in ("opencrg",)}
    assert runtime - names == set(), f"{module.__name__}: not in the stubs"
    assert names - runtime == set(), f"{module.__name__}: stubbed but missing"
    for cls, stubbed_members in members.items():
        if cls.startswith("_"):
            continue
        have = public(getattr(module, cls))
        want = {m for m in stubbed_members if not m.startswith("_")}
        # Exceptions and named tuples inherit members the stubs need not repeat.
        if issubclass(getattr(module, cls), (Exception, tuple)):
            assert want <= have, f"{cls}: {want - have} stubbed but missing"
            continue
        assert have == want, f"{cls}: missing from the stubs {have - want}, stubbed but missing {want - have}"


def test_the_stubs_name_what_the_modules_hold():
    folder = pathlib.Path(opencrg.__file__).parent
    assert (folder / "py.typed").exists()
    check(opencrg, folder / "__init__.pyi")
    check(opencrg.odr, folder / "odr.pyi")
