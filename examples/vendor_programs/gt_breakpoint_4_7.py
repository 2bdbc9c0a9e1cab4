"""GT manual (seed 000) Example 4-7 "Specifying and Triggering the Positive Position Breakpoint", L1265-1297 (with
§4.3.2 L1255-1263), on the initialisation it calls: GTInitial / InputCfg / AxisInitial of Examples 3-3, 3-4, 3-6
(``_gt_init.py``).

What it does: axis 1 moves toward 50000 pulse on a T-curve at 1 pulse/ST (acceleration 0.1 pulse/ST^2) with the
auto-update at a breakpoint on (GT_AuUpdtOn), a positive position breakpoint at 20000 (GT_SetBrkCn + Update,
GT_PosBrk) and a velocity of 4 pulse/ST staged for the auto-update (GT_SetVel(4) after the Update). The program
ends there; the card goes on.

The manual's result (L1267): "in the process of moving the axis #1 to the position 50000, the controller will
trigger the breakpoint at the position 20000, and change the valid velocity from 1 (Pulse/ST) to 4 (Pulse/ST)":
the breakpoint fires when the actual position reaches 20000 (>=, L1263), the breakpoint-triggered flag (status
bit 2) is set (L1263), and the axis then runs at 4 pulse/ST and stops at 50000.

C -> Python changes (syntax only): ``GT_ClearSts()`` (L1281, the manual's misspelling) is ``GT_ClrSts()``; ``rtn``
is the file's global, as the manual's fragment uses it undeclared.
"""

from _gt_init import AxisInitial, GTInitial, InputCfg, error, machine  # noqa: F401 (machine: see __main__)
from servobench.dialects.gt import (GT_AuUpdtOn, GT_Axis, GT_ClrSts, GT_PosBrk, GT_SetAcc, GT_SetBrkCn, GT_SetPos,
                                    GT_SetVel, GT_Update, use_machine)

rtn = 0


def main():
    global rtn
    GTInitial()
    InputCfg()
    AxisInitial()

    rtn = GT_Axis(1); error(rtn)  # Specify the axis #1 of the current axis.
    rtn = GT_ClrSts(); error(rtn)  # Clear status.
    rtn = GT_SetVel(1); error(rtn)  # Specify velocity of 1 (Pulse/ST).
    rtn = GT_SetAcc(0.1); error(rtn)  # Specify acceleration of 0.1 (Pulse/ST2)
    rtn = GT_SetPos(50000); error(rtn)  # Specify target position of 50000.
    rtn = GT_AuUpdtOn(); error(rtn)  # Validate the function of self-updating parameters at breakpoint position.
    rtn = GT_SetBrkCn(20000); error(rtn)  # Specify breakpoint position.
    rtn = GT_Update(); error(rtn)  # Update parameter (Breakpoint position becomes effective.).
    rtn = GT_PosBrk(); error(rtn)  # Specify the breakpoint triggering condition of positive position breakpoint.
    rtn = GT_SetVel(4); error(rtn)  # Specify velocity of 4 (Wait for self-updating.).


if __name__ == "__main__":
    use_machine(machine)
    main()
