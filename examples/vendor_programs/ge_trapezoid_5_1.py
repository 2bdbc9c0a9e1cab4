"""GE manual (seed 001) Example 5-1 "梯形曲线例程" (trapezoid-curve example), L1010-1050, with the AxisInitial of
Example 3-4 it calls (GE-X00-XV, analog output, L670-692) and the units of §5.1.2 (L998-1008).

What it does: hooks the command handler, opens the controller (ISA form, base 0x300), resets it, initialises
axis 1 (limit switches high-level triggered, Kp 10, Update, servo on, status cleared, 200 ms wait) and moves it on
a trapezoid to 200000 pulse at 166.7 pulse/ms with 4 pulse/ms^2 (AxisRunT: PrflT, SetPos, SetVel, SetAcc,
Update). The program ends there; the card goes on.

The manual's figures (L1003-1008): 10 m/min at 1 um/pulse is 166.7 pulse/ms, 200 mm is 200000 pulse; the curve
(L1052-1062): accelerate at 4 pulse/ms^2 to 166.7 pulse/ms, hold, decelerate to 0 at 200000 -- 41.7 ms up,
41.7 ms down, 1241.4 ms in all. The command handler reports no error.

C -> Python changes (syntax only): the handler's ``char *command`` is a Python str; ``GT_Open(0x300)`` misses its
``;`` in the print (L1041); main's closing lines printed after a page break (L1045-1048) are main's.
"""

from servobench.dialects.ge import (GT_AxisOn, GT_ClrSts, GT_HookCommand, GT_LmtSns, GT_Open, GT_PrflT, GT_Reset,
                                    GT_SetAcc, GT_SetKp, GT_SetPos, GT_SetVel, GT_Update, delay, use_machine)

errors: list = []  # (command, error) the handler printed, for the test


def error(rtn):
    """Example 3-1 (L581-613): the return-value function AxisInitial calls."""
    if rtn != 0:
        print(f"\a\nError Code ={rtn}")


def AxisInitial(axis_num, limit, kp):
    """Example 3-4 (L670-692): initialisation of the axes of a GE-X00-XV card (analog voltage output)."""
    # control axis initialisation
    rtn = GT_LmtSns(limit)  # set the limit switches' trigger level
    error(rtn)
    for i in range(1, axis_num + 1):
        rtn = GT_SetKp(i, kp)  # set the axis's proportional gain
        error(rtn)
        rtn = GT_Update(i)  # refresh the parameters so that Kp takes effect
        error(rtn)
        rtn = GT_AxisOn(i)  # servo-enable the axis
        error(rtn)
        rtn = GT_ClrSts(i)  # reset the axis status register
        error(rtn)
        delay(200)  # insert a suitable delay: wait for the drive to be servo-ready


def AxisRunT(axis, pos, vel, acc):
    GT_PrflT(axis)  # trapezoid acceleration/deceleration
    GT_SetPos(axis, pos)  # target position of the axis
    GT_SetVel(axis, vel)  # velocity of the axis
    GT_SetAcc(axis, acc)  # acceleration of the axis
    GT_Update(axis)  # refresh the axis's parameters


def CommandHandle(command, error):
    if error == -1:
        print("\a\nCommunication Error !")
    elif error == 0:
        pass
    elif error == 1:
        print("\a\nCommand Error !")
    elif error == 7:
        print("\a\nParameter Error !")
    else:
        print(f"\a\nError Code ={error}")
    if error != 0:
        errors.append((command, error))


def main():
    GT_HookCommand(CommandHandle)  # hook the error handler
    GT_Open(0x300)  # open the motion controller
    GT_Reset()  # reset the motion controller
    AxisInitial(1, 0, 10)  # control axis initialisation, Example 3-4
    AxisRunT(1, 200000, 166.7, 4)  # the axis moves on a trapezoid curve


# -- the simulated machine (not the manual's) -----------------------------------------------------------------------
def machine():
    """A GE-400-PV card (4 axes, 200 us servo period, the GT-lineage servo law with the GE's fractional gains):
    velocity-mode servo drives, 10000-count encoders, 50 pulse/ms per volt (the speed mode of L1000)."""
    import servobench as sb

    card = sb.Card(4, law=sb.GtServoLaw(fractional_gains=True), drive=sb.VelocityDrive(), servo_period_s=200e-6)
    card.set_clock("program")
    return card


if __name__ == "__main__":
    use_machine(machine)
    main()
