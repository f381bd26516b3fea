"""The rules parser is put together from one mixin per concern (lgmcts/language/rules.py); a method
defined twice, in two mixins or twice in one class body, silently takes the place of the other, so no
name may be defined twice."""

from __future__ import annotations

import ast
import inspect
from pathlib import Path

import lgmcts.language
from lgmcts.language.rules import _Parser


def test_no_method_is_defined_in_two_parts_of_the_parser():
    owners: dict[str, list[str]] = {}
    for cls in inspect.getmro(_Parser):
        if cls is object:
            continue
        for name in vars(cls):
            if not (name.startswith("__") and name.endswith("__")):
                owners.setdefault(name, []).append(cls.__name__)
    assert {name: where for name, where in owners.items() if len(where) > 1} == {}


def _twice_in_a_class(source: str) -> list[str]:
    out = []
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.ClassDef):
            seen: set[str] = set()
            for item in node.body:
                if isinstance(item, (ast.FunctionDef, ast.AsyncFunctionDef)) and not item.decorator_list:
                    if item.name in seen:
                        out.append(f"{node.name}.{item.name}")
                    seen.add(item.name)
    return out


def test_no_class_of_the_language_package_defines_a_method_twice():
    root = Path(lgmcts.language.__file__).parent
    found = {p.name: t for p in sorted(root.glob("*.py")) if (t := _twice_in_a_class(p.read_text()))}
    assert found == {}


def test_a_method_defined_twice_is_found():
    assert _twice_in_a_class("class A:\n    def f(self): pass\n    def g(self): pass\n    def f(self): pass\n") == ["A.f"]
