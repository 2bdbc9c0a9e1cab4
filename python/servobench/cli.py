"""The `servobench` command line. Sub-commands: demo."""

from __future__ import annotations

import sys


def main(argv=None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    commands = {"demo": "simulate a point-to-point move, print its metrics, write the response plot"}
    if not argv or argv[0] in ("-h", "--help"):
        print("usage: servobench <command> [options]\n\ncommands:")
        for name, text in commands.items():
            print(f"  {name:10s} {text}")
        return 0
    cmd, rest = argv[0], argv[1:]
    if cmd == "demo":
        from .demo import main as demo_main

        return demo_main(rest)
    print(f"servobench: unknown command '{cmd}'; commands: {', '.join(commands)}", file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main())
