"""The bytes of the library code's cache (code/library.py), written so that a process reads only
the library code it uses.

Most of the library's IR is in its functions' parameters, bodies and facts and a few large
constants' values (the albedo and DFG tables), and a request uses a part of them. Each of those
fields is pickled apart, as bytes inside the file, and unpickled the first time it is read
(ir.Item's `pending`); the rest (every item's name, key and type, the modules, the symbol table) is
read at once. A function's facts are apart from its body: the passes read the facts of every
function they keep or drop, a request prints only some bodies (targets/printed.py holds the text of
the others); its parameters are apart from both, read where a call is resolved to it or it is
printed (most of a cold process's unpickling was the parameters of functions it never called). A
reference from a deferred field to a library item (a callee) is written as the item's place among
the library's items, and one from a body to a statement its facts name (a member store) as its place
among those; both are read back as the same objects. A forwarding function's facts hold its call's
arguments: it is read whole, at once.
"""
import io
import _thread

from . import ir, pickling
from .check import flat_items

# the fields of an item kept in the file until asked for, each read apart, except a body: its
# member stores are its facts', read first (NEEDS)
DEFERRED = {ir.Function: ("params", "facts", "body"), ir.Constant: ("value",)}
NEEDS = {"body": "facts"}


class _Items:
    """Stands, in the state's pickle, for the list of the library's items (filled once it is read)."""


_ITEMS = _Items()
_RESTORING = _thread.allocate_lock()  # two threads asking for one item's fields read them once (threading's
# import costs a cold process more than the lock)


def library_items(modules: dict) -> list:
    """Every top-level item of the modules, in module and source order: what a reference is a place in."""
    return [item for module in modules.values() for item in flat_items(module.items) if isinstance(item, ir.Item)]


def copies_in(items: list, resolutions: dict) -> list:
    """The items of the library's functions with their sections resolved (code/library.py's
    resolutions) that are not among `items` (library_items), in order: their places follow."""
    known = {id(item) for item in items}
    out = []
    for resolved, _ in resolutions.values():
        for item in flat_items(resolved):
            if isinstance(item, ir.Item) and id(item) not in known:
                known.add(id(item))
                out.append(item)
    return out


def dumps(state, items: list) -> bytes:
    """`state` pickled, the DEFERRED fields of `items` (library_items) apart."""
    out = io.BytesIO()
    _StateWriter(out, {id(item): n for n, item in enumerate(items)}).dump(state)
    return out.getvalue()


def loads(data: bytes, items_of) -> object:
    """What `dumps` wrote; `items_of(state)` gives its library_items (to resolve references by place)."""
    items: list = []
    reader = pickling.Unpickler(io.BytesIO(data))
    reader.persistent_load = lambda pid: items if pid == "items" else _unknown(pid)
    state = reader.load()
    items.extend(items_of(state))
    return state


def _unknown(pid):
    raise pickling.UnpicklingError(f"unknown persistent id {pid!r}")


class _StateWriter(pickling.Pickler):
    def __init__(self, file, index: dict[int, int]):
        super().__init__(file, protocol=pickling.PROTOCOL)
        self.index = index

    def reducer_override(self, obj):
        fields = DEFERRED.get(obj.__class__)
        if fields is None or id(obj) not in self.index or obj.facts is None or obj.facts.forwards is not None:
            return NotImplemented
        state = obj.__getstate__()[1]
        stores = {id(store.statement): n for n, store in enumerate(obj.facts.stores)}
        blobs = {}
        for name in fields:
            out = io.BytesIO()
            _FieldWriter(out, self.index, stores if name == "body" else {}).dump(state.pop(name))
            blobs[name] = out.getvalue()
        return _deferred, (obj.__class__, state, blobs, _ITEMS)

    def persistent_id(self, obj):
        return "items" if obj is _ITEMS else None


class _FieldWriter(pickling.Pickler):
    """A deferred field: a library item in it written as its place (an int), a statement of the
    item's stores as its place among them (a 1-tuple)."""

    def __init__(self, file, index: dict[int, int], stores: dict[int, int]):
        super().__init__(file, protocol=pickling.PROTOCOL)
        self.index, self.stores = index, stores

    def persistent_id(self, obj):
        if isinstance(obj, ir.Item):
            return self.index.get(id(obj))
        store = self.stores.get(id(obj))
        return None if store is None else (store,)


def _deferred(cls, state: dict, blobs: dict[str, bytes], items: list):
    """An item as the state's pickle reads it: its DEFERRED fields still in `blobs`."""
    item = object.__new__(cls)
    for name, value in state.items():
        setattr(item, name, value)
    item.pending = _Pending(blobs, items)
    return item


class Apart:
    """A table whose values are pickled apart in the file, each unpickled when first asked for
    (the library's inline templates: a request instantiates a few of its hundreds). Its values
    hold no library item."""
    __slots__ = ("keys", "values", "blobs")

    def __init__(self, values: dict, blobs: dict[str, bytes] | None = None):
        self.keys = tuple(values) + tuple(blobs or ())  # in the order written
        self.values = dict(values)  # read, or made in this process
        self.blobs = dict(blobs or {})  # key -> its value's pickle, still unread

    def get(self, key):
        found = self.values.get(key)
        if found is None and key in self.blobs:
            with _RESTORING:
                blob = self.blobs.pop(key, None)
                if blob is not None:
                    self.values[key] = pickling.loads(blob)
            found = self.values.get(key)
        return found

    def __iter__(self):
        return iter(self.keys)

    def __reduce__(self):
        blobs = {key: self.blobs[key] if key in self.blobs else pickling.dumps(self.values[key], pickling.PROTOCOL)
                 for key in self.keys}
        return Apart, ({}, blobs)


class _Pending:
    __slots__ = ("blobs", "items")

    def __init__(self, blobs: dict[str, bytes], items: list):
        self.blobs, self.items = dict(blobs), items

    def restore(self, item, name: str) -> None:
        """Reads `name` (and the field it NEEDS) into `item`, if still unread."""
        with _RESTORING:
            if name not in self.blobs:
                return  # not deferred, or another thread read it
            for field in (NEEDS.get(name), name):
                blob = self.blobs.pop(field, None)
                if blob is not None:
                    stores = item.facts.stores if field == "body" else ()
                    reader = pickling.Unpickler(io.BytesIO(blob))
                    reader.persistent_load = lambda pid: self.items[pid] if pid.__class__ is int else stores[pid[0]].statement
                    setattr(item, field, reader.load())
