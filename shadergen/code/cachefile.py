"""The bytes of the library code's cache (code/library.py), written so that a process reads only
the library code it uses.

Most of the library's IR is in its functions' parameters, bodies and facts and a few large
constants' values (the albedo and DFG tables), and a request uses a part of them. Each of those
fields is pickled apart, after the rest in the file, and unpickled the first time it is read
(ir.Item's `pending`); the rest (every item's name, key and type, the modules, the symbol table) is
read at once. A function's facts are apart from its body: the passes read the facts of every
function they keep or drop, a request prints only some bodies (targets/printed.py holds the text of
the others); its parameters are apart from both, read where a call is resolved to it or it is
printed (most of a cold process's unpickling was the parameters of functions it never called). A
reference from a deferred field to a library item (a callee) is written as the item's place among
the library's items, and one from a body to a statement its facts name (a member store) as its place
among those; both are read back as the same objects. A forwarding function's facts hold its call's
arguments: it is read whole, at once.

The file is a line with the CRC-32 and the length of the state's pickle, that pickle, then the
deferred fields' pickles one after another, each named in the state by its offset, length and
CRC-32. A process reads and checks the state's pickle when it loads the file, reads the area
when it first needs a field, and checks each field when it first reads it (`Blobs`), not the
megabyte of fields it never reads (checking and copying them out of the pickle was a third of a
cold process's reading of the cache). A field found damaged has the file built and written
again (`rebuild`: its bytes are the same, the state being built alike in any process), and it
and every later field are read from that.
"""
import io
import zlib
import _thread

from . import ir, pickling
from .check import flat_items

# the fields of an item kept in the file until asked for, each read apart, except a body: its
# member stores are its facts', read first (NEEDS)
DEFERRED = {ir.Function: ("params", "facts", "body"), ir.Constant: ("value",)}
NEEDS = {"body": "facts"}


class _Items:
    """Stands, in the state's pickle, for the list of the library's items (filled once it is read)."""


class _Area:
    """Stands, in the state's pickle, for the file's deferred fields (a Blobs once it is read)."""


_ITEMS, _AREA = _Items(), _Area()
# two threads asking for one item's fields read them once (threading's import costs a cold process
# more than the lock); reentrant: rebuilding a damaged file may read other items' fields
_RESTORING = _thread.RLock()
_HEADER = len(b"%08x %08x\n" % (0, 0))


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
    """The file: `state` pickled, the DEFERRED fields of `items` (library_items) apart."""
    out, area = io.BytesIO(), io.BytesIO()
    _StateWriter(out, {id(item): n for n, item in enumerate(items)}, area).dump(state)
    pickled = out.getvalue()
    return b"%08x %08x\n" % (zlib.crc32(pickled), len(pickled)) + pickled + area.getvalue()


def load(path: str, items_of, rebuild) -> object:
    """What `dumps` wrote into the file `path` (its area read when a field is first asked for);
    `items_of(state)` gives its library_items (to resolve references by place); `rebuild()` writes
    the file again and gives its bytes, where a field is found damaged. Raises OSError where the
    file cannot be read, ValueError where the state's pickle is damaged (and the pickle's errors)."""
    with open(path, "rb") as f:
        header = f.read(_HEADER)
        size = _state_size(header)
        pickled = f.read(size)
    if len(pickled) != size or zlib.crc32(pickled) != int(header[:8], 16):
        raise ValueError("damaged")
    items: list = []
    area = Blobs(path, _HEADER + size, rebuild)
    reader = pickling.Unpickler(io.BytesIO(pickled))
    reader.persistent_load = lambda pid: items if pid == "items" else area if pid == "area" else _unknown(pid)
    state = reader.load()
    items.extend(items_of(state))
    return state


def _state_size(header: bytes) -> int:
    """The length of the state's pickle, as a file's header line gives it."""
    if len(header) < _HEADER or header[8:9] != b" " or header[_HEADER - 1:_HEADER] != b"\n":
        raise ValueError("not a cache file")
    return int(header[9:_HEADER - 1], 16)


def _unknown(pid):
    raise pickling.UnpicklingError(f"unknown persistent id {pid!r}")


