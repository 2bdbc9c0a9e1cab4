"""GUC-ECAT manual (seed 002) §4.1.2: "Establish coordinate system" (L736-768) followed by the "Linear
interpolation program" (L802-848): a 2-D coordinate system (synVelMax 500 pulse/ms, synAccMax 1 pulse/ms^2,
evenTime 50 ms, profile 1 -> X, 2 -> Y, origin at profile (100, 100)); seven lines at 100 pulse/ms and 0.1
pulse/ms^2 ending at rest, with buffered digital outputs (GT_BufIO 0x55 / 0xaa / 0x55) and buffered delays
(400 ms, 100 ms) between them; the crd starts on FIFO0 and GT_CrdStatus is read every PLC cycle.

What the manual says (L850-853, Fig 4-5): the seven segments run in order and draw a hexagon, vertices (200000, 0),
(100000, 173205), (-100000, 173205), (-200000, 0), (-100000, -173205), (100000, -173205) and back to (200000, 0)
(crd coordinates, pulse); the outputs and delays happen during the motion at their places in the FIFO; GT_CrdStatus
counts the segments completed (7 at the end, L855-857) and run is 1 while the crd moves.

C -> Python (syntax only): the Structured Text ``IF First THEN ... END_IF`` block runs once, the GT_CrdStatus read
after it every PLC cycle (one pass per task cycle) until run = 0; ``ADR(x)`` out-parameters are returned
(``rtn, run, segment = GT_CrdStatus(1, 0)``); TCrdPrm is the dialect's dataclass (``SysMemSet`` to 0 = its
defaults); ``16#55`` is ``0x55``; the OCR's ``GT LnXY`` / ``GT_BuflO`` are GT_LnXY / GT_BufIO; the ``rtn = ...``
lines (C assignments in the ST listing) are assignments; ``GT_Open()`` where the PLC runtime opens the controller.
"""

import servobench as sb
from servobench.dialects import gts
from servobench.dialects.gts import (MC_GPO, GT_AxisOn, GT_BufDelay, GT_BufIO, GT_CrdClear, GT_CrdSpace, GT_CrdStart,
                                     GT_CrdStatus, GT_LnXY, GT_Open, GT_SetCrdPrm, TCrdPrm)

TASK_CYCLE_MS = 1.0  # the PLC task's cycle (OtoStudio task configuration; the example does not give it)


def main():
    rtn = GT_Open()
    # -- Example: establish coordinate system (L741-768) --
    crdPrm = TCrdPrm()                # Define the structure variable for coordinate system; initialize to 0
    crdPrm.dimension = 2              # two-dimensional coordinate system
    crdPrm.synVelMax = 500            # Maximum resultant velocity: 500 pulse/ms
    crdPrm.synAccMax = 1              # Maximum resultant acceleration: 1 pulse/ms^2
    crdPrm.evenTime = 50              # Smooth time: 50 ms
    crdPrm.profile[0] = 1             # map profiler1 to X-axis
    crdPrm.profile[1] = 2             # map profiler2 to Y-axis
    crdPrm.setOriginFlag = 1          # Specify origin
    crdPrm.originPos[0] = 100
    crdPrm.originPos[1] = 100
    rtn = GT_SetCrdPrm(1, crdPrm)     # Establish coordinate system 1 and set parameters

    # -- Linear interpolation program (L802-848) --
    First = True
    while True:  # once per PLC task cycle
        if First:
            rtn = GT_AxisOn(1)
            rtn = GT_AxisOn(2)
            rtn = GT_CrdClear(1, 0)                      # clear the data in FIFO0 of coordinate 1
            # The first Crd data
            rtn = GT_LnXY(1, 200000, 0, 100, 0.1, 0, 0)  # transfer linear interpolation data to FIFO0 of crd 1
            # Coordinate of end-point: (200000,0); target velocity: 100 pulse/ms; acceleration: 0.1 pulse/ms^2;
            # velocity at end-point: 0
            # The second Crd data
            rtn = GT_LnXY(1, 100000, 173205, 100, 0.1, 0, 0)
            # buffer digital output
            rtn = GT_BufIO(1, MC_GPO, 0xffff, 0x55, 0)   # Type of digital output: general purpose
            # All the bit0~bit15 output; Output value is 0x55
            # The third Crd data
            rtn = GT_LnXY(1, -100000, 173205, 100, 0.1, 0, 0)
            # buffer digital output
            rtn = GT_BufIO(1, MC_GPO, 0xffff, 0xaa, 0)
            # The fourth Crd data
            rtn = GT_LnXY(1, -200000, 0, 100, 0.1, 0, 0)
            # buffer delay
            rtn = GT_BufDelay(1, 400, 0)                 # delay 400 ms
            # The fifth Crd data
            rtn = GT_LnXY(1, -100000, -173205, 100, 0.1, 0, 0)
            # buffer digital output
            rtn = GT_BufIO(1, MC_GPO, 0xffff, 0x55, 0)
            # buffer delay
            rtn = GT_BufDelay(1, 100, 0)
            # The sixth Crd data
            rtn = GT_LnXY(1, 100000, -173205, 100, 0.1, 0, 0)
            # The seventh Crd data
            rtn = GT_LnXY(1, 200000, 0, 100, 0.1, 0, 0)
            rtn, space = GT_CrdSpace(1, 0)               # Get free space of FIFO0 of coordinate system1
            rtn = GT_CrdStart(1, 0)                      # Start Crd motion of FIFO0 of coordinate system1
            First = False
        # The value of run is 1 if the coordinate system is in motion
        rtn, run, segment = GT_CrdStatus(1, 0)
        if not run:  # (not in the manual: the PLC task runs on; the example is done when the path is)
            return rtn, run, segment, space
        gts.controller().run_ms(TASK_CYCLE_MS)  # the PLC task cycle passes


# -- the simulated machine (not the manual's): a GUC-800, 8 servo axes under the tuned GT law, 1 ms servo
# period, program-mode clock. The manual's example has no switches; none are placed. -------------------------------
def machine() -> sb.Card:
    card = sb.Card(8, law=sb.GtServoLaw(kp=38, ki=60, kd=830, kaff=12870), servo_period_s=200e-6)
    card.set_clock("program")
    return card


if __name__ == "__main__":
    gts.use_machine(machine)
    print(main())
