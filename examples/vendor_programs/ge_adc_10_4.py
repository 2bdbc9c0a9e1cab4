"""GE manual (seed 001) Example 10-4 "读取通道 1 的模拟电压输入" (read the analog voltage input of channel 1),
L2896-2920, with the conversion of Table 10-4 (L2930-2937).

What it does: opens and resets the controller, reads channel 1 with GT_GetAdc and prints its value (or "Command
Error !" when the call fails), closes the controller.

The manual's result (Table 10-4): the value read is the input voltage as 12-bit counts, +10 V = 2047, 0 V = 0,
-10 V = -2048; GT_GetAdc returns 0.

C -> Python changes (syntax only): ``GT_GetAdc(1, &voltage)`` returns ``(rtn, voltage)``; ``printf`` is ``out``
(the program's printed lines, for the test).
"""

from servobench.dialects.ge import GT_Close, GT_GetAdc, GT_Open, GT_Reset, use_machine

out: list = []  # what the program printed


def main():
    GT_Open()  # open the motion controller
    GT_Reset()  # reset the motion controller
    rtn, voltage = GT_GetAdc(1)
    if 0 == rtn:  # read the analog voltage of channel 1
        out.append(f"\n Channel 1 Voltage : {voltage}")  # print the analog voltage of channel 1
    else:
        out.append("\nCommand Error !")
    GT_Close()  # close the motion controller


# -- the simulated machine (not the manual's) -----------------------------------------------------------------------
CHANNEL_1_VOLTS = 5.0   # the sensor wired to analog input 1


def machine():
    """A GE-400-PV card with the optional A/D inputs; 5 V on channel 1."""
    import servobench as sb
    from servobench import card_io

    card = sb.Card(4, law=sb.GtServoLaw(fractional_gains=True), drive=sb.VelocityDrive(), servo_period_s=200e-6)
    card_io.of(card).adc_volts[0] = CHANNEL_1_VOLTS
    card.set_clock("program")
    return card


if __name__ == "__main__":
    use_machine(machine)
    main()
    print(*out)
