"""The GUC-ECAT motion program (GUC Chapter 5, L2100-2560): a program downloaded into the controller whose
functions run in up to 32 threads on the card, beside the application program, with global variables and 32 data
pages of local variables the application reads and writes; as a mixin of
:class:`~servobench.dialects.gts.GtsController`.

The manual's motion programs are C files compiled by the vendor's MCT2008 tool (L2238-2241); here, as for the
application programs, the C becomes Python with the same statements (decision GS13): a motion program is a ``.py``
file whose module-level numbers are the global variables and whose functions are the motion functions; it calls
the ``GT_*`` functions by name, as the C file does (they are put into its namespace and run on the card: no bus
time). A function that waits (a polling loop in C) is a generator: each ``yield`` ends the thread's work for this
servo tick (the card's thread scheduling, L2117-2120); a plain function runs to its end in the tick its thread
starts. Locals a program sets with GT_SetVarValue are the function's parameters (``def add(begin, end)``, L2278).

Call order (L2236-2249): GT_Compile (checks the file, "writes" ``<stem>.bin``) -> GT_Download -> GT_GetFunId /
GT_GetVarId -> GT_Bind(thread, funId, page) -> GT_SetVarValue -> GT_RunThread -> GT_GetThreadSts /
GT_GetVarValue. Codes: 0 success, 1 the call is refused in this state (no program, unknown name, a running
thread), 7 a value out of range.

The card's part is C++ (decision GY1): the card module ``_core.guc_program(card)`` (``vendor/googol/guc_program.hpp``)
holds the program's symbol tables, the 32 threads (binding, run/pause, TThreadSts), the data pages and the globals,
checks every argument and returns the codes, and says each tick which thread steps. What stays here is what IS
Python: compiling and loading the ``.py`` (its namespace, its functions), the generator of each started thread,
and the per-tick hook that steps them and reports each step's outcome back (:func:`_step`)."""

from __future__ import annotations

import contextlib
import inspect
import weakref
from dataclasses import dataclass, field
from pathlib import Path

from .. import _core
from ._controller import GOOGOL_COMMAND_ERROR, GOOGOL_COMM_ERROR, GOOGOL_PARAMETER_ERROR, GOOGOL_SUCCESS
from ._gt_system import gt_adapter
from ._gts_config import _f, _nums

N_THREADS = N_PAGES = 32  # threads and data pages 0..31 (L2108, L2172-2175, L2254)
GLOBAL_PAGE = -1          # GT_Set/GetVarValue page of the global variables (L2217-2219)

#: Motion-program calls the simulation cannot carry out (none: see the module docstring).
UNSUPPORTED_PROGRAM: dict[str, str] = {}


@dataclass
class TCompileInfo:
    """GT_Compile's result: the file, the line of the first error (0 = none) and its message."""
    fileName: str = ""
    lineNo: int = 0
    message: str = ""


@dataclass
class TVarInfo:
    """A variable of the downloaded program (L2158-2166): id (its index among the globals or the function's
    variables), dataType 0 (DINT), the function ("" = global) and the name."""
    id: int = -1
    dataType: int = 0
    function: str = ""
    name: str = ""


@dataclass
class TThreadSts:
    """TThreadSts (L2200-2213): run 1 running, 2 paused, 0 not running (stopped or ended; decision GS14); error
    the last return code of a GT call the thread made (or 1 if the function raised); result the function's
    return value; line the motion program's line the thread stands on."""
    run: int = 0
    error: int = 0
    result: float = 0.0
    line: int = 0


@dataclass
class _Host:
    """What IS Python of the program a card runs (GS13, GY1): its namespace (the globals its functions read and
    assign), its functions in id order, the generator of each started thread and the tick hook's subscription."""
    ns: dict
    functions: list
    frames: dict = field(default_factory=dict)
    sid: int | None = None


#: GT_Compile's output, the PC's ``<stem>.bin`` files: compiled code by path.
_COMPILED: dict = {}
#: The program each card runs (by its Python Card), forgotten with the card.
_HOSTS: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()


