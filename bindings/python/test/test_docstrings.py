"""Every bound class, function, method and property has a docstring beyond pybind11's generated signature."""

import inspect

import cairn

SUBMODULES = ["systems", "optimization", "multibody", "perception", "planning", "visualization", "examples"]


def own_text(doc, name):
    """The docstring without pybind11's signature lines ("name(...) -> ...", "Overloaded function.", "1. ...")."""
    lines = []
    for line in (doc or "").splitlines():
        stripped = line.strip()
        if not stripped or stripped == "Overloaded function.":
            continue
        if stripped.startswith(name + "(") or (stripped[:1].isdigit() and ". " + name + "(" in stripped):
            continue
        lines.append(stripped)
    return " ".join(lines)


def overload_docs(doc, name):
    """For an overloaded function, the text of each overload (pybind11 numbers them "1. name(...)")."""
    parts, current = [], None
    for line in (doc or "").splitlines():
        stripped = line.strip()
        if stripped[:1].isdigit() and ". " + name + "(" in stripped:
            current = []
            parts.append(current)
        elif current is not None and stripped:
            current.append(stripped)
    return [" ".join(p) for p in parts]


def missing_docs():
    missing = []
    for module_name in SUBMODULES:
        module = getattr(cairn, module_name)
        for name, member in vars(module).items():
            if name.startswith("_"):
                continue
            where = f"cairn.{module_name}.{name}"
            if inspect.isclass(member):
                missing += check_class(member, where)
            elif callable(member):
                missing += check_function(member, name, where)
    return missing


def check_function(function, name, where):
    doc = function.__doc__ or ""
    if "Overloaded function." in doc:
        return [f"{where} (overload {i + 1})" for i, text in enumerate(overload_docs(doc, name)) if not text]
    return [] if own_text(doc, name) else [where]


def check_class(cls, where):
    missing = [] if (cls.__doc__ or "").strip() else [where]
    is_enum = hasattr(cls, "__members__")  # py::enum_ generates __init__, value, name, ... (documented by the enum)
    for name, member in vars(cls).items():
        if name.startswith("_") and (name != "__init__" or is_enum):
            continue
        if is_enum and name in ("value", "name"):
            continue
        qualified = f"{where}.{name}"
        if isinstance(member, property):
            if not (member.__doc__ or "").strip():
                missing.append(qualified)
        elif inspect.isclass(member):
            missing += check_class(member, qualified)
        elif type(member).__name__ == "instancemethod" or callable(member):
            function = getattr(member, "__func__", member)
            if hasattr(function, "__doc__") and type(function).__name__ in ("builtin_function_or_method",
                                                                            "instancemethod"):
                missing += check_function(function, name, qualified)
    return missing


def test_every_binding_has_a_docstring():
    missing = missing_docs()
    assert not missing, "no docstring: " + ", ".join(missing)


def test_the_check_sees_the_bindings():
    # The walk above must reach methods and properties, or it would pass vacuously.
    assert own_text(cairn.systems.DiagramBuilder.Build.__doc__, "Build")
    assert overload_docs(cairn.systems.System.get_input_port.__doc__, "get_input_port")[0]
    assert check_function(len, "len", "len") == []
