"""GE manual (seed 001) Example 7-1 "Home 回原点例程（以 GE-300-SG 运动控制器为例）" (homing on a GE-300-SG),
L2099-2199, with the procedure of §7.2 (L2053-2069) and the AxisInitial of Example 3-3 (GE-X00-XV, pulse output,
L640-668) that main refers to ("引用例程 3-2 或 3-3", L2187).

What it does: hooks the command handler, opens and resets the card, initialises axis 1 (pulse output, CW/CCW
pulses, servo on), then Home(1, -1000000, 1000, 20, 2): a path line of axis 1 toward -1000000 at 20 pulse/ms
(acceleration 0.01 pulse/ms^2) with the Home capture armed; when status bit 3 (captured) comes, GT_StpMtn and wait
for the path to end (coordinate status bit 0); back to the captured position at 2 pulse/ms; 1000 pulse further
to leave the switch; wait 1000 ms for the table to settle; GT_ZeroPos. Home returns 0 (1 if the path ended
without a Home signal).

The manual's result (§7.2 L2053-2069): the table stands 1000 pulse past the position where the Home signal came,
and that place is the machine's zero (actual and profile 0); no command error is reported, main prints nothing.

C -> Python changes (syntax only): ``#include "ges.h"`` (the SX library, Example 3-5 L741) is
``lib = GeController("SX")`` and its functions; ``GT_GetPrfPnt(prf_pos)`` / ``GT_GetCrdSts(&crd_status)`` /
``GT_GetSts(axis, &status)`` / ``GT_GetCapt(axis, &pos)`` return ``(rtn, value)`` tuples; ``do {...} while (c)``
is ``while True: ...; if not c: break``; ``rtn`` (used undeclared, L2160) is a local; the handler's ``char
*command`` is a str.
"""

from servobench.dialects.ge import GeController

lib = GeController("SX")  # the GE-X00-SX library (ges.h)
GT_AxisOn, GT_CaptHome, GT_ClrSts, GT_CtrlMode = lib.GT_AxisOn, lib.GT_CaptHome, lib.GT_ClrSts, lib.GT_CtrlMode
GT_GetCapt, GT_GetCrdSts, GT_GetPrfPnt, GT_GetSts = lib.GT_GetCapt, lib.GT_GetCrdSts, lib.GT_GetPrfPnt, lib.GT_GetSts
GT_HookCommand, GT_LmtSns, GT_LnXYZ, GT_Open = lib.GT_HookCommand, lib.GT_LmtSns, lib.GT_LnXYZ, lib.GT_Open
GT_Reset, GT_SetSynAcc, GT_SetSynVel, GT_StepPulse = lib.GT_Reset, lib.GT_SetSynAcc, lib.GT_SetSynVel, lib.GT_StepPulse
GT_StpMtn, GT_ZeroPos, delay = lib.GT_StpMtn, lib.GT_ZeroPos, lib.delay

printed: list = []  # what main and the handler printed, for the test


def error(rtn):
    """Example 3-1 (L581-613): the return-value function AxisInitial calls."""
    if rtn != 0:
        printed.append(f"Error Code ={rtn}")


def AxisInitial(axis_num, limit):
    """Example 3-3 (L640-668): initialisation of the axes of a GE-X00-XV card in pulse output."""
    # control axis initialisation
    rtn = GT_LmtSns(limit)  # set the limit switches' trigger level
    error(rtn)
    for i in range(1, axis_num + 1):
        rtn = GT_CtrlMode(i, 1)  # the axis outputs pulses
        error(rtn)
        rtn = GT_StepPulse(i)  # the axis outputs CW/CCW pulses
        error(rtn)
        rtn = GT_AxisOn(i)  # enable the drive
        error(rtn)
        rtn = GT_ClrSts(i)  # reset the axis status register
        error(rtn)
        delay(200)  # insert a suitable delay: wait for the drive to be servo-ready


