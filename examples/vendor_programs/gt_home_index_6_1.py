"""GT manual (seed 000) Example 6-1 "Home+Index Programming (Only for SV Card)", L2021-2099, with the
initialisation it calls: GTInitial of Example 3-3 (PCI card, L528-543), InputCfg of Example 3-4 (L595-619) and
AxisInitial of Example 3-6 (SV card, L697-742).

What it does: opens the PCI card(s), resets, makes card No. 1 current, sets the 200 us sample time and masks every
axis's interrupts; limit switches high-level triggered, encoders of axes 1-4 reversed; axis 1 closed loop (Kp 20,
Kd 10, bias 10), axis 2 open loop, axes 3 and 4 pulse output (pulse + direction, CW/CCW); then home(200000) on
axis 1: a T-curve (4 pulse/ST, 1 pulse/ST^2) toward 200000 with the Home capture armed, back to the captured
position, the Index capture armed and 8000 pulse further, back to the captured Index, and GT_ZeroPos.

The manual's result (L2017, L2023): "This example fixes the home position and set to zero": the axis stands at the
Index mark nearest the Home switch past its edge, where actual and target position read 0; the captures are exact
to +-1 pulse (L2015).

C -> Python changes (syntax only): ``GT_GetSts(&status)`` / ``GT_GetCapt(&pos)`` return ``(rtn, value)`` tuples;
``rtn`` is the file's global, as the manual's fragment uses it undeclared; ``home`` is called ``Home`` in main
(L2093) and defined as ``home`` (L2026): one name, ``home``. GTInitial, InputCfg, AxisInitial and ``error`` are in
``_gt_init.py`` (shared with the other GT programs, with their own changes listed there), as are the simulated
machine and ``machine()``.
"""

from _gt_init import AxisInitial, GTInitial, InputCfg, error, machine  # noqa: F401 (machine: see __main__)
from servobench.dialects.gt import (GT_Axis, GT_CaptHome, GT_CaptIndex, GT_ClrSts, GT_GetCapt, GT_GetSts, GT_PrflT,
                                    GT_SetAcc, GT_SetPos, GT_SetVel, GT_Update, GT_ZeroPos, use_machine)

rtn = 0


def home(pos):
    """Example 6-1 (L2026-2082): fixes the home position (Home + Index) and sets it to zero."""
    global rtn
    rtn = GT_ClrSts(); error(rtn)  # Clear status.
    rtn = GT_CaptHome(); error(rtn)  # Specify the capture mode of Home capturing.
    rtn = GT_PrflT(); error(rtn)  # Specify T-curve of current axis.
    rtn = GT_SetVel(4); error(rtn)  # Specify velocity of 4 pulse/ST.
    rtn = GT_SetAcc(1); error(rtn)  # Specify acceleration of 1 pulse/ST2.
    rtn = GT_SetPos(pos); error(rtn)  # Specify target position.
    rtn = GT_Update(); error(rtn)  # Update parameter.
    rtn, status = GT_GetSts(); error(rtn)  # Get axis status.
    while not (status & 0x8):  # Wait for Home capturing.
        if status & 0x1:
            return  # If the motion is completed but Home is not triggered, exit.
        rtn, status = GT_GetSts(); error(rtn)  # Get axis status.
    rtn, pos = GT_GetCapt(); error(rtn)  # Get position captured.
    rtn = GT_SetPos(pos); error(rtn)  # Specify capture position of target position.
    rtn = GT_Update(); error(rtn)  # Update parameter.
    rtn = GT_ClrSts(); error(rtn)  # Clear status.
    rtn, status = GT_GetSts(); error(rtn)  # Get status value.
    while not (status & 0x1):  # Wait until the motion is completed.
        rtn, status = GT_GetSts(); error(rtn)  # Get status.
    rtn = GT_ClrSts(); error(rtn)  # Clear status.
    rtn = GT_CaptIndex(); error(rtn)  # Specify the capture mode of Index capturing.
    pos = pos + 8000  # Captured position + 8000 pulse
    rtn = GT_SetPos(pos); error(rtn)  # Move 8000 pulse from captured position.
    rtn = GT_Update(); error(rtn)
    rtn, status = GT_GetSts(); error(rtn)  # Get status.
    while not (status & 0x8):  # Get status and wait for index capturing.
        rtn, status = GT_GetSts(); error(rtn)
    rtn = GT_ClrSts(); error(rtn)  # Clear status.
    rtn, pos = GT_GetCapt(); error(rtn)  # Get position captured.
    rtn = GT_SetPos(pos); error(rtn)  # Specify the captured position of target position.
    rtn = GT_Update(); error(rtn)
    rtn, status = GT_GetSts(); error(rtn)  # Get status.
    while not (status & 0x1):  # Wait until the motion is completed.
        rtn, status = GT_GetSts(); error(rtn)
    rtn = GT_ClrSts(); error(rtn)  # Clear status.
    rtn = GT_ZeroPos(); error(rtn)  # Specify actual and target position of zero.


def main():
    global rtn
    GTInitial()
    InputCfg()
    AxisInitial()
    rtn = GT_Axis(1); error(rtn)
    home(200000)


if __name__ == "__main__":
    use_machine(machine)
    main()
