"""Issue 21.2: hypothesis fuzzing of every public callable, each call in its own child process.

The callables: the public functions and classes of ``servobench`` and its modules, the methods of an Axis and a
Card, and the vendor functions of the four dialects (on an open card). For each, hypothesis draws a fixed number
of argument lists (positional and keyword, by the callable's parameter names) from a pool of awkward values: NaN,
+-inf, 1e308, 2^63, huge and tiny numbers, None, strings, lists, arrays. Every call runs in a fresh forked child
(multiprocessing.Pool, one task per child) with a time limit. Required:

* no crash and no hang: every child returns within the limit;
* no NaN in the output of a call whose inputs were all finite (an infinity may mean "none": no gain crossover,
  no current limit);
* at least 95 % of the rejections a ValueError/TypeError whose message names the parameter (or the owner's
  field) -- the other exceptions are counted and listed;
* a dialect (vendor) function never raises: it returns the vendor's error code.

Run time: about a minute on two cores (SERVOBENCH_FUZZ_EXAMPLES, default 4 argument lists per callable).
"""

from __future__ import annotations

import inspect
import math
import multiprocessing
import numbers
import os
import re
import types

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import servobench as sb
from servobench.dialects import aps, ge, gt, gts

# A documented refusal of a command in the object's present state (a card command refused with the vendor's cause,
# a fit that cannot identify, a path that cannot be built): not a bad value, counted apart from the rejections.
REFUSALS = (sb._core.CardCommandRefused, sb._core.MotionCommandRefused, sb.identify.IdentificationError,
            sb.paths.PathGeometryError)
EXAMPLES = int(os.environ.get("SERVOBENCH_FUZZ_EXAMPLES", "4"))
TIME_LIMIT_S = 30.0
SKIP_NAMES = re.compile(r"plot|save|write|to_csv|main|demo|wait_until|run_until|sleep|delay|show|bench|dump|"
                        r"load_axis|cli|^run_ms$|^run$|GT_Delay|wait")

# Awkward values: the edges of the number line and the wrong types.
AWKWARD = [math.nan, math.inf, -math.inf, 1e308, -1e308, 2**63, -(2**63), 2**31, 1e-300, 1e20, -1.0, 0, 1, 0.5,
           7, 100.0, 3e4, None, True, "x", [], [1.0, 2.0], np.zeros(3), np.array([math.nan, 1.0])]
VALUES = st.one_of(st.sampled_from(AWKWARD), st.floats(allow_nan=True, allow_infinity=True),
                   st.integers(min_value=-(2**64), max_value=2**64))


def _public_callables():
    """(label, owner kind, name) of everything fuzzed; resolved again in the child by label."""
    out = []
    modules = {"sb": sb, "sb.frequency": sb.frequency, "sb.design": sb.design, "sb.identify": sb.identify,
               "sb.motion": sb.motion, "sb.paths": sb.paths, "sb.pvt": sb.pvt, "sb.gearing": sb.gearing,
               "sb.homing": sb.homing, "sb.metrics": sb.metrics, "sb.trajectory": sb.trajectory,
               "sb.autotune": sb.autotune, "sb.axisfile": sb.axisfile}
    seen = set()
    for label, mod in modules.items():
        for name in sorted(dir(mod)):
            if name.startswith("_") or SKIP_NAMES.search(name):
                continue
            obj = getattr(mod, name)
            if isinstance(obj, types.ModuleType) or not callable(obj) or id(obj) in seen:
                continue
            if (isinstance(obj, type) and obj.__module__ == "servobench._core"
                    and not (getattr(obj.__init__, "__doc__", "") or "").startswith("__init__(")):
                continue  # a C++ result type Python cannot construct (no constructor bound)
            if getattr(obj, "__module__", "") and not str(getattr(obj, "__module__", "")).startswith("servobench"):
                continue
            seen.add(id(obj))
            out.append((label, name))
    for label, cls in (("axis", sb.Axis), ("card", sb.Card)):
        members = set(dir(cls)) | (set(dir(sb._core.Card)) if label == "card" else set())
        for name in sorted(members):
            if name.startswith("_") or SKIP_NAMES.search(name) or not callable(_member(label, name)):
                continue
            out.append((label, name))
    for label, mod in (("gt", gt), ("ge", ge), ("gts", gts), ("aps", aps)):
        for name in sorted(getattr(mod, {"gt": "GT_FUNCTIONS", "ge": "GE_FUNCTIONS", "gts": "GTS_FUNCTIONS",
                                         "aps": "APS_FUNCTIONS"}[label])):
            if name in ("GT_Open", "GT_Close", "APS_initial", "APS_close") or SKIP_NAMES.search(name):
                continue
            out.append((label, name))
    return out


