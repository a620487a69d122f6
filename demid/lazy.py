"""A package's names exported from their submodules on first use (PEP 562): importing a package for one light
part does not import its heavy siblings.  A bottom module: it imports nothing from demid."""

from __future__ import annotations

from importlib import import_module


def lazy_exports(package: str, where: dict[str, str]):
    """``(__getattr__, __all__)`` for ``package``: each name of ``where`` is read from its module (a name
    relative to ``package``, e.g. ``.render`` or ``..plots.criticism``) the first time it is asked for."""

    def __getattr__(name: str):
        if name in where:
            return getattr(import_module(where[name], package), name)
        raise AttributeError(f"module {package!r} has no attribute {name!r}")

    return __getattr__, sorted(where)