def _prog(card):
    """The card's C++ motion-program module (vendor/googol/guc_program.hpp)."""
    return _core.guc_program(card.kernel)


def _bin_of(path) -> Path:
    return Path(path).expanduser().resolve().with_suffix(".bin")


def _dint(v):
    """A variable's value as the program holds it: an int when whole (DINT), else the float."""
    return int(v) if v == v and abs(v) != float("inf") and v == int(v) else v


def _value(v):
    """A Python variable's value for the card (a double; a value that is not a number reads 0)."""
    try:
        return float(v)
    except (TypeError, ValueError, OverflowError):
        return 0.0


def _var(info):
    """TVarInfo's (id, function) as the C++ module takes them (anything else: no variable, 1)."""
    return (_f(info.id), str(info.function or "")) if isinstance(info, TVarInfo) else (-1.0, "")


def _once(f, kwargs):
    """A plain motion function as a thread: runs to its end in its first tick."""
    return (yield from ()) or f(**kwargs)


# -- the host: compile, download, the per-tick stepping ---------------------------------------------------------------
def _compile(self, pFileName):
    info = TCompileInfo(fileName=str(pFileName))
    if not isinstance(pFileName, (str, Path)) or not str(pFileName):
        return GOOGOL_PARAMETER_ERROR, info
    path = Path(pFileName).expanduser()
    if path.suffix != ".py":
        info.message = "not a Python motion program: C motion programs need the vendor's MCT2008 compiler (GS13)"
        return GOOGOL_COMMAND_ERROR, info
    try:
        code = compile(path.read_text(encoding="utf-8"), str(path.resolve()), "exec")
    except OSError as e:
        info.message = f"cannot read the file: {e}"
        return GOOGOL_COMMAND_ERROR, info
    except SyntaxError as e:
        info.lineNo, info.message = int(e.lineno or 0), str(e.msg)
        return GOOGOL_COMMAND_ERROR, info
    _COMPILED[_bin_of(path)] = code
    return GOOGOL_SUCCESS, info


def _library(self, prog) -> dict:
    """The GT functions as the program calls them: the controller's, each reporting its code to the C++ module as
    the calling thread's ``error``. They run inside a servo tick (:func:`_step`), so they cost no bus time."""
    def on_card(name):
        def call(*args, **kwargs):
            out = getattr(self, name)(*args, **kwargs)  # the vendor wrapper: a code, never an exception
            prog.record_error(int(out if isinstance(out, int) else out[0]))
            return out

        call.__name__ = name
        return call

    return {n: on_card(n) for n in dir(type(self)) if n.startswith("GT_") and n not in ("GT_Open", "GT_Close")}


def _download(self, pFileName) -> int:
    if self._card is None:
        return GOOGOL_COMM_ERROR
    if not isinstance(pFileName, (str, Path)) or not str(pFileName):
        return GOOGOL_PARAMETER_ERROR
    path = Path(pFileName).expanduser()
    if path.suffix == ".py" and (rtn := _compile(self, path)[0]):
        return rtn
    code = _COMPILED.get(_bin_of(path))
    if code is None:
        return GOOGOL_COMMAND_ERROR
    prog = _prog(self._card)
    prog.stop_all()
    lib = _library(self, prog)
    ns = {"__name__": "motion_program", "__builtins__": __builtins__, **lib}
    try:
        exec(code, ns)  # noqa: S102 -- the user's own motion program, as the card runs the downloaded file
    except Exception:  # noqa: BLE001
        return GOOGOL_COMMAND_ERROR
    funs = [v for k, v in ns.items() if inspect.isfunction(v) and v.__globals__ is ns and not k.startswith("_")]
    glob = [k for k, v in ns.items() if not k.startswith("_") and k not in lib
            and isinstance(v, (int, float)) and not isinstance(v, bool)]
    prog.load([_symbols(f) for f in funs], glob, [float(ns[k]) for k in glob])
    old = _HOSTS.get(self._card)
    _HOSTS[self._card] = _Host(ns, funs, sid=old.sid if old is not None else None)
    return GOOGOL_SUCCESS


