"""The type stubs of the compiled core (python/stcontact/_core.pyi) name exactly what stcontact._core
exports: the same functions, classes, members and arguments, so that they cannot drift from the
bindings. The stubs are read with ast beside the imported package (where CMake copies them)."""

import ast
import inspect
import os
import re

import stcontact
from stcontact import _core

STUB = os.path.join(os.path.dirname(stcontact.__file__), "_core.pyi")
PICKLING = {"__getstate__", "__setstate__"}
# pybind11 puts the signature first in the docstring: "name(arg: type, ...) -> type".
SIGNATURE = re.compile(r"^\w+\((.*)\) -> ")


def stub_tree():
    with open(STUB) as f:
        return ast.parse(f.read(), STUB)


def public(names):
    return {n for n in names if not n.startswith("_") or n in PICKLING}


def top_level_parts(text):
    """`text` split at the commas outside brackets ("a: Dict[str, int], b: int" -> two parts)."""
    parts, depth, start = [], 0, 0
    for i, char in enumerate(text):
        depth += {"[": 1, "(": 1, "]": -1, ")": -1}.get(char, 0)
        if char == "," and depth == 0:
            parts.append(text[start:i])
            start = i + 1
    parts.append(text[start:])
    return [part.strip() for part in parts if part.strip()]


def arguments_of(function):
    """The argument names pybind11 gives `function` (self included for methods)."""
    match = SIGNATURE.match(function.__doc__ or "")
    assert match, "%s: no signature in its docstring" % function.__name__
    return [part.split(":")[0].strip() for part in top_level_parts(match.group(1))]


def stub_arguments(node):
    return [arg.arg for arg in node.args.args]


def is_property(node):
    return isinstance(node, ast.FunctionDef) and any(
        isinstance(d, ast.Name) and d.id == "property" for d in node.decorator_list)


def is_static(node):
    return any(isinstance(d, ast.Name) and d.id == "staticmethod" for d in node.decorator_list)


def stub_members(class_node):
    return {node.name: node for node in class_node.body if isinstance(node, ast.FunctionDef)}


def module_level(tree):
    names = {}
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            names[node.name] = node
        elif isinstance(node, ast.AnnAssign):
            names[node.target.id] = node
    return names


def test_the_stub_names_every_export_and_nothing_else():
    stubs = {name for name in module_level(stub_tree()) if not name.startswith("_") or name == "__version__"}
    exported = public(dir(_core)) | {"__version__"}
    assert stubs == exported


def test_functions_have_the_bindings_arguments():
    for name, node in module_level(stub_tree()).items():
        if isinstance(node, ast.FunctionDef):
            assert stub_arguments(node) == arguments_of(getattr(_core, name)), name


def test_classes_have_the_bindings_members_and_arguments():
    for name, node in module_level(stub_tree()).items():
        if not isinstance(node, ast.ClassDef):
            continue
        cls = getattr(_core, name)
        assert inspect.isclass(cls), name
        if issubclass(cls, BaseException):  # InputError: an exception class, nothing of its own
            assert [base.id for base in node.bases] == [b.__name__ for b in cls.__bases__]
            assert not stub_members(node)
            continue
        members = stub_members(node)
        assert set(members) == public(vars(cls)), name
        for member, stub in members.items():
            bound = vars(cls)[member]
            assert is_property(stub) == isinstance(bound, property), (name, member)
            assert is_static(stub) == isinstance(bound, staticmethod), (name, member)
            if not is_property(stub):
                function = bound.__func__ if isinstance(bound, staticmethod) else bound
                assert stub_arguments(stub) == arguments_of(function), (name, member)


def test_the_package_is_marked_typed():
    assert os.path.isfile(os.path.join(os.path.dirname(stcontact.__file__), "py.typed"))
