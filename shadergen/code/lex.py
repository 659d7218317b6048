"""Tokens of the GLSL subset the node libraries are written in (code/parse.py reads them).

A token is (kind, text, line, column, blank): kind "id", "num", "op", "pp" (a preprocessor line,
without a comment after it), "placeholder" (`{{name}}` of an inline expression, text the name),
"comment" (on a line of its own), "trailing" (after code on its line) or "eof"; `blank` tells
that a blank line separates it from the token before it (a comment block above a blank line
documents the file, not the definition below). Comments' text is without `//` or `/* */`, one
token per line of a block comment. Errors name file:line:col.
"""
import re
from collections import namedtuple

from ..errors import source_error

__all__ = ["Token", "tokenize"]


# (as the module's doc says; collections' namedtuple: typing's NamedTuple costs a cold process the
# import of typing)
Token = namedtuple("Token", "kind text line column blank")


# The pattern's source, compiled (and kept in re's cache) where text is tokenized: a process that
# reads its library from the cache tokenizes nothing, and compiling it was 1.6 ms of its start.
TOKEN = r"""(?xs)
    (?P<line_comment>//[^\n]*)
  | (?P<block_comment>/\*.*?\*/)
  | (?P<ws>\s+)
  | (?P<pp>\#(?:[^\n/]|/(?![/*]))*)
  | (?P<placeholder>\{\{\s*\w+\s*\}\})
  | (?P<num>0[xX][0-9a-fA-F]+[uU]?|(?:\d+\.\d*|\.\d+|\d+)(?:[eE][+-]?\d+)?[fFuU]?)
  | (?P<id>[A-Za-z_]\w*)
  | (?P<op><<=|>>=|\+\+|--|\+=|-=|\*=|/=|%=|&=|\|=|\^=|==|!=|<=|>=|&&|\|\||<<|>>|[-+*/%<>=!~&|^?:;,.(){}\[\]])
"""


def tokenize(path: str, text: str, placeholders: bool = False, line: int = 1, column: int = 1) -> list[Token]:
    """The tokens of `text` (starting at `line`, `column` of `path`), ending with an "eof" token.
    `placeholders`: `{{name}}` is a token (inline expressions); elsewhere it is an error."""
    out: list[Token] = []
    pos, line_start = 0, 1 - column  # line_start: the offset of the current line's first character
    code_on_line = False  # a token other than a comment began on this line
    blank = False
    match = re.compile(TOKEN).match
    while pos < len(text):
        m = match(text, pos)
        kind = m.lastgroup if m else None
        if kind is None or (kind == "placeholder" and not placeholders):
            raise source_error(path, line, pos - line_start + 1, f"unexpected character {text[pos]!r}")
        value = m.group()
        col = pos - line_start + 1
        if kind == "ws":
            newlines = value.count("\n")
            if newlines:
                blank = blank or newlines > 1
                line += newlines
                line_start = pos + value.rindex("\n") + 1
                code_on_line = False
        elif kind in ("line_comment", "block_comment"):
            comment_kind = "trailing" if code_on_line else "comment"
            body = value[2:-2] if kind == "block_comment" else value[2:]
            for k, part in enumerate(body.split("\n")):
                part = part.strip()
                if kind == "block_comment":
                    part = part.lstrip("*").strip()
                if part:
                    out.append(Token(comment_kind, part, line + k, col if k == 0 else 1, blank))
                    blank = False
            if "\n" in value:
                line += value.count("\n")
                line_start = pos + value.rindex("\n") + 1
        else:
            if kind == "placeholder":
                value = value[2:-2].strip()
            elif kind == "pp":
                value = value.rstrip()
            out.append(Token(kind, value, line, col, blank))
            blank = False
            code_on_line = True
        pos = m.end()
    out.append(Token("eof", "", line, pos - line_start + 1, blank))
    return out
