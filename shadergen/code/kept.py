"""A memo of bounded size that keeps what it took: once full it takes no more (as the statement
memo, code/statements.py). One that let old entries go for new ones would, on a walk over more
materials than it holds (a library of a thousand, request after request), let every entry go
before it was asked for again, and pay for keeping each one for nothing."""


class Kept:
    """key -> value, at most `count` entries whose sizes (`keep`'s) add up to at most `size`."""
    __slots__ = ("entries", "count", "size", "used")

    def __init__(self, count: int, size: int):
        self.entries: dict = {}
        self.count, self.size, self.used = count, size, 0

    def get(self, key, default=None):
        return self.entries.get(key, default)

    def keep(self, key, value, size: int = 0) -> None:
        # (two threads may both add one past the bounds: a bound, not an invariant)
        if len(self.entries) < self.count and self.used + size <= self.size:
            self.entries[key] = value
            self.used += size

    def __len__(self) -> int:
        return len(self.entries)
