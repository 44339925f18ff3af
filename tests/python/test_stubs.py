"""The type stubs (kernel/python/ratbez-stubs/__init__.pyi) are current and complete: the committed file is
what scripts/generate_stubs.py makes of the built module (a public name added, renamed or documented
differently fails here until the stubs are regenerated), it parses, every public name of the module has
a stub with its parameters, and every public function, method, class and property has a docstring."""
import ast
import importlib.util
import inspect
from pathlib import Path

import pytest

import ratbez

ROOT = Path(__file__).resolve().parents[2]
STUBS = ROOT / "kernel" / "python" / "ratbez-stubs" / "__init__.pyi"


def generator():
    spec = importlib.util.spec_from_file_location("generate_stubs", ROOT / "scripts" / "generate_stubs.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def public_members():
    """(qualified name, object) of every public function, class, method and property."""
    for name in dir(ratbez):
        if name.startswith("_"):
            continue
        value = getattr(ratbez, name)
        if inspect.isclass(value):
            yield name, value
            for member, attribute in vars(value).items():
                if not member.startswith("_"):
                    yield f"{name}.{member}", attribute
        elif callable(value):
            yield name, value


def prose(doc):
    """A docstring without pybind11's signature lines."""
    return [line for line in (doc or "").splitlines() if line.strip() and " -> " not in line
            and line.strip() != "Overloaded function."]


@pytest.mark.skipif(not (ratbez.has_occt and ratbez.has_cgal),
                    reason="the stubs describe the full module (with OCCT and CGAL)")
def test_stubs_are_current():
    assert STUBS.read_text() == generator().generate(), \
        "stale stubs: run PYTHONPATH=build/kernel/python /usr/bin/python3 scripts/generate_stubs.py"


@pytest.mark.skipif(not (ratbez.has_occt and ratbez.has_cgal),
                    reason="the stubs describe the full module (with OCCT and CGAL)")
def test_every_public_name_has_a_stub():
    tree = ast.parse(STUBS.read_text())
    stubbed = set()
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            stubbed.add(node.name)
        if isinstance(node, ast.ClassDef):
            stubbed.update(f"{node.name}.{item.name}" for item in node.body if isinstance(item, ast.FunctionDef))
    missing = [name for name, _ in public_members() if name not in stubbed and not name.startswith("Error.")]
    assert not missing, missing


def test_stub_parameters_match_the_module():
    tree = ast.parse(STUBS.read_text())
    stubs = {node.name: node for node in tree.body if isinstance(node, ast.FunctionDef)}
    for name, function in stubs.items():
        expected = [p.arg for p in function.args.args]
        doc_signature = getattr(ratbez, name).__doc__.splitlines()[0]
        for argument in expected:
            assert f"{argument}: " in doc_signature, (name, argument)
    # No parameter the module converts itself is left as a bare object.
    assert ": object" not in STUBS.read_text()


def test_every_public_name_has_a_docstring():
    undocumented = []
    for name, value in public_members():
        if name.startswith("Error."):
            continue
        doc = value.__doc__ if not isinstance(value, staticmethod) else value.__func__.__doc__
        if not prose(doc):
            undocumented.append(name)
    assert not undocumented, undocumented


@pytest.mark.skipif(not (ratbez.has_occt and ratbez.has_cgal),
                    reason="the stubs describe the full module (with OCCT and CGAL)")
def test_settable_properties_are_settable_in_the_stubs():
    # Solid.name is free to set; its stub was a read-only property, so a type checker called `s.name = ...` an error.
    tree = ast.parse(STUBS.read_text())
    setters = {f"{node.name}.{item.name}" for node in tree.body if isinstance(node, ast.ClassDef)
               for item in node.body if isinstance(item, ast.FunctionDef)
               and any(isinstance(d, ast.Attribute) and d.attr == "setter" for d in item.decorator_list)}
    settable = {name for name, value in public_members() if isinstance(value, property) and value.fset is not None}
    assert "Solid.name" in settable
    assert setters == settable


def test_the_stubs_lie_beside_the_built_module():
    # User trial: with PYTHONPATH=build/kernel/python (as the README runs it) editors found no stubs; the build
    # puts them beside the module as ratbez.pyi.
    beside = Path(ratbez.__file__).with_name("ratbez.pyi")
    assert beside.read_text() == STUBS.read_text()
