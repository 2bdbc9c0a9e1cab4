"""GUC-ECAT manual (seed 002) §5.2.3 example (1) "Addition in single thread", L2262-2402: the application program
resets the controller, compiles and downloads the motion program ``sum`` (guc_motion/sum.py, the C of L2266-2296
in Python), looks up the function ``add`` and the variables ``sum`` (global), ``begin`` and ``end`` (locals), binds
thread 0 to ``add`` and data page 0, sets sum = 0, begin = 1, end = 100, runs the thread and reads its status and
``sum`` every PLC cycle.

What the manual says: the motion program adds begin..end into the global ``sum`` and then ends (L2264):
sum = 1 + 2 + ... + 100 = 5050, and ``add`` returns it.

C -> Python (syntax only): the Structured Text ``IF First THEN ... END_IF`` block runs once, the statements after it
run every PLC cycle (the loop below, one pass per task cycle, until the thread ends); ``ADR(x)`` out-parameters are
returned (``rtn, funid = GT_GetFunId(funname)``); the PLC runtime opens the controller before the task runs,
here ``GT_Open()`` does (the machine :func:`machine` builds); TCompileInfo / TVarInfo / TThreadSts are the dialect's
dataclasses; ``rtn:GT_RunThread(0)`` (L2388, a misprint of ``:=``) is a call; the file names 'sum.c' / 'sum.bin'
are the Python motion program and its compiled form beside this file (decision GS13).
"""

from pathlib import Path

import servobench as sb
from servobench.dialects import gts
from servobench.dialects.gts import (GT_Bind, GT_Compile, GT_Download, GT_GetFunId, GT_GetThreadSts, GT_GetVarId,
                                     GT_GetVarValue, GT_Open, GT_Reset, GT_RunThread, GT_SetVarValue)

HERE = Path(__file__).resolve().parent
TASK_CYCLE_MS = 1.0  # the PLC task's cycle (OtoStudio task configuration; the example does not give it)


def main():
    filename = str(HERE / "guc_motion" / "sum.py")            # 'sum.c'
    downloadfilename = str(HERE / "guc_motion" / "sum.bin")    # 'sum.bin'
    funname = "add"
    varname = "sum"
    rtn = GT_Open()
    first = True
    while True:  # PROGRAM MAIN, once per PLC task cycle
        if first:
            # Reset the motion controller
            rtn = GT_Reset()
            # compile sum.c
            # generate sum.bin and sum.ini after compiling
            rtn, compile = GT_Compile(filename)
            # Download the motion program sum.bin
            rtn = GT_Download(downloadfilename)
            # Get the ID of function
            rtn, funid = GT_GetFunId(funname)
            # Get the ID of global variable "sum"
            rtn, sum = GT_GetVarId(0, varname)
            # Get the ID of local variable "begin"
            varname = "begin"
            rtn, begin = GT_GetVarId(funname, varname)
            # Get the ID of local variable "end"
            varname = "end"
            rtn, end = GT_GetVarId(funname, varname)
            # bind thread, function and data page
            rtn = GT_Bind(0, funid, 0)
            value = 0
            # Initial the global variable "sum" of motion program
            rtn = GT_SetVarValue(-1, sum, value, 1)
            value = 1
            # Initial the local variable "begin" of motion program
            rtn = GT_SetVarValue(0, begin, value, 1)
            value = 100
            # Initial the local variable "end" of motion program
            rtn = GT_SetVarValue(0, end, value, 1)
            # Start up thread
            rtn = GT_RunThread(0)
            first = False
        # Check the status of thread
        rtn, thread = GT_GetThreadSts(0)
        # Check the value of global variable "sum"
        rtn, value = GT_GetVarValue(-1, sum, 1)
        if not thread.run:  # (not in the manual: the PLC task runs on; the example is done when the thread ends)
            return rtn, thread, value
        gts.controller().run_ms(TASK_CYCLE_MS)  # the PLC task cycle passes


# -- the simulated machine (not the manual's): a GUC-800 with 8 axes, 200 us servo period (the tuned law's),
# program-mode clock ----------------------------------------------------------------------------------------------
def machine() -> sb.Card:
    card = sb.Card(8, law=sb.GtServoLaw(kp=38, ki=60, kd=830, kaff=12870), servo_period_s=200e-6)
    card.set_clock("program")
    return card


if __name__ == "__main__":
    gts.use_machine(machine)
    print(main())
