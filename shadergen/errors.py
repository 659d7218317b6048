"""One error type that crosses every layer: a code, a message, and where in the document it happened."""


class ShaderGenError(Exception):
    """A failure a user can act on. `code` is one of the contract's error codes
    (invalid_document, unknown_node, type_mismatch, cycle, unsupported_target, ...);
    `where` is the element path (or line) it concerns."""

    def __init__(self, code: str, message: str, where: str | None = None):
        super().__init__(message)
        self.code = code
        self.message = message
        self.where = where

    def to_dict(self) -> dict:
        return {"code": self.code, "message": self.message, "where": self.where}

    def __str__(self) -> str:
        return f"{self.code}: {self.message}" + (f" (at {self.where})" if self.where else "")


def source_error(path: str, line: int, column: int, what: str) -> ShaderGenError:
    """An error in a library's shader source, at `path`:`line`:`column` (the code IR's parser and
    checker raise it; here, so that a process that reads its library from the cache and only
    checks does not import the parser's lexer)."""
    return ShaderGenError("invalid_source", f"{path}:{line}:{column}: {what}", path)
