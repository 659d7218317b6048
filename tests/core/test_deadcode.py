"""The dead-code step of C-like stages: which library items a stage keeps, with which comments."""
from shadergen.targets.deadcode import used_functions

from .conftest import kept_code

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
    assert "#ifndef ITERATIONS\n#define ITERATIONS 2\n#endif" in code
    assert "float twice" in code  # reached through repeated()


def test_used_identifiers_come_from_code_not_comments():
    _, used = used_functions(LIBRARY.split("\n"), "float a = twice(1.0); // u_unread")
    assert "twice" in used and "u_unread" not in used and "square" not in used
