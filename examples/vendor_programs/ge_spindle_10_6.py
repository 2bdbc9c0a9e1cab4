"""GE manual (seed 001) Example 10-6 "设定主轴转速" (set the spindle speed), L2999-3020, with GT_SetSpindleVel
(L5724-5734) and GT_CloseSpindle (L3885-3893).

What it does: opens and resets a GE-X00-SV controller, sets the spindle output to 32767 (full scale, +10 V) and
prints "GT_SetSpindleVel OK!", waits 10 s, switches the spindle output off and prints "GT_ CloseSpindle OK!",
closes the controller.

The manual's result (L5728): the spindle's 16-bit analog output, -32768..32767 for -10..+10 V, is +10 V for the
10 s, then off (0 V); both calls return 0.

C -> Python changes (syntax only): the SV card's library (``GeController("SX")``, as ``ges.h`` in Example 3-5
L741) gives the functions; the two ``if (0 == ...`` lines miss their ``)`` in the print (L3009, L3014);
``printf`` is ``out`` (the program's printed lines, for the test).
"""

from servobench.dialects.ge import GeController

lib = GeController("SX")  # the GE-X00-SX/SV library (ges.h)
GT_Open, GT_Reset, GT_Close, delay = lib.GT_Open, lib.GT_Reset, lib.GT_Close, lib.delay
GT_SetSpindleVel, GT_CloseSpindle = lib.GT_SetSpindleVel, lib.GT_CloseSpindle

out: list = []  # what the program printed


def main():
    GT_Open()  # open the motion controller
    GT_Reset()  # reset the motion controller
    if 0 == GT_SetSpindleVel(32767):  # set the spindle speed
        out.append("\n GT_SetSpindleVel OK!")
    delay(10000)  # wait 10 s
    if 0 == GT_CloseSpindle():  # switch the spindle off
        out.append("\n GT_ CloseSpindle OK!")
    GT_Close()  # close the motion controller


# -- the simulated machine (not the manual's) -----------------------------------------------------------------------
def machine():
    """A GE-400-SV card (4 axes, 200 us) whose spindle output drives the machine's spindle amplifier."""
    import servobench as sb

    card = sb.Card(4, law=sb.GtServoLaw(fractional_gains=True), drive=sb.VelocityDrive(), servo_period_s=200e-6)
    card.set_clock("program")
    return card


if __name__ == "__main__":
    lib.use_machine(machine)
    main()
    print(*out)
