"""GUC-ECAT manual (seed 002) §5.2.3 example (2) "Addition in multi-thread", L2404-2535: the same motion program
as example (1) (guc_motion/sum.py, L2266-2296), run by two threads of the same function ``add``: thread 0 with data
page 0 adds 1..50, thread 1 with data page 1 adds 51..100, both into the global ``sum``.

What the manual says: the two threads complete the addition task of example (1) together (L2408): when both
have ended, sum = 1 + ... + 100 = 5050; thread 0's ``add`` returned the sum so far after 1..50 (1275 if it ran
first).

C -> Python (syntax only), as in guc_motion_sum.py: the ``IF First THEN`` block once, the status reads every PLC
cycle until both threads have ended; ``ADR(x)`` out-parameters returned; 'sum.c' / 'sum.bin' the Python motion
program beside this file (decision GS13); ``GT_Open()`` where the PLC runtime opens the controller.
"""

from pathlib import Path

import servobench as sb
from servobench.dialects import gts
from servobench.dialects.gts import (GT_Bind, GT_Compile, GT_Download, GT_GetFunId, GT_GetThreadSts, GT_GetVarId,
                                     GT_GetVarValue, GT_Open, GT_Reset, GT_RunThread, GT_SetVarValue)

HERE = Path(__file__).resolve().parent
TASK_CYCLE_MS = 1.0  # the PLC task's cycle (OtoStudio task configuration; the example does not give it)


def main():
    First = True
    filename = str(HERE / "guc_motion" / "sum.py")            # 'sum.c'
    downloadfilename = str(HERE / "guc_motion" / "sum.bin")    # 'sum.bin'
    funname = "add"
    varname = "sum"
    rtn = GT_Open()
    while True:  # PROGRAM MAIN, once per PLC task cycle
        if First:
            # Reset the motion controller
            rtn = GT_Reset()
            # compile sum.c
            # generate sum.bin and sum.ini after compiling
            # Ensure that error.ini locates in project file folder
            rtn, compile = GT_Compile(filename)
            # Download the motion program sum.bin
            rtn = GT_Download(downloadfilename)
            # Get the ID of function
            rtn, funId = GT_GetFunId(funname)
            # Get the ID of global variable "sum"
            rtn, sum = GT_GetVarId(0, varname)
            # Get the ID of local variable "begin"
            varname = "begin"
            rtn, begin = GT_GetVarId(funname, varname)
            # Get the ID of local variable "end"
            varname = "end"
            rtn, end = GT_GetVarId(funname, varname)
            # bind thread, function and data page
            rtn = GT_Bind(0, funId, 0)
            rtn = GT_Bind(1, funId, 1)
            # Initial the global variable "sum" of motion program
            value = 0
            rtn = GT_SetVarValue(-1, sum, value, 1)
            # Initial the local variable "begin" of motion program in thread 0
            value = 1
            rtn = GT_SetVarValue(0, begin, value, 1)
            # Initial the local variable "end" of motion program in thread 0
            value = 50
            rtn = GT_SetVarValue(0, end, value, 1)
            # Initial the local variable "begin" of motion program in thread 1
            value = 51
            rtn = GT_SetVarValue(1, begin, value, 1)
            # Initial the local variable "end" of motion program in thread 1
            value = 100
            rtn = GT_SetVarValue(1, end, value, 1)
            # Start thread 0 and 1
            rtn = GT_RunThread(0)
            rtn = GT_RunThread(1)
            First = False
        # Check the status of thread
        rtn, thread0 = GT_GetThreadSts(0)
        rtn, thread1 = GT_GetThreadSts(1)
        # Check the value of the global variable "sum"
        rtn, value = GT_GetVarValue(-1, sum, 1)
        if not thread0.run and not thread1.run:  # (not in the manual: the example is done when both threads end)
            return rtn, thread0, thread1, value
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
