"""ADLINK PCI-8254/8258 manual (seed 004), §4.4 Home Move, ``home_move_example()``, L2283-2326.

What it does: homes axis 0 in mode 0 (ORG signal), direction 1 (negative), T-curve, acceleration 1e6 pulse/s^2,
search speed 1e5 pulse/s, approach speed 5e4 pulse/s, no EZ alignment, no shift, HOME_POS 0 (L2295-2303); waits
with ``Sleep(100)`` while the "motion done bit" ``(msts >> MTS_NSTP) & 1`` reads 1 (L2312-2317); then reads ASTP
and, on an abnormal stop, the stop code (L2319-2326).

What the manual says the result is: after the home move the axis stops at the original position and the command
and feedback positions are reset to zero (HOME_POS, L2252, L2278); ASTP clear = homing success (L2319-2326). With
mode 0 and the negative direction, starting below the ORG switch the search reverses at MEL and ends at the ORG
edge on the PEL side (start case C, L2366-2372).

C -> Python changes (syntax only): ``I32 x;`` declarations dropped; ``&stop_code`` out-parameter ->
``_, stop_code = APS_get_stop_code(axis_id)``; ``do {...} while (c);`` -> ``while True: ... if not c: break``;
the empty C blocks ``{ /* Error handling */ }`` / ``{ // Homing success. }`` -> ``pass``; ``l32`` (an OCR slip for
I32, L2323) dropped. ``main()`` opens the board (``APS_initial``, which every APS program calls first; the manual's
example function assumes it) and calls the example.
"""

from servobench.dialects.aps import *  # noqa: F401,F403 (APS168.h, APS_define.h, ErrorCodeDef.h)


def home_move_example():
    # This example shows how home move operates
    axis_id = 0

    # 1. Select home mode and config home parameters
    APS_set_axis_param(axis_id, PRA_HOME_MODE, 0)  # Set home mode
    APS_set_axis_param(axis_id, PRA_HOME_DIR, 1)  # Set home direction
    APS_set_axis_param(axis_id, PRA_HOME_CURVE, 0)  # Set acceleration pattern (T-curve)
    APS_set_axis_param(axis_id, PRA_HOME_ACC, 1000000)  # Set homing acceleration rate
    APS_set_axis_param(axis_id, PRA_HOME_VM, 100000)  # Set homing maximum velocity.
    APS_set_axis_param(axis_id, PRA_HOME_VO, 50000)  # Set homing
    APS_set_axis_param(axis_id, PRA_HOME_EZA, 0)  # Set homing
    APS_set_axis_param(axis_id, PRA_HOME_SHIFT, 0)  # Set homing
    APS_set_axis_param(axis_id, PRA_HOME_POS, 0)  # Set homing

    # 2. Start home move
    return_code = APS_home_move(axis_id)  # Start homing
    if return_code != ERR_NoError:
        pass  # Error handling

    # 3. Wait for home move done,
    while True:
        Sleep(100)
        msts = APS_motion_status(axis_id)  # Get motion status
        msts = (msts >> MTS_NSTP) & 1  # Get motion done bit
        if not msts == 1:
            break

    # 4. Check home move success or not
    msts = APS_motion_status(axis_id)  # Get motion status
    msts = (msts >> MTS_ASTP) & 1  # Get abnormal stop bit
    if msts == 1:
        # Error handling ...
        _, stop_code = APS_get_stop_code(axis_id)
    else:
        pass  # Homing success.


def main():
    APS_initial(0)  # the board, opened as every APS program does first (not printed in the example)
    home_move_example()


# -- the simulated machine (not the manual's) -------------------------------------------------------------------
def machine():
    """A PCI-8254 (4 axes, servo period 250 us, L1733) whose axis 0 drives a rigid load, 10000 pulse/rev, with the
    ORG switch over 10000..14000 pulse, limits at +-50000 pulse and the index mark at 2500 pulse; the axis starts
    at 0 (below ORG: the manual's start case C) with its servo on, as the setup wizard leaves it."""
    import servobench as sb
    from servobench.homing import pulse_to_rad

    cpr = 10000
    card = sb.Card(4, law=sb.ApsServoLaw(kp=38 * 1024, kd=830 * 32), servo_period_s=250e-6,
                   switches=sb.Switches(home_min_rad=pulse_to_rad(10000, cpr),
                                        home_max_rad=pulse_to_rad(14000, cpr),
                                        neg_limit_rad=pulse_to_rad(-50000, cpr),
                                        pos_limit_rad=pulse_to_rad(50000, cpr)),
                   encoder=sb.Encoder(counts_per_rev=cpr, index_angle_rad=pulse_to_rad(2500, cpr)))
    for i in range(len(card)):
        card.axis_on(i)
    card.set_clock("program")
    return card


if __name__ == "__main__":
    use_machine(machine)
    main()
