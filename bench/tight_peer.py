"""Bench-only peer (issue 22 point 5): "a tight C++ loop of the same arithmetic" for the rigid chain.

bench/tight_rigid.cpp is the numba peer's loop (bench/numba_peer.py) written once in C++; ``kernel()`` compiles it
with the system C++ compiler (``CXX``, default ``c++``; -O3 -march=native -ffp-contract=off, so no fused
multiply-add changes the arithmetic) into build/bench-tight/ and returns a NumPy-friendly callable, or None when no
compiler is there. It is not used by the product; the bench checks its feedback equals servobench's on every tick.
"""

from __future__ import annotations

import ctypes
import hashlib
import os
import pathlib
import shutil
import subprocess

import numpy as np

HERE = pathlib.Path(__file__).resolve().parent
SRC = HERE / "tight_rigid.cpp"
FLAGS = ["-O3", "-march=native", "-ffp-contract=off", "-fPIC", "-shared"]


def compiler_version() -> str:
    """The C++ compiler's first version line, or "not installed"."""
    cxx = shutil.which(os.environ.get("CXX", "c++"))
    if cxx is None:
        return "not installed"
    return subprocess.run([cxx, "--version"], capture_output=True, text=True).stdout.splitlines()[0]


def kernel():
    """rigid_chain(consts, pos, vel, acc, out) -> None (float64 arrays; out has len(pos)), or None without a
    compiler. Compiled once per source/flags hash (compile time is not timed by the benches)."""
    cxx = shutil.which(os.environ.get("CXX", "c++"))
    if cxx is None:
        return None
    tag = hashlib.sha1(SRC.read_bytes() + " ".join(FLAGS).encode()).hexdigest()[:12]
    out_dir = HERE.parent / "build" / "bench-tight"
    lib = out_dir / f"tight_rigid_{tag}.so"
    if not lib.exists():
        out_dir.mkdir(parents=True, exist_ok=True)
        subprocess.run([cxx, *FLAGS, str(SRC), "-o", str(lib)], check=True)
    dll = ctypes.CDLL(str(lib))
    fn = dll.rigid_chain
    dp = ctypes.POINTER(ctypes.c_double)
    fn.argtypes = [dp, dp, dp, dp, dp, ctypes.c_long]
    fn.restype = None

    def rigid_chain(consts, pos, vel, acc, out):
        arrs = [np.ascontiguousarray(a, dtype=np.float64) for a in (consts, pos, vel, acc)]
        assert out.dtype == np.float64 and out.flags.c_contiguous and len(out) == len(arrs[1])
        fn(*(a.ctypes.data_as(dp) for a in arrs), out.ctypes.data_as(dp), len(arrs[1]))

    return rigid_chain