def CommandHandle(command, error):
    if error == -1:
        printed.append("Communication Error !")
    elif error == 0:
        pass
    elif error == 1:
        printed.append("Command Error !")
    elif error == 2:
        printed.append("Radius or chord is 0 !")
    elif error == 3:
        printed.append("Length is 0 or overflow !")
    elif error == 4:
        printed.append("Velocity or acceleration is less then 0 !")
    elif error == 5:
        printed.append("Chord is greater than diameter !")
    elif error == 7:
        printed.append("Parameter error !")
    else:
        printed.append(f"Error Code = {error}")


def Home(axis, pos, offset, vel_high, vel_low):
    GT_ClrSts(axis)  # clear the homing axis's status
    GT_CaptHome(axis)  # the homing axis captures on Home
    GT_SetSynVel(vel_high)  # homing velocity
    GT_SetSynAcc(0.01)  # homing acceleration
    _, prf_pos = GT_GetPrfPnt()  # read the axes' profile positions
    prf_pos[axis - 1] = pos  # target position of the homing axis
    GT_LnXYZ(prf_pos[0], prf_pos[1], prf_pos[2])
    while True:
        _, crd_status = GT_GetCrdSts()  # read the coordinate system's status
        if crd_status & 1:  # the motion has completed
            return 1  # and still no Home signal: return error code 1
        _, status = GT_GetSts(axis)  # read the axis status
        if status & 0x8:  # wait for the Home signal (do ... while (!(status & 0x8)))
            break
    GT_StpMtn()  # smooth stop
    while True:
        _, crd_status = GT_GetCrdSts()  # read the coordinate system's status
        if crd_status & 1:  # wait for the motion to complete (do ... while (!(crd_status & 1)))
            break
    _, pos = GT_GetCapt(axis)  # read the captured position
    GT_SetSynVel(vel_low)  # to the origin at low speed
    prf_pos[axis - 1] = pos
    rtn = GT_LnXYZ(prf_pos[0], prf_pos[1], prf_pos[2])
    while True:
        _, crd_status = GT_GetCrdSts()  # read the coordinate system's status
        if crd_status & 1:  # wait for the motion to complete (do ... while (!(crd_status & 1)))
            break
    prf_pos[axis - 1] += offset  # a short distance further, off the Home switch
    GT_LnXYZ(prf_pos[0], prf_pos[1], prf_pos[2])
    while True:
        _, crd_status = GT_GetCrdSts()  # read the coordinate system's status
        if crd_status & 1:  # wait for the motion to complete (do ... while (!(crd_status & 1)))
            break

    delay(1000)  # insert a suitable delay: wait for the table to settle

    GT_ZeroPos(axis)  # zero the table's position: the machine coordinate system
    return 0


def main():
    GT_HookCommand(CommandHandle)
    GT_Open()  # open the motion controller
    GT_Reset()  # reset the motion controller
    AxisInitial(1, 0)  # Example 3-2 or 3-3
    if 0 != Home(1, -1000000, 1000, 20, 2):  # call the homing function
        printed.append("\n Home Error !")


# -- the simulated machine (not the manual's) -----------------------------------------------------------------------
HOME_EDGE = -2000   # the table enters the Home switch of axis 1 here, moving toward -1000000 (pulse)


def machine():
    """A GE-300-SG's axes (4-axis SX card, 200 us): pulse-input servo drives (10000 pulse/rev, 10000-count
    encoders); axis 1 has its Home switch from -3000 to -2000 pulse, entered at -2000 on the way to -1000000."""
    import math

    import servobench as sb

    rad = 2 * math.pi / 10000
    card = sb.Card(4, law=sb.GtServoLaw(fractional_gains=True), drive=sb.ServoPositionDrive(),
                   switches=sb.Switches(home_min_rad=(HOME_EDGE - 1000) * rad, home_max_rad=HOME_EDGE * rad),
                   servo_period_s=200e-6)
    card.set_clock("program")
    return card


if __name__ == "__main__":
    lib.use_machine(machine)
    main()