class Blobs:
    """The deferred fields of a file, each checked when read (see the module's doc). The area is
    read from the file when a first field is asked for: a request whose nodes are all inline
    expressions reads none (the file is named by its content's key, so whoever wrote it again in
    between wrote the same bytes; a damaged one fails the fields' checks)."""
    __slots__ = ("path", "data", "start", "rebuild")

    def __init__(self, path: str, start: int, rebuild):
        self.path, self.start, self.rebuild = path, start, rebuild
        self.data: bytes | None = None  # the area (from `start`), once read

    def read(self, location: tuple[int, int, int]) -> memoryview:
        """A field's pickle, by its (offset, length, CRC-32) in the area."""
        blob = self._blob(location)
        if blob is None:  # damaged: the file built and written again, and read from then on
            data = self.rebuild()
            self.data, self.start = data, _HEADER + _state_size(data)
            blob = self._blob(location)
            if blob is None:
                raise pickling.UnpicklingError("the library's code cache was built again unlike before")
        return blob

    def _blob(self, location) -> memoryview | None:
        if self.data is None:
            try:
                with open(self.path, "rb") as f:
                    f.seek(self.start)
                    self.data, self.start = f.read(), 0
            except OSError:  # gone since: as damaged
                return None
        offset, length, checksum = location
        start = self.start + offset
        blob = memoryview(self.data)[start:start + length]
        return blob if len(blob) == length and zlib.crc32(blob) == checksum else None


def _placed(area, blob: bytes) -> tuple[int, int, int]:
    """`blob` appended to the `area` being written: its (offset, length, CRC-32) there."""
    return area.tell(), area.write(blob), zlib.crc32(blob)


class _StateWriter(pickling.Pickler):
    def __init__(self, file, index: dict[int, int], area):
        super().__init__(file, protocol=pickling.PROTOCOL)
        self.index, self.area = index, area

    def reducer_override(self, obj):
        if obj.__class__ is Apart:
            return Apart, ({}, {key: _placed(self.area, obj.pickled(key)) for key in obj.keys}, _AREA)
        fields = DEFERRED.get(obj.__class__)
        if fields is None or id(obj) not in self.index or obj.facts is None or obj.facts.forwards is not None:
            return NotImplemented
        state = obj.__getstate__()[1]
        stores = {id(store.statement): n for n, store in enumerate(obj.facts.stores)}
        locations = {}
        for name in fields:
            out = io.BytesIO()
            _FieldWriter(out, self.index, stores if name == "body" else {}).dump(state.pop(name))
            locations[name] = _placed(self.area, out.getvalue())
        return _deferred, (obj.__class__, state, locations, _ITEMS, _AREA)

    def persistent_id(self, obj):
        return "items" if obj is _ITEMS else "area" if obj is _AREA else None


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


def _deferred(cls, state: dict, locations: dict[str, tuple], items: list, area: Blobs):
    """An item as the state's pickle reads it: its DEFERRED fields still in the `area`."""
    item = object.__new__(cls)
    for name, value in state.items():
        setattr(item, name, value)
    item.pending = _Pending(locations, items, area)
    return item


class Apart:
    """A table whose values are pickled apart in the file, each unpickled when first asked for
    (the library's inline templates: a request instantiates a few of its hundreds). Its values
    hold no library item."""
    __slots__ = ("keys", "values", "locations", "area")

    def __init__(self, values: dict, locations: dict[str, tuple] | None = None, area: Blobs | None = None):
        self.keys = tuple(values) + tuple(locations or ())  # in the order written
        self.values = dict(values)  # read, or made in this process
        self.locations = dict(locations or {})  # key -> where its value's pickle is in the `area`, still unread
        self.area = area

    def get(self, key):
        found = self.values.get(key)
        if found is None and key in self.locations:
            with _RESTORING:
                location = self.locations.pop(key, None)
                if location is not None:
                    self.values[key] = pickling.loads(self.area.read(location))
            found = self.values.get(key)
        return found

    def pickled(self, key) -> bytes:
        """A value's pickle (as the file holds it, if still unread)."""
        if key in self.locations:
            return bytes(self.area.read(self.locations[key]))
        return pickling.dumps(self.values[key], pickling.PROTOCOL)

    def __iter__(self):
        return iter(self.keys)


class _Pending:
    __slots__ = ("locations", "items", "area")

    def __init__(self, locations: dict[str, tuple], items: list, area: Blobs):
        self.locations, self.items, self.area = locations, items, area  # (its own: unpickled for it)

    def restore(self, item, name: str) -> None:
        """Reads `name` (and the field it NEEDS) into `item`, if still unread."""
        with _RESTORING:
            if name not in self.locations:
                return  # not deferred, or another thread read it
            for field in (NEEDS.get(name), name):
                location = self.locations.get(field)
                if location is not None:
                    stores = item.facts.stores if field == "body" else ()
                    reader = pickling.Unpickler(io.BytesIO(self.area.read(location)))
                    reader.persistent_load = lambda pid: self.items[pid] if pid.__class__ is int else stores[pid[0]].statement
                    setattr(item, field, reader.load())
                    del self.locations[field]
