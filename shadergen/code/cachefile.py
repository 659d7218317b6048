"""The bytes of the library code's cache (code/library.py), written so that a process reads only
the library code it uses.

Most of the library's IR is in its functions' bodies and a few large constants' values (the
albedo and DFG tables), and a request reaches a small part of them. Each of those fields (and
the facts read from them, which point into the body) is pickled apart, as bytes inside the
file, and unpickled the first time one of them is read (ir.Item's `pending`); the rest (every
item's name, signature and type, the modules, the symbol table) is read at once. A reference
from a deferred field to a library item (a call's callee, a fact's callee) is written as the
item's place among the library's items, and read back as that same item: the checker's callees
stay the library's own Functions.
"""
import io
import pickle
import threading

from . import ir
from .check import flat_items

# the fields of an item kept in the file until asked for
DEFERRED = {ir.Function: ("body", "facts"), ir.Constant: ("value", "facts")}


class _Items:
    """Stands, in the state's pickle, for the list of the library's items (filled once it is read)."""


_ITEMS = _Items()
_RESTORING = threading.Lock()  # two threads asking for one item's fields read them once


def library_items(modules: dict) -> list:
    """Every top-level item of the modules, in module and source order: what a reference is a place in."""
    return [item for module in modules.values() for item in flat_items(module.items) if isinstance(item, ir.Item)]


def dumps(state, modules: dict) -> bytes:
    """`state` pickled, the DEFERRED fields of the items of `modules` apart."""
    out = io.BytesIO()
    _StateWriter(out, {id(item): n for n, item in enumerate(library_items(modules))}).dump(state)
    return out.getvalue()


def loads(data: bytes, modules_of) -> object:
    """What `dumps` wrote; `modules_of(state)` gives its modules (to resolve references by place)."""
    items: list = []
    reader = pickle.Unpickler(io.BytesIO(data))
    reader.persistent_load = lambda pid: items if pid == "items" else _unknown(pid)
    state = reader.load()
    items.extend(library_items(modules_of(state)))
    return state


def _unknown(pid):
    raise pickle.UnpicklingError(f"unknown persistent id {pid!r}")


class _StateWriter(pickle.Pickler):
    def __init__(self, file, index: dict[int, int]):
        super().__init__(file, protocol=pickle.HIGHEST_PROTOCOL)
        self.index = index

    def reducer_override(self, obj):
        fields = DEFERRED.get(obj.__class__)
        if fields is None or id(obj) not in self.index:
            return NotImplemented
        state = obj.__getstate__()[1]
        deferred = {name: state.pop(name) for name in fields}
        out = io.BytesIO()
        _FieldsWriter(out, self.index).dump(deferred)
        return _deferred, (obj.__class__, state, out.getvalue(), _ITEMS)

    def persistent_id(self, obj):
        return "items" if obj is _ITEMS else None


class _FieldsWriter(pickle.Pickler):
    """Deferred fields, a library item among them written as its place."""

    def __init__(self, file, index: dict[int, int]):
        super().__init__(file, protocol=pickle.HIGHEST_PROTOCOL)
        self.index = index

    def persistent_id(self, obj):
        return self.index.get(id(obj)) if isinstance(obj, ir.Item) else None


def _deferred(cls, state: dict, blob: bytes, items: list):
    """An item as the state's pickle reads it: its DEFERRED fields still in `blob`."""
    item = object.__new__(cls)
    for name, value in state.items():
        setattr(item, name, value)
    item.pending = _Pending(blob, items)
    return item


class _Pending:
    __slots__ = ("blob", "items")

    def __init__(self, blob: bytes, items: list):
        self.blob, self.items = blob, items

    def restore(self, item) -> None:
        with _RESTORING:
            if item.pending is not self:
                return  # another thread read them
            reader = pickle.Unpickler(io.BytesIO(self.blob))
            reader.persistent_load = self.items.__getitem__
            for name, value in reader.load().items():
                setattr(item, name, value)
            item.pending = None
