"""`shadergen` command line: each subcommand lives in its own module, imported only when used
(a cold `shadergen generate` must not pay for the renderer or the web stack)."""
import argparse
import gc
import importlib
import os
import sys

# Young objects a `generate` process allocates between collections (Python's default is 700): a
# cold process builds tens of thousands of short-lived nodes, inputs and elements, and the
# collector rescanned them every few hundred; garbage cycles are still collected, less often.
GENERATE_GC_THRESHOLD = 20_000

# subcommand -> module with add_arguments(parser) and run(args) -> exit code (and EXAMPLES, shown by --help)
SUBCOMMANDS = {
    "generate": ("shadergen.cli_generate", "generate shaders and variable listings (JSON Lines)"),
    "render": ("shadergen.render.cli", "render a material thumbnail on headless EGL"),
    "serve": ("service.cli", "run the HTTP service"),
    "worker": ("service.worker_cli", "run a render worker for the Redis job back end"),
}
EXAMPLES = """examples:
  shadergen generate examples/marble_checker.mtlx
  shadergen render examples/marble_checker.mtlx -o marble.png
  shadergen serve --workers 2
run `shadergen COMMAND --help` for the options of each command."""


class HelpFormatter(argparse.RawDescriptionHelpFormatter):
    """Every option's help ends with its default (when it has one worth saying); examples keep
    their line breaks."""

    def __init__(self, prog, indent_increment=2, max_help_position=24, width=None):
        # argparse makes a formatter for every add_argument (to check its metavar), sized to the
        # terminal by shutil, whose import (with the compression modules it brings) costs a cold
        # `generate` more than argparse itself: the width is read here instead, as shutil does.
        super().__init__(prog, indent_increment, max_help_position, width or terminal_columns() - 2)

    def _get_help_string(self, action):
        text = action.help or ""
        if action.default in (None, False, [], argparse.SUPPRESS) or "default" in text or not action.option_strings:
            return text
        return f"{text} (default: %(default)s)"


def terminal_columns() -> int:
    """$COLUMNS, else the width of the terminal on stdout, else 80 (shutil.get_terminal_size's rule)."""
    try:
        columns = int(os.environ.get("COLUMNS", 0))
    except ValueError:
        columns = 0
    if columns > 0:
        return columns
    try:
        return os.get_terminal_size(sys.__stdout__.fileno()).columns or 80
    except (AttributeError, ValueError, OSError):
        return 80


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    parser = argparse.ArgumentParser(prog="shadergen", description=__doc__.split("\n")[0], epilog=EXAMPLES,
                                     formatter_class=HelpFormatter)
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    chosen = argv[0] if argv and argv[0] in SUBCOMMANDS else None
    for name, (module, help_text) in SUBCOMMANDS.items():
        p = sub.add_parser(name, help=help_text, description=help_text, formatter_class=HelpFormatter)
        if name == chosen:
            loaded = importlib.import_module(module)
            loaded.add_arguments(p)
            p.epilog = getattr(loaded, "EXAMPLES", None)
    args = parser.parse_args(argv)
    return importlib.import_module(SUBCOMMANDS[args.command][0]).run(args)


def entry() -> None:
    """The console script (and `python -m shadergen.cli`). `generate` collects garbage less often
    (GENERATE_GC_THRESHOLD), and after it the interpreter is left without being torn down: freeing
    the loaded library object by object would cost a cold process a fifth of its time, and generate
    leaves nothing to close (its files are closed as they are written; its output is flushed here).
    Other commands run servers and workers: they exit the ordinary way."""
    argv = sys.argv[1:]
    if argv[:1] == ["generate"]:
        gc.set_threshold(GENERATE_GC_THRESHOLD)
    code = main(argv)
    if argv[:1] == ["generate"]:
        sys.stdout.flush()
        sys.stderr.flush()
        os._exit(code)
    sys.exit(code)


if __name__ == "__main__":
    entry()
