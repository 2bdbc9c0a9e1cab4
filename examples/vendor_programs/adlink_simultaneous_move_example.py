"""ADLINK PCI-8254/8258 manual (seed 004), §4.9 (synchronized start), ``simultaneous_move_example()``, L3772-3790.

What it does: point-to-point moves of axis 0 to 10000 pulse and axis 1 to 20000 pulse, both with Option 0x100
(bit 8, MF_WAIT: "set to trigger start mode", L3782-3788), then ``APS_move_trigger(2, {0, 1})`` "sends the trigger
so that axes 0 and 1 start at the same time" (L3789).

What the manual says the result is: both axes wait for the trigger (MTS WAIT, L3669-3720) and then start
together; "movement of each axis is independent from each other and so the end time varies" (L2566): each reaches
its own target (10000 and 20000 pulse) with its own profile.

C -> Python changes (syntax only): declarations dropped; ``I32 axis_array[2] = { 0, 1 }`` -> a list; the Chinese
comments translated. ``main()`` opens the board (``APS_initial``; the example assumes it) and calls the example.
"""

from servobench.dialects.aps import *  # noqa: F401,F403 (APS168.h, APS_define.h, ErrorCodeDef.h)


def simultaneous_move_example():
    # This example shows how to execute a simultaneous move
    option = 0x100  # bit 8 = 1
    return_code = 0
    dimension = 2
    axis_array = [0, 1]

    return_code = APS_ptp(0, option, 10000, 0)  # axis 0 set to trigger-start mode
    return_code = APS_ptp(1, option, 20000, 0)  # axis 1 set to trigger-start mode
    return_code = APS_move_trigger(dimension, axis_array)  # send the trigger: axes 0 & 1 start at the same time
    return return_code


def main():
    APS_initial(0)  # the board, opened as every APS program does first (not printed in the example)
    return simultaneous_move_example()


# -- the simulated machine (not the manual's) -------------------------------------------------------------------
def machine():
    """A PCI-8254 (4 axes, servo period 250 us, L1733), rigid loads, servos on, the PRA_* motion parameters at
    the dialect's defaults (VM 1e5 pulse/s, ACC = DEC 1e6 pulse/s^2)."""
    import servobench as sb

    card = sb.Card(4, law=sb.ApsServoLaw(kp=38 * 1024, kd=830 * 32), servo_period_s=250e-6)
    for i in range(len(card)):
        card.axis_on(i)
    card.set_clock("program")
    return card


if __name__ == "__main__":
    use_machine(machine)
    main()