def _member(label, name):
    return getattr(sb.Axis() if label == "axis" else sb.Card(4), name, None)


def _resolve(label, name):
    if label == "axis":
        return getattr(sb.Axis(law=sb.GtServoLaw(kp=38, kd=830)), name)
    if label == "card":
        return getattr(sb.Card(4), name)
    if label in ("gt", "ge", "gts", "aps"):
        mod = {"gt": gt, "ge": ge, "gts": gts, "aps": aps}[label]
        if label == "aps":
            aps.APS_initial(0)
        else:
            mod.GT_Open(sb.Card(4))
        return getattr(mod, name)
    return getattr(eval(label, {"sb": sb}), name)  # noqa: S307 -- the labels above


def _parameter_names(fn):
    try:
        return [p.name for p in inspect.signature(fn).parameters.values()
                if p.kind not in (p.VAR_POSITIONAL, p.VAR_KEYWORD) and p.name != "self"]
    except (TypeError, ValueError):
        doc = (getattr(fn, "__doc__", "") or "").splitlines()
        m = re.match(r"\w+\((.*)\)", doc[0] if doc else "")
        if not m:
            return []
        return [a.split(":")[0].strip() for a in m.group(1).split(",")
                if a.strip() and a.split(":")[0].strip() not in ("self", "*", "**kwargs", "*args")]


def _finite(x) -> bool:
    if isinstance(x, bool) or x is None or isinstance(x, str):
        return True
    if isinstance(x, numbers.Number):
        return bool(np.isfinite(complex(x).real)) and bool(np.isfinite(complex(x).imag)) if not isinstance(
            x, numbers.Integral) else abs(int(x)) < 2**62
    if isinstance(x, np.ndarray):
        return x.dtype.kind not in "fc" or bool(np.all(np.isfinite(x)))
    if isinstance(x, (list, tuple)):
        return all(_finite(v) for v in x)
    if isinstance(x, dict):
        return all(_finite(v) for v in x.values())
    return True


def _has_nan(x, depth=0) -> bool:
    if depth > 3:
        return False
    if isinstance(x, float):
        return math.isnan(x)
    if isinstance(x, complex):
        return math.isnan(x.real) or math.isnan(x.imag)
    if isinstance(x, np.ndarray):
        return x.dtype.kind in "fc" and bool(np.any(np.isnan(x)))
    if isinstance(x, (list, tuple)):
        return any(_has_nan(v, depth + 1) for v in x[:1000])
    if isinstance(x, dict):
        return any(_has_nan(v, depth + 1) for v in list(x.values())[:1000])
    if hasattr(x, "__dataclass_fields__"):
        return any(_has_nan(getattr(x, f, None), depth + 1) for f in x.__dataclass_fields__)
    return False


