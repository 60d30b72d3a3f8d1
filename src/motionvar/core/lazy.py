"""Names of a package imported on first use (PEP 562), so that a rule that needs one
module of a package does not load the others (and their scikit-learn or torch)."""

from __future__ import annotations

import importlib
from collections.abc import Callable, Mapping, Sequence
from typing import Any


def lazy_exports(
    package: str, exports: Mapping[str, Sequence[str]]
) -> tuple[Callable[[str], Any], Callable[[], list[str]]]:
    """``__getattr__`` and ``__dir__`` for ``package`` (its ``__name__``): ``exports`` maps a
    relative module (".sfpca") to the names it provides; a name is imported from its module
    the first time it is asked for and then kept in the package's namespace.

    A name may not be that of its own module (``".diversity": ["diversity"]``): once the
    submodule is imported, the package's attribute is the module and ``__getattr__`` is no
    longer asked; import such a name eagerly instead."""
    where = {name: module for module, names in exports.items() for name in names}
    shadowed = sorted(name for name, module in where.items() if name == module.rsplit(".", 1)[-1])
    if shadowed:
        raise ValueError(f"{package}: lazy names {shadowed} are also their modules' names; import them eagerly")

    def __getattr__(name: str) -> Any:
        if name not in where:
            raise AttributeError(f"module {package!r} has no attribute {name!r}")
        value = getattr(importlib.import_module(where[name], package), name)
        setattr(importlib.import_module(package), name, value)
        return value

    def __dir__() -> list[str]:
        return sorted(set(vars(importlib.import_module(package))) | set(where))

    return __getattr__, __dir__
