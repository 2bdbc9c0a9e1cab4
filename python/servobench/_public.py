"""Tab completion shows what a module offers, not what it imported (issue 23.6): each servobench module lists its
public names in ``__all__``; :func:`limit_dir_to_all` gives the package's loaded modules a PEP 562 ``__dir__``
returning those names (plus, for a package, its submodules), which is what ``dir()``, IPython and Jedi complete
from. Attribute access is unchanged: ``servobench.axis.np`` still resolves, it is only not offered."""

from __future__ import annotations

__all__ = ["limit_dir_to_all"]

import sys
import types
from typing import Callable


def _public_dir(module: types.ModuleType) -> Callable[[], list[str]]:
    prefix = module.__name__ + "."

    def __dir__() -> list[str]:
        submodules = {name[len(prefix):] for name in sys.modules
                      if name.startswith(prefix) and "." not in name[len(prefix):]
                      and not name[len(prefix):].startswith("_")}
        return sorted(set(module.__all__) | submodules)

    return __dir__


def limit_dir_to_all(package: str) -> None:
    """Gives every loaded module of `package` (and `package` itself) that defines ``__all__`` and no ``__dir__`` of
    its own a ``__dir__`` listing its ``__all__`` and its loaded public submodules."""
    for name, module in list(sys.modules.items()):
        if (name == package or name.startswith(package + ".")) and isinstance(module, types.ModuleType) \
                and "__all__" in vars(module) and "__dir__" not in vars(module):
            module.__dir__ = _public_dir(module)  # type: ignore[method-assign]  # PEP 562 module __dir__