def _symbols(f) -> tuple:
    """A function's row of the symbol table: name, variables (parameters first), has-default per parameter, line."""
    code, sig = f.__code__, inspect.signature(f).parameters
    params = code.co_varnames[: code.co_argcount + code.co_kwonlyargcount]
    return (f.__name__, list(code.co_varnames), [sig[n].default is not inspect.Parameter.empty for n in params],
            code.co_firstlineno)


def _run_thread(self, thread) -> int:
    """GT_RunThread, and the tick hook on while a thread runs."""
    if self._card is None:
        return GOOGOL_COMM_ERROR
    rtn = _prog(self._card).run_thread(_f(thread))
    host = _HOSTS.get(self._card)
    if rtn == GOOGOL_SUCCESS and host is not None and host.sid is None:
        card = self._card
        host.sid = card.on_event(lambda _c, _ev: _step(card), timer_ticks=1)
    return rtn


def _step(card) -> None:
    """One servo tick of the program's threads: the C++ module says which thread steps (thread order, L2117-2120),
    the host runs its generator to its next ``yield`` and reports how it ended, its line and its locals. The
    globals go into the program's namespace before and back to the card after."""
    prog, host = _prog(card), _HOSTS[card]
    names, ns = prog.global_names, host.ns
    ns.update(zip(names, map(_dint, prog.global_values)))
    clock = card.clock  # the program's GT calls count as made inside the tick: no bus time (GS13)
    with clock.inside_tick() if clock is not None else contextlib.nullcontext():
        step = prog.next_step(-1)
        while step is not None:
            thread, start, fun_id, args = step
            f = host.functions[fun_id - 1]
            end, value = 0, 0.0
            try:
                if start:
                    args = {k: _dint(v) for k, v in args.items()}
                    host.frames[thread] = f(**args) if inspect.isgeneratorfunction(f) else _once(f, args)
                next(host.frames[thread])
            except StopIteration as done:
                end, value = 1, _value(done.value or 0)
            except Exception:  # noqa: BLE001 -- a failing motion program stops its thread (GS14)
                end = 2
            frame = getattr(host.frames.get(thread), "gi_frame", None) if end == 0 else None
            loc = frame.f_locals if frame is not None else {}
            step = prog.stepped(thread, end, value, frame.f_lineno if frame is not None else 0,
                                [_value(loc[n]) if n in loc else None for n in f.__code__.co_varnames])
    prog.set_global_values([_value(ns.get(n)) for n in names])
    if not prog.any_active():
        card.remove_event(host.sid)
        host.sid = None


def _read_values(rtn, values):
    """GT_GetVarValue's (rtn, value) or, count 2..8, (rtn, [values]); (rtn, 0) when refused."""
    if rtn != GOOGOL_SUCCESS:
        return rtn, 0
    out = [_dint(v) for v in values]
    return rtn, out[0] if len(out) == 1 else out


def _card_call(method):
    """A command row's adapter: -1 without a card, else the C++ module's ``method`` with the arguments as doubles
    (a non-number NaN: out of every range, 7)."""
    def body(self, *args):
        return GOOGOL_COMM_ERROR if self._card is None else getattr(_prog(self._card), method)(*_nums(*args))

    return body


