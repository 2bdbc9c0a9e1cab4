"""ADLINK PCI-8254/8258 manual (seed 004), §4.10.6 Point Table Movement, ``pt_move_example()``, L3880-3911.

What it does: enables point table 0 for 2-D motion on axes 0 and 1 (L3893-3896), reads the table status
(L3898-3899), and if the point buffer is not full (``BitSts & 0x02``, L3901) pushes a line to (10000, 10000)
(L3903-3907), then starts the table (L3910).

What the manual says the result is: "The motion kernel program starts executing movement commands contained in
buffer points in sequence until interrupted or each buffer point has been executed" (L3870-3872): the axes move
along the line and stop at (10000, 10000) pulse; a table has 50 buffer points (L3796), so the first status shows
an empty, not full buffer.

C -> Python changes (syntax only): declarations dropped; ``PTLINE Prof; PTSTS Status;`` -> the dialect's
dataclasses; the ``&Status`` out-parameters -> returned tuples; ``&AxisArr`` -> the list; the example's
``if (...)`` without braces guards the whole indented block as its indentation shows (the OCR lost the braces of
the function too); ``APS_pt_start(Board_ID, PtblId, 0)`` keeps its third argument (the library's has two, the
dialect accepts both). ``main()`` opens the board (``APS_initial``; the example assumes it) and calls the example.
"""

from servobench.dialects.aps import *  # noqa: F401,F403 (APS168.h, APS_define.h, ErrorCodeDef.h)


def pt_move_example():
    # This example shows how pt move operation
    Board_ID = 0
    PtblId = 0  # Point table 0
    Dimension = 2  # 2D Dimension
    AxisArr = [0, 1]  # Set Axis 0 & Axis 1 to point table 0
    Prof = PTLINE()
    Status = PTSTS()

    # Enable point table id 0 for 2D dimension with aixe 0 and axis 1.
    APS_pt_enable(Board_ID, PtblId, Dimension, AxisArr)  # Enable point table id 0

    # Get status of point table id 0 to monitor buffer
    _, Status = APS_get_pt_status(Board_ID, PtblId)
    if not (Status.BitSts & 0x02):  # Point buffer is not full

        # Push move into point buffer
        Prof.Dim = 2
        Prof.Pos[0] = 10000
        Prof.Pos[1] = 10000
        ret, Status = APS_pt_line(Board_ID, PtblId, Prof)

    # Start point table move
    APS_pt_start(Board_ID, PtblId, 0)


def main():
    APS_initial(0)  # the board, opened as every APS program does first (not printed in the example)
    pt_move_example()


# -- the simulated machine (not the manual's) -------------------------------------------------------------------
def machine():
    """A PCI-8254 (4 axes, servo period 250 us, L1733), rigid loads, servos on; the table's speeds are the
    reference axis's PRA_* defaults (VM 1e5 pulse/s, ACC = DEC 1e6 pulse/s^2, decision AF6)."""
    import servobench as sb

    card = sb.Card(4, law=sb.ApsServoLaw(kp=38 * 1024, kd=830 * 32), servo_period_s=250e-6)
    for i in range(len(card)):
        card.axis_on(i)
    card.set_clock("program")
    return card


if __name__ == "__main__":
    use_machine(machine)
    main()