def _call(task):
    """In the child: resolve, call, classify. Returns (label, name, outcome, detail)."""
    label, name, args, kwargs = task
    try:
        fn = _resolve(label, name)
    except Exception as e:  # noqa: BLE001
        return label, name, "setup", repr(e)
    names = _parameter_names(fn)
    try:
        out = fn(*args, **kwargs)
    except (ValueError, TypeError) as e:
        msg = str(e)
        given_names = names[:len(args)] + list(kwargs)
        named = (any(n and n in msg for n in given_names) or "argument" in msg
                 or re.search(r"\w+\.\w+ = ", msg) is not None or "must be" in msg and len(given_names) <= 1)
        return label, name, "rejected_named" if named else "rejected_unnamed", f"{type(e).__name__}: {msg[:200]}"
    except REFUSALS as e:
        return label, name, "refused", f"{type(e).__name__}: {str(e)[:200]}"
    except Exception as e:  # noqa: BLE001
        return label, name, "other_exception", f"{type(e).__name__}: {str(e)[:200]}"
    if label in ("gt", "ge", "gts", "aps"):
        pass
    if _finite(list(args)) and _finite(kwargs) and _has_nan(out):
        return label, name, "nan_output", repr(out)[:200]
    return label, name, "ok", ""


def _draw_tasks(callables):
    tasks = []
    dialects = {"gt": gt, "ge": ge, "gts": gts, "aps": aps}
    for label, name in callables:
        try:  # the parameter names, without opening a card in this (the test) process
            fn = getattr(dialects[label].controller(), name) if label in dialects else _resolve(label, name)
            names = _parameter_names(fn)
        except Exception:  # noqa: BLE001
            names = []
        drawn = []

        @settings(max_examples=EXAMPLES, database=None, derandomize=True, deadline=None,
                  suppress_health_check=list(HealthCheck))
        @given(args=st.lists(VALUES, max_size=min(4, max(len(names), 1))),
               kw=st.dictionaries(st.sampled_from(names or ["x"]), VALUES, max_size=2))
        def draw(args, kw):
            kw = {k: v for k, v in kw.items() if k not in names[:len(args)]}
            drawn.append((list(args), kw if names else {}))

        draw()
        tasks += [(label, name, a, k) for a, k in drawn]
    return tasks


@pytest.fixture(scope="module")
def fuzz_results():
    callables = _public_callables()
    tasks = _draw_tasks(callables)
    ctx = multiprocessing.get_context("fork")
    results, lost = [], []
    with ctx.Pool(processes=2, maxtasksperchild=1) as pool:
        pending = [(t, pool.apply_async(_call, (t,))) for t in tasks]
        for t, p in pending:
            try:
                results.append(p.get(timeout=TIME_LIMIT_S))
            except multiprocessing.TimeoutError:
                lost.append((t[0], t[1], repr(t[2])[:120], repr(t[3])[:120]))
            except Exception as e:  # noqa: BLE001 -- a result that could not be sent back
                results.append((t[0], t[1], "other_exception", repr(e)[:200]))
        pool.terminate()
    return callables, tasks, results, lost


def test_fuzz_covers_every_public_callable(fuzz_results):
    callables, tasks, results, lost = fuzz_results
    assert len(callables) > 300
    assert len(tasks) >= EXAMPLES * len(callables) // 2


def test_fuzz_no_crash_and_no_hang(fuzz_results):
    _c, _t, _r, lost = fuzz_results
    assert not lost, f"{len(lost)} calls crashed the child or hung: {lost[:10]}"


def test_fuzz_no_nan_from_finite_inputs(fuzz_results):
    _c, _t, results, _l = fuzz_results
    bad = [r for r in results if r[2] == "nan_output"]
    assert not bad, bad[:10]


def test_fuzz_dialects_never_raise(fuzz_results):
    _c, _t, results, _l = fuzz_results
    bad = [r for r in results if r[0] in ("gt", "ge", "gts", "aps") and r[2] not in ("ok", "setup")]
    assert not bad, f"{len(bad)} vendor calls raised: {bad[:10]}"


def test_fuzz_rejections_name_the_parameter(fuzz_results):
    _c, _t, results, _l = fuzz_results
    rejected = [r for r in results if r[2] in ("rejected_named", "rejected_unnamed", "other_exception")]
    named = [r for r in rejected if r[2] == "rejected_named"]
    share = len(named) / max(len(rejected), 1)
    others = [r for r in rejected if r[2] != "rejected_named"]
    assert share >= 0.95, f"{share:.1%} of {len(rejected)} rejections named the parameter; e.g. {others[:15]}"