# -- the rows: name, parameters, returns, adapter, docstring ----------------------------------------------------------
_ROWS = (
    ("GT_Compile", "pFileName", None, _compile,
     "(rtn, TCompileInfo): compiles the motion program ``pFileName`` (a ``.py`` file, GS13) and keeps the\n"
     "result as ``<stem>.bin`` for GT_Download (L2451, L2238-2241). 1 with the line and message of the first\n"
     "error, or for a file that is missing or not Python (a C file needs the vendor's MCT2008)."),
    ("GT_Download", "pFileName", "int", _download,
     "Downloads the compiled program ``<stem>.bin`` (or a ``.py`` file, compiled now) into the controller,\n"
     "replacing the previous one and stopping its threads (L2143-2145, L2243-2245). 1 if it was not compiled\n"
     "or its module code raised; -1 without an open card."),
    ("GT_GetFunId", "pFunName", None,
     lambda self, name: (GOOGOL_COMM_ERROR, 0) if self._card is None else tuple(_prog(self._card).fun_id(str(name))),
     "(rtn, function id 1..) of a function of the downloaded program (L2150-2152); 1 if there is none."),
    ("GT_GetVarId", "pFunName, pVarName", None,
     lambda self, fun, var: (GOOGOL_COMM_ERROR, TVarInfo()) if self._card is None else (lambda rtn, i, fn, nm: (
         rtn, TVarInfo(id=i, function=fn, name=nm) if rtn == 0 else TVarInfo()))(*_prog(self._card).var_id(
             "" if fun in (None, 0, "") else str(fun), str(var))),
     "(rtn, TVarInfo) of a global (pFunName None, 0 or \"\") or of a local of function pFunName (its\n"
     "variables: parameters first) (L2158-2166); 1 if there is no such variable."),
    ("GT_Bind", "thread, funId, page", "int", _card_call("bind"),
     "Binds thread 0..31 to function funId and data page 0..31 (L2170-2175); 1 while the thread runs\n"
     "(L2256), for an unknown function, or a page another thread uses (L2258)."),
    ("GT_RunThread", "thread", "int", _run_thread,
     "Starts thread 0..31 (its function with the locals of its page as arguments) or resumes a paused one\n"
     "(L2178-2182); it runs from the next servo tick. 1 if unbound or already running."),
    ("GT_StopThread", "thread", "int", _card_call("stop_thread"),
     "Stops thread 0..31 (L2185-2189); a stopped thread starts again from its function's beginning."),
    ("GT_PauseThread", "thread", "int", _card_call("pause_thread"),
     "Pauses a running thread 0..31 where it stands (L2192-2196); GT_RunThread resumes it. 1 if it does not\n"
     "run."),
    ("GT_GetThreadSts", "thread", None,
     lambda self, t: (GOOGOL_COMM_ERROR, TThreadSts()) if self._card is None else (lambda rtn, *s: (
         rtn, TThreadSts(*s)))(*_prog(self._card).thread_status(_f(t))),
     "(rtn, TThreadSts) of thread 0..31 (L2200-2213)."),
    ("GT_SetVarValue", "page, pVarInfo, pValue, count=1", "int",
     lambda self, page, info, value, count: GOOGOL_COMM_ERROR if self._card is None else _prog(
         self._card).set_var_value(_f(page), *_var(info), _nums(*(value if isinstance(value, (list, tuple))
                                                                 else [value])), _f(count)),
     "Writes ``count`` (1..8) DINT values from pVarInfo on: page -1 the globals, 0..31 the locals of that\n"
     "data page (the arguments the page's thread starts with) (L2215-2225)."),
    ("GT_GetVarValue", "page, pVarInfo, count=1", None,
     lambda self, page, info, count: (GOOGOL_COMM_ERROR, 0) if self._card is None else _read_values(
         *_prog(self._card).var_value(_f(page), *_var(info), _f(count))),
     "(rtn, value) or, count 2..8, (rtn, [values]): globals (page -1) or the locals of data page 0..31 (as\n"
     "the running thread has them now, else as set) (L2227-2233)."),
)


class GtsProgramMixin:
    """GT_Compile, GT_Download, GT_GetFunId, GT_GetVarId, GT_Bind, GT_RunThread, GT_StopThread, GT_PauseThread,
    GT_GetThreadSts, GT_SetVarValue, GT_GetVarValue (see the module docstring): generated from :data:`_ROWS`."""

    def _close_program(self) -> None:
        """Stops every thread (GT_Close / GT_Reset)."""
        if self._card is not None:
            _prog(self._card).stop_all()


for _name, _params, _returns, _body, _doc in _ROWS:
    setattr(GtsProgramMixin, _name, gt_adapter(_name, _params, _body, _doc, _returns, "GtsController",
                                               "servobench.dialects.gts"))
