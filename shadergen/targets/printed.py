"""Every library item as a target prints it, kept on disk beside the library's code cache.

A shader's library functions are the same text request after request, and in a new process
printing them (and reading their bodies from the code cache, code/cachefile.py) was most of what
a cold `generate` spent on emission. The first process to ask prints every item of the library
once (an item it cannot print is left to fail where a shader asks for it) and writes the lines;
later processes read them. Only the library's own items are looked up here: a copy a pass made
(a resolved section, members dropped) is printed from its IR. The file is named by the code
cache's key, which covers the library and the generator's code, and by the target.
"""
import os
import pickle

from ..code.cachefile import library_items
from ..errors import ShaderGenError
from ..library import cache_dir, read_checked, write_checked


class PrintedLibrary:
    """`lines(item)`: a library item's lines as `print_item` writes them; None for any other item."""
    __slots__ = ("place", "printed")

    def __init__(self, code, target: str, print_item):
        items = library_items(code.modules)
        self.place = {id(item): n for n, item in enumerate(items)}
        key = f"{code.key}\0{target}".encode()
        path = os.path.join(cache_dir(), f"printed-{target}-{code.key[:24]}.pickle")
        self.printed = _read(path, key)
        if self.printed is None or len(self.printed) != len(items):
            self.printed = tuple(_lines(print_item, item) for item in items)
            write_checked(path, pickle.dumps((key, self.printed), protocol=pickle.HIGHEST_PROTOCOL))

    def lines(self, item) -> tuple[str, ...] | None:
        n = self.place.get(id(item))
        return None if n is None else self.printed[n]


def _lines(print_item, item) -> tuple[str, ...] | None:
    try:
        return tuple(print_item(item))
    except ShaderGenError:
        return None


def _read(path: str, key: bytes) -> tuple | None:
    body = read_checked(path)
    try:
        stored_key, printed = pickle.loads(body) if body is not None else (None, None)
    except (pickle.UnpicklingError, EOFError, ValueError, TypeError):
        return None
    return printed if stored_key == key and isinstance(printed, tuple) else None
