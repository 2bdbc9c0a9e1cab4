"""ADLINK PCI-8254/8258 manual (seed 004), §4.5 Velocity Move, ``velocity_move_example()``, L2596-2630.

What it does (L2596-2603): sets PRA_STP_DEC, PRA_CURVE (S-factor 0.5), PRA_ACC and PRA_DEC to 10000; starts a
velocity move of axis 0 at 500 pulse/s, changes the speed on the fly to 1000 pulse/s after 2 s and to 600 pulse/s
after 2 more seconds, and after 2 more seconds stops by deceleration (APS_stop_move, decelerating at PRA_STP_DEC,
L2570-2574).

What the manual says the result is: the axis runs at each speed in turn ("Change speed on the fly", L2620-2622)
and stops by deceleration at the end (L2603, L2627); the velocity move keeps updating the target and command
positions (L2634).

C -> Python changes (syntax only): declarations ``I32``/``F64`` dropped. ``main()`` opens the board
(``APS_initial``; the example assumes it) and calls the example.
"""

from servobench.dialects.aps import *  # noqa: F401,F403 (APS168.h, APS_define.h, ErrorCodeDef.h)


def velocity_move_example():
    axis_id = 0
    speed_1 = 500.0
    speed_2 = 1000.0
    speed_3 = 600.0

    APS_set_axis_param_f(axis_id, PRA_STP_DEC, 10000.0)
    APS_set_axis_param_f(axis_id, PRA_CURVE, 0.5)  # Set acceleration rate
    APS_set_axis_param_f(axis_id, PRA_ACC, 10000.0)  # Set acceleration rate
    APS_set_axis_param_f(axis_id, PRA_DEC, 10000.0)  # Set deceleration rate

    APS_vel(axis_id, 0, speed_1, 0)  # Start a velocity move
    Sleep(2000)  # Wait 2 second
    APS_vel(axis_id, 0, speed_2, 0)  # Change speed on the fly
    Sleep(2000)  # Wait 2 second
    APS_vel(axis_id, 0, speed_3, 0)  # Change speed on the fly
    Sleep(2000)  # Wait 2 second

    APS_stop_move(axis_id)  # Stop


def main():
    APS_initial(0)  # the board, opened as every APS program does first (not printed in the example)
    velocity_move_example()


# -- the simulated machine (not the manual's) -------------------------------------------------------------------
def machine():
    """A PCI-8254 (4 axes, servo period 250 us, L1733), rigid loads, no switches in the way, servos on."""
    import servobench as sb

    card = sb.Card(4, law=sb.ApsServoLaw(kp=38 * 1024, kd=830 * 32), servo_period_s=250e-6)
    for i in range(len(card)):
        card.axis_on(i)
    card.set_clock("program")
    return card


if __name__ == "__main__":
    use_machine(machine)
    main()
