"""`shadergen` command line: each subcommand lives in its own module, imported only when used
(a cold `shadergen generate` must not pay for the renderer or the web stack)."""
import argparse
import importlib
import sys

# subcommand -> module with add_arguments(parser) and run(args) -> exit code
SUBCOMMANDS = {
    "generate": ("shadergen.cli_generate", "generate shaders and variable listings (JSON Lines)"),
    "render": ("shadergen.render.cli", "render a material thumbnail on headless EGL"),
    "serve": ("service.cli", "run the HTTP service"),
    "worker": ("service.worker_cli", "run a render worker for the Redis job back end"),
}


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    parser = argparse.ArgumentParser(prog="shadergen", description=__doc__.split("\n")[0])
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    chosen = argv[0] if argv and argv[0] in SUBCOMMANDS else None
    for name, (module, help_text) in SUBCOMMANDS.items():
        p = sub.add_parser(name, help=help_text)
        if name == chosen:
            importlib.import_module(module).add_arguments(p)
    args = parser.parse_args(argv)
    return importlib.import_module(SUBCOMMANDS[args.command][0]).run(args)


if __name__ == "__main__":
    sys.exit(main())
