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

    def _get_help_string(self, action):
        text = action.help or ""
        if action.default in (None, False, [], argparse.SUPPRESS) or "default" in text or not action.option_strings:
            return text
        return f"{text} (default: %(default)s)"


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
