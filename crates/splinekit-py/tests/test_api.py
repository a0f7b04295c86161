"""The type stubs describe the module as it is (CI also runs mypy.stubtest), and every
public item has a docstring."""

import ast
import inspect
import pathlib

import splinekit as sk
from splinekit import _splinekit

STUBS = pathlib.Path(sk.__file__).with_name("_splinekit.pyi")


def stub_names():
    """The stub's public classes, each with its methods (those of the stub-only private
    bases it derives from included: they stand for methods each class defines itself at
    run time), and its public functions."""
    tree = ast.parse(STUBS.read_text())
    bodies, bases, functions = {}, {}, set()
    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            bodies[node.name] = {n.name for n in node.body if isinstance(n, ast.FunctionDef)}
            bases[node.name] = [b.id for b in node.bases if isinstance(b, ast.Name) and b.id.startswith("_")]
        elif isinstance(node, ast.FunctionDef) and not node.name.startswith("_"):
            functions.add(node.name)

    def methods(name):
        return bodies[name].union(*(methods(b) for b in bases[name]))

    classes = {name: methods(name) for name in bodies if not name.startswith("_")}
    return classes, functions


def public(cls):
    own = {k for k, v in vars(cls).items() if not k.startswith("_") or k == "__call__"}
    return own


def test_stubs_match_the_module():
    classes, functions = stub_names()
    # The classes the registry makes from a kind's fields have their stubs too (a kind
    # declared `python(fields "Name")` fails here until its class is in the stubs).
    made = set(_splinekit._FIELDS_CLASSES)
    assert made <= set(classes), made - set(classes)
    runtime = {n for n in dir(_splinekit) if not n.startswith("_")}
    runtime_classes = {n for n in runtime if inspect.isclass(getattr(_splinekit, n))}
    assert runtime_classes == set(classes)
    assert {n for n in runtime if callable(getattr(_splinekit, n))} - runtime_classes == functions
    for name, methods in classes.items():
        cls = getattr(_splinekit, name)
        assert public(cls) <= methods | {"__init__"}, (name, public(cls) - methods)
        documented = {m for m in methods if m not in ("__init__", "__new__")}
        assert documented <= set(dir(cls)), (name, documented - set(dir(cls)))


def test_every_public_item_has_a_docstring():
    for name in sk.__all__:
        item = getattr(sk, name)
        assert inspect.getdoc(item), name
        if inspect.isclass(item):
            for attr, value in vars(item).items():
                if not attr.startswith("_"):
                    assert inspect.getdoc(value), f"{name}.{attr}"
