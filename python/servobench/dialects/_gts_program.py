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
thread), 7 a value out of range."""

from __future__ import annotations

import inspect
import math
from dataclasses import dataclass
from pathlib import Path

from ._controller import GOOGOL_COMMAND_ERROR, GOOGOL_COMM_ERROR, GOOGOL_PARAMETER_ERROR, GOOGOL_SUCCESS

N_THREADS = N_PAGES = 32  # threads and data pages 0..31 (L2108, L2172-2175, L2254)
GLOBAL_PAGE = -1          # GT_Set/GetVarValue page of the global variables (L2217-2219)
_DINT = (-2**31, 2**31 - 1)

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


class _Thread:
    def __init__(self):
        self.fun_id = 0
        self.page = -1
        self.gen = None
        self.paused = False
        self.sts = TThreadSts()
        self.exception: BaseException | None = None


def _int_in(v, lo, hi) -> bool:
    try:
        x = float(v)
    except (TypeError, ValueError):
        return False
    return math.isfinite(x) and x == int(x) and lo <= x <= hi


def _bin_of(path) -> Path:
    p = Path(path).expanduser().resolve()
    return p.with_suffix(".bin")


class GtsProgramMixin:
    """GT_Compile, GT_Download, GT_GetFunId, GT_GetVarId, GT_Bind, GT_RunThread, GT_StopThread, GT_PauseThread,
    GT_GetThreadSts, GT_SetVarValue, GT_GetVarValue (see the module docstring)."""

    def _mp(self) -> dict:
        st = self.__dict__.get("_mp_state")
        if st is None:
            st = self.__dict__["_mp_state"] = {"compiled": {}, "ns": None, "funs": [], "globals": [],
                                               "threads": [_Thread() for _ in range(N_THREADS)],
                                               "pages": [dict() for _ in range(N_PAGES)], "current": None}
        return st

    def _tick_hook(self, name: str, fn) -> None:
        """Runs ``fn(card)`` after every servo tick while the program's threads run (``None`` stops it): one card
        timer event (:meth:`~servobench.Card.on_event`, ``timer_ticks=1``). ``name`` is "threads" (the only
        per-tick work left in Python: the motion program is the host's Python code, decision GT12)."""
        st = self._mp()
        if fn is not None and st.get("sid") is None:
            st["sid"] = self._card.on_event(lambda c, _ev: fn(c), timer_ticks=1)
        elif fn is None and st.get("sid") is not None:
            self._card.remove_event(st["sid"])
            st["sid"] = None

    def _close_program(self) -> None:
        """Stops every thread (GT_Close / GT_Reset / a new download)."""
        st = self._mp()
        for th in st["threads"]:
            if th.gen is not None:
                th.gen.close()
            th.gen, th.paused, th.sts.run = None, False, 0
        if self._card is not None:
            self._tick_hook("threads", None)

    # -- the program's namespace: the GT library on the card --------------------------------------------------
    def _library(self) -> dict:
        """The GT functions as the program calls them: the controller's, recording each return code as the calling
        thread's ``error``. They run inside a servo tick (:meth:`_step_threads`), so they cost no bus time."""
        lib = {}
        for name in dir(type(self)):
            if name.startswith("GT_") and name not in ("GT_Open", "GT_Close"):
                lib[name] = self._on_card(name)
        return lib

    def _on_card(self, name):
        def call(*args, **kwargs):
            out = getattr(self, name)(*args, **kwargs)  # the vendor wrapper: a code, never an exception
            th = self._mp()["current"]
            if th is not None:
                th.sts.error = int(out if isinstance(out, int) else out[0])
            return out

        call.__name__ = name
        return call

    # -- compile and download ----------------------------------------------------------------------------------
    def GT_Compile(self, pFileName):
        """(rtn, TCompileInfo): compiles the motion program ``pFileName`` (a ``.py`` file, GS13) and keeps the
        result as ``<stem>.bin`` for GT_Download (L2451, L2238-2241). 1 with the line and message of the first
        error, or for a file that is missing or not Python (a C file needs the vendor's MCT2008)."""
        info = TCompileInfo(fileName=str(pFileName))
        if not isinstance(pFileName, (str, Path)) or not str(pFileName):
            return GOOGOL_PARAMETER_ERROR, info
        path = Path(pFileName).expanduser()
        if path.suffix != ".py":
            info.message = "not a Python motion program: C motion programs need the vendor's MCT2008 compiler (GS13)"
            return GOOGOL_COMMAND_ERROR, info
        try:
            source = path.read_text(encoding="utf-8")
            code = compile(source, str(path.resolve()), "exec")
        except OSError as e:
            info.message = f"cannot read the file: {e}"
            return GOOGOL_COMMAND_ERROR, info
        except SyntaxError as e:
            info.lineNo, info.message = int(e.lineno or 0), str(e.msg)
            return GOOGOL_COMMAND_ERROR, info
        self._mp()["compiled"][_bin_of(path)] = code
        return GOOGOL_SUCCESS, info

    def GT_Download(self, pFileName) -> int:
        """Downloads the compiled program ``<stem>.bin`` (or a ``.py`` file, compiled now) into the controller,
        replacing the previous one and stopping its threads (L2143-2145, L2243-2245). 1 if it was not compiled
        or its module code raised; -1 without an open card."""
        if self._card is None:
            return GOOGOL_COMM_ERROR
        if not isinstance(pFileName, (str, Path)) or not str(pFileName):
            return GOOGOL_PARAMETER_ERROR
        st = self._mp()
        path = Path(pFileName).expanduser()
        if path.suffix == ".py":
            rtn, _info = self.GT_Compile(path)
            if rtn:
                return rtn
        code = st["compiled"].get(_bin_of(path))
        if code is None:
            return GOOGOL_COMMAND_ERROR
        self._close_program()
        lib = self._library()
        ns = {"__name__": "motion_program", "__builtins__": __builtins__, **lib}
        try:
            exec(code, ns)  # noqa: S102 -- the user's own motion program, as the card runs the downloaded file
        except Exception:  # noqa: BLE001
            return GOOGOL_COMMAND_ERROR
        funs = [v for k, v in ns.items() if inspect.isfunction(v) and v.__globals__ is ns and not k.startswith("_")]
        glob = [k for k, v in ns.items() if not k.startswith("_") and k not in lib
                and isinstance(v, (int, float)) and not isinstance(v, bool)]
        st.update(ns=ns, funs=funs, globals=glob, pages=[dict() for _ in range(N_PAGES)])
        for th in st["threads"]:
            th.fun_id, th.page = 0, -1
        return GOOGOL_SUCCESS

    def GT_GetFunId(self, pFunName):
        """(rtn, function id 1..) of a function of the downloaded program (L2150-2152); 1 if there is none."""
        st = self._mp()
        for k, f in enumerate(st["funs"], 1):
            if f.__name__ == pFunName:
                return GOOGOL_SUCCESS, k
        return (GOOGOL_COMM_ERROR if self._card is None else GOOGOL_COMMAND_ERROR), 0

    def GT_GetVarId(self, pFunName, pVarName):
        """(rtn, TVarInfo) of a global (pFunName None, 0 or "") or of a local of function pFunName (its
        variables: parameters first) (L2158-2166); 1 if there is no such variable."""
        st = self._mp()
        if st["ns"] is None:
            return (GOOGOL_COMM_ERROR if self._card is None else GOOGOL_COMMAND_ERROR), TVarInfo()
        if pFunName in (None, 0, ""):
            names, fun = st["globals"], ""
        else:
            f = next((f for f in st["funs"] if f.__name__ == pFunName), None)
            if f is None:
                return GOOGOL_COMMAND_ERROR, TVarInfo()
            names, fun = list(f.__code__.co_varnames), f.__name__
        if pVarName not in names:
            return GOOGOL_COMMAND_ERROR, TVarInfo()
        return GOOGOL_SUCCESS, TVarInfo(id=names.index(pVarName), function=fun, name=str(pVarName))

    # -- threads ------------------------------------------------------------------------------------------------
    def _thread(self, thread):
        return self._mp()["threads"][int(thread)] if _int_in(thread, 0, N_THREADS - 1) else None

    def GT_Bind(self, thread, funId, page) -> int:
        """Binds thread 0..31 to function funId and data page 0..31 (L2170-2175); 1 while the thread runs
        (L2256), for an unknown function, or a page another thread uses (L2258)."""
        if self._card is None:
            return GOOGOL_COMM_ERROR
        st = self._mp()
        th = self._thread(thread)
        if th is None or not _int_in(page, 0, N_PAGES - 1) or not _int_in(funId, 1, 2**15):
            return GOOGOL_PARAMETER_ERROR
        if th.sts.run or int(funId) > len(st["funs"]):
            return GOOGOL_COMMAND_ERROR
        if any(o is not th and o.page == int(page) for o in st["threads"]):
            return GOOGOL_COMMAND_ERROR
        th.fun_id, th.page = int(funId), int(page)
        return GOOGOL_SUCCESS

    def GT_RunThread(self, thread) -> int:
        """Starts thread 0..31 (its function with the locals of its page as arguments) or resumes a paused one
        (L2178-2182); it runs from the next servo tick. 1 if unbound or already running."""
        if self._card is None:
            return GOOGOL_COMM_ERROR
        th = self._thread(thread)
        if th is None:
            return GOOGOL_PARAMETER_ERROR
        st = self._mp()
        if th.paused:
            th.paused, th.sts.run = False, 1
            return GOOGOL_SUCCESS
        if th.sts.run or not th.fun_id or th.fun_id > len(st["funs"]):
            return GOOGOL_COMMAND_ERROR
        f = st["funs"][th.fun_id - 1]
        page = st["pages"][th.page]
        params = inspect.signature(f).parameters
        kwargs = {n: page[n] for n in params if n in page}
        missing = [n for n, p in params.items() if n not in kwargs and p.default is inspect.Parameter.empty]
        kwargs.update({n: 0 for n in missing})  # a C local nobody set reads 0 here
        th.gen = f(**kwargs) if inspect.isgeneratorfunction(f) else _once(f, kwargs)
        th.sts, th.exception = TThreadSts(run=1, line=f.__code__.co_firstlineno), None
        self._tick_hook("threads", self._step_threads)
        return GOOGOL_SUCCESS

    def _step_threads(self, _card) -> None:
        """One servo tick of the running threads, in thread order (the card's scheduler). Their GT calls count as
        made inside the tick (the clock's nesting depth, as calls from an event callback): no bus time (GS13)."""
        local = getattr(getattr(self._card, "_clock", None), "_local", None)
        depth = getattr(local, "depth", 0)
        if local is not None:
            local.depth = depth + 1
        try:
            self._step_each()
        finally:
            if local is not None:
                local.depth = depth

    def _step_each(self) -> None:
        st = self._mp()
        for th in st["threads"]:
            if th.gen is None or th.paused:
                continue
            st["current"] = th
            try:
                next(th.gen)
                frame = th.gen.gi_frame
                if frame is not None:
                    th.sts.line = frame.f_lineno
            except StopIteration as done:
                th.gen, th.sts.run = None, 0
                try:
                    th.sts.result = float(done.value or 0)
                except (TypeError, ValueError):
                    th.sts.result = 0.0
            except Exception as e:  # noqa: BLE001 -- a failing motion program stops its thread (GS14)
                th.gen, th.sts.run, th.sts.error, th.exception = None, 0, GOOGOL_COMMAND_ERROR, e
            finally:
                st["current"] = None
        if not any(th.gen is not None for th in st["threads"]):
            self._tick_hook("threads", None)

    def GT_StopThread(self, thread) -> int:
        """Stops thread 0..31 (L2185-2189); a stopped thread starts again from its function's beginning."""
        if self._card is None:
            return GOOGOL_COMM_ERROR
        th = self._thread(thread)
        if th is None:
            return GOOGOL_PARAMETER_ERROR
        if th.gen is not None:
            th.gen.close()
        th.gen, th.paused, th.sts.run = None, False, 0
        return GOOGOL_SUCCESS

    def GT_PauseThread(self, thread) -> int:
        """Pauses a running thread 0..31 where it stands (L2192-2196); GT_RunThread resumes it. 1 if it does not
        run."""
        if self._card is None:
            return GOOGOL_COMM_ERROR
        th = self._thread(thread)
        if th is None:
            return GOOGOL_PARAMETER_ERROR
        if th.gen is None or th.paused:
            return GOOGOL_COMMAND_ERROR
        th.paused, th.sts.run = True, 2
        return GOOGOL_SUCCESS

    def GT_GetThreadSts(self, thread):
        """(rtn, TThreadSts) of thread 0..31 (L2200-2213)."""
        if self._card is None:
            return GOOGOL_COMM_ERROR, TThreadSts()
        th = self._thread(thread)
        if th is None:
            return GOOGOL_PARAMETER_ERROR, TThreadSts()
        s = th.sts
        return GOOGOL_SUCCESS, TThreadSts(run=s.run, error=s.error, result=s.result, line=s.line)

    # -- variables ------------------------------------------------------------------------------------------------
    def _var_names(self, page, info, count):
        """The ``count`` variable names from ``info`` on, or None."""
        st = self._mp()
        if st["ns"] is None or not isinstance(info, TVarInfo) or not _int_in(count, 1, 8):
            return None
        if int(page) == GLOBAL_PAGE:
            names = st["globals"] if info.function == "" else None
        else:
            f = next((f for f in st["funs"] if f.__name__ == info.function), None) if info.function else None
            names = list(f.__code__.co_varnames) if f is not None else None
        if names is None or not 0 <= info.id or info.id + int(count) > len(names):
            return None
        return names[info.id: info.id + int(count)]

    def GT_SetVarValue(self, page, pVarInfo, pValue, count=1) -> int:
        """Writes ``count`` (1..8) DINT values from pVarInfo on: page -1 the globals, 0..31 the locals of that
        data page (the arguments the page's thread starts with) (L2215-2225)."""
        if self._card is None:
            return GOOGOL_COMM_ERROR
        if not _int_in(page, GLOBAL_PAGE, N_PAGES - 1):
            return GOOGOL_PARAMETER_ERROR
        values = list(pValue) if isinstance(pValue, (list, tuple)) else [pValue]
        if len(values) < int(count) if _int_in(count, 1, 8) else True:
            return GOOGOL_PARAMETER_ERROR
        if not all(_int_in(v, *_DINT) for v in values[: int(count)]):
            return GOOGOL_PARAMETER_ERROR
        names = self._var_names(page, pVarInfo, count)
        if names is None:
            return GOOGOL_COMMAND_ERROR
        st = self._mp()
        target = st["ns"] if int(page) == GLOBAL_PAGE else st["pages"][int(page)]
        for n, v in zip(names, values):
            target[n] = int(v)
        return GOOGOL_SUCCESS

    def GT_GetVarValue(self, page, pVarInfo, count=1):
        """(rtn, value) or, count 2..8, (rtn, [values]): globals (page -1) or the locals of data page 0..31 (as
        the running thread has them now, else as set) (L2227-2233)."""
        if self._card is None:
            return GOOGOL_COMM_ERROR, 0
        if not _int_in(page, GLOBAL_PAGE, N_PAGES - 1):
            return GOOGOL_PARAMETER_ERROR, 0
        names = self._var_names(page, pVarInfo, count)
        if names is None:
            return GOOGOL_COMMAND_ERROR, 0
        st = self._mp()
        if int(page) == GLOBAL_PAGE:
            src = st["ns"]
        else:
            src = dict(st["pages"][int(page)])
            th = next((t for t in st["threads"] if t.page == int(page) and t.gen is not None), None)
            frame = getattr(th.gen, "gi_frame", None) if th is not None else None
            if frame is not None:
                src.update(frame.f_locals)
        out = [_dint(src.get(n, 0)) for n in names]
        return GOOGOL_SUCCESS, (out[0] if int(count) == 1 else out)


def _dint(v):
    try:
        x = float(v)
    except (TypeError, ValueError):
        return 0
    return int(x) if math.isfinite(x) and x == int(x) else x


def _once(f, kwargs):
    """A plain motion function as a thread: runs to its end in its first tick."""
    return (yield from ()) or f(**kwargs)
