"""The reach pass of a stage (shadergen/code/passes/reach.py): which library items a stage keeps,
with which comments."""
from shadergen.code.facts import collect
from shadergen.code.passes import reach

from .conftest import checked_code, kept_code

LIBRARY = """// Helpers shared by the whole file: a header, separated from what follows by a blank line.

// --- Section ---

// Twice x: attached to the function below.
float twice(float x)
{
    return 2.0 * x;
}

// The square: nobody calls it, though a comment mentions twice().
float square(float x)
{
    return x * x;
}

#ifndef ITERATIONS
#define ITERATIONS 2
#endif

float repeated(float x)
{
    float y = x;
    for (int i = 0; i < ITERATIONS; i++)
        y = twice(y);
    return y;
}
"""


def kept(roots: str) -> str:
    return kept_code(LIBRARY, roots)


def test_detached_comment_blocks_are_left_out_and_attached_ones_kept():
    code = kept("float a = twice(1.0);")
    assert "// Twice x: attached to the function below.\nfloat twice(float x)" in code
    assert "Helpers shared" not in code and "--- Section ---" not in code


def test_a_name_in_a_comment_keeps_nothing_alive():
    code = kept("float a = twice(1.0); // not square(), see the comment")
    assert "float twice" in code and "square" not in code


def test_a_default_definition_is_kept_whole_only_where_its_name_is_used():
    assert "ITERATIONS" not in kept("float a = twice(1.0);")
    code = kept("float a = repeated(1.0);")
    lines = code.split("\n")
    guard = lines.index("#ifndef ITERATIONS")
    assert lines[guard + 1].endswith("ITERATIONS = 2;") and lines[guard + 2] == "#endif"  # its guard kept with it
    assert guard < lines.index("float repeated(float x)")  # a definition before its use
    assert "float twice" in code  # reached through repeated()


def test_used_identifiers_come_from_code_not_comments():
    items, main = checked_code(LIBRARY, "float a = twice(1.0); // u_unread")
    reached, left_out = reach.run(items, collect([main]))
    assert reached.functions == ("twice(float)",) and "u_unread" not in reached.names
    assert left_out == 3  # square, repeated and ITERATIONS
