"""`servobench demo`: the built-in demonstration."""

from __future__ import annotations


# ----------------------------------------------------------------------------------------------------------------
# demo
# ----------------------------------------------------------------------------------------------------------------
def cmd_demo(args) -> int:
    from ..demo import main as demo_main

    return demo_main(["--law", args.law, "--out", args.out])
