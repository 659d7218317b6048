"""What the printers of typed IR (glsl/printer.py, wgsl/printer.py) share: the line width, how a
long argument list wraps, how comments are written, and the few type facts printing needs.

Expressions are printed by a `render(expr, column, indent)` of the printer: `column` None prints on
one line; a column is where the text starts (in a statement indented `indent` columns), so an
argument list that would run past WIDTH wraps, its arguments aligned after the `(` as the library
sources align them.
"""

from ..code import ir

WIDTH = 110
# An argument list opening past this column is not aligned after its `(`, where each line would
# hold a few arguments only: a long one (an array's values) starts on a line of its own, one indent
# deeper than its statement; a short one stays on its line, which runs past WIDTH. A list of more
# than LONG literals (a table) that would wrap does so whenever its `(` is not near its statement's
# start.
HANGING = 70
LONG = 8
INDENT = "    "


def comment_lines(comment) -> list[str]:
    """`//` lines of a comment: one string, or a sequence of lines (without their `//`)."""
    lines = [comment] if isinstance(comment, str) else list(comment)
    return ["//" + line if not line or line[0] == " " else "// " + line for line in lines]


def with_trailing(line: str, comment) -> str:
    """`line` with the comment that followed its code in the source."""
    return line if not comment else line + "  " + " ".join(comment_lines(comment))


def end_column(start: int, text: str) -> int:
    """The column after `text` printed from column `start`."""
    newline = text.rfind("\n")
    return start + len(text) if newline < 0 else len(text) - newline - 1


def binary_text(render_left, op: str, render_right, column, indent: int) -> str:
    """`left op right` for an expression starting at `column` (`render_left(column, indent)` and
    `render_right` render the operands, parenthesised as they need). Too long for its line, it
    breaks after the operator where both operands then fit, the right one aligned with the
    expression's start (not too far right); else its operands wrap inside."""
    if column is None:
        return f"{render_left(None, indent)} {op} {render_right(None, indent)}"
    left, right = render_left(None, indent), render_right(None, indent)
    if column + len(left) + len(op) + 2 + len(right) <= WIDTH:
        return f"{left} {op} {right}"
    if column <= HANGING and column + len(left) + len(op) + 1 <= WIDTH and column + len(right) <= WIDTH:
        return f"{left} {op}\n{' ' * column}{right}"
    left = render_left(column, indent)
    return f"{left} {op} {render_right(end_column(column, left) + len(op) + 2, indent)}"


def arguments(render, args, column: int, indent: int) -> str:
    """The arguments of a call whose `(` ends at `column`, in a statement indented `indent`
    columns: on the line while they fit, else on the next, aligned after the `(`."""
    if column > HANGING and len(args) <= LONG:
        return ", ".join([render(arg, None, indent) for arg in args])
    if column > HANGING or (len(args) > LONG and column > indent + 2 * len(INDENT)
                            and all(type(a) is ir.Literal for a in args)):
        # a long list (an array's values) on lines of their own, as full as they go
        column = indent + len(INDENT)
        out = "\n" + " " * column
    else:
        out = ""
    end = column
    for i, arg in enumerate(args):
        flat = render(arg, None, indent)
        tail = 1  # the `,` or `)` after it
        separator = "" if i == 0 else ", "
        if end + len(separator) + len(flat) + tail <= WIDTH:
            text = separator + flat
        elif i == 0:
            text = render(arg, end, indent)
        elif column + len(flat) + tail <= WIDTH:
            text = ",\n" + " " * column + flat
        else:
            text = ",\n" + " " * column + render(arg, column, indent)
        out += text
        end = end_column(end, text)
    return out
