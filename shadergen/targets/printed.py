"""Every library item as a target prints it, kept on disk beside the library's code cache.

A shader's library functions are the same text request after request, and in a new process
printing them (and reading their bodies from the code cache, code/cachefile.py) was most of what
a cold `generate` spent on emission. The first process to ask prints every item of the library
once (an item it cannot print is left to fail where a shader asks for it) and writes the lines;
later processes read them. Only the library's own items are looked up here (its functions with
their sections resolved among them, code/library.py): a copy a pass made (members dropped) is
printed from its IR. The file is named by the code cache's key, which covers the library and the
generator's code, and by the target.
"""
import os

from ..code import pickling
from ..errors import ShaderGenError
from ..library import cache_dir, read_checked, write_checked


class PrintedLibrary:
    """`lines(item)`: a library item's lines as `print_item` writes them; None for any other item.
    The lines of the library's functions with their sections resolved (code/library.py's Resolved
    copies) are pickled apart in the file and read the first time one is asked for."""
    __slots__ = ("code", "place", "printed", "copies_pickled", "copies")

    def __init__(self, code, target: str, print_item):
        self.code = code
        items, self.place = code.items()
        key = f"{code.key}\0{target}".encode()
        path = os.path.join(cache_dir(), f"printed-{target}-{code.key[:24]}.pickle")
        found = _read(path, key)
        if found is None or len(found[0]) != len(items):
            copies = code.read_resolutions().copies
            found = (tuple(_lines(print_item, item) for item in items),
                     pickling.dumps(tuple(_lines(print_item, item) for item in copies), protocol=pickling.PROTOCOL))
            write_checked(path, pickling.dumps((key, *found), protocol=pickling.PROTOCOL))
        self.printed, self.copies_pickled = found
        self.copies = None  # id(copy) -> its lines, read when first asked

    def lines(self, item) -> tuple[str, ...] | None:
        n = self.place.get(id(item))
        if n is not None:
            return self.printed[n]
        if self.code.resolved is None:
            return None  # (no stage asked for a resolution: `item` is none of them)
        if self.copies is None:
            lines = pickling.loads(self.copies_pickled)
            self.copies = {id(copy): text for copy, text in zip(self.code.resolved.copies, lines)}
        return self.copies.get(id(item))


def _lines(print_item, item) -> tuple[str, ...] | None:
    try:
        return tuple(print_item(item))
    except ShaderGenError:
        return None


def _read(path: str, key: bytes) -> tuple | None:
    """(the library items' lines, the copies' lines pickled), or None."""
    body = read_checked(path)
    try:
        stored_key, printed, copies = pickling.loads(body) if body is not None else (None, None, None)
    except (pickling.UnpicklingError, EOFError, ValueError, TypeError):
        return None
    return (printed, copies) if stored_key == key and isinstance(printed, tuple) and isinstance(copies, bytes) else None
