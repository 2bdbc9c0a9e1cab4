"""The GT manual's (seed 000) initialisation functions that its example programs call, shared by the gt_*
programs here: the return-value function of Sample 2-1 (L430-452), GTInitial of Example 3-3 (PCI card, L528-543),
InputCfg of Example 3-4 (L595-619), AxisInitial of Example 3-6 (SV card, L697-742), and the simulated machine they
run against (two GT-400-SV cards in one PC; not the manual's).

GTInitial opens the PCI card(s), resets, makes card No. 1 current, sets the 200 us sample time and masks every
axis's interrupts; InputCfg sets the limit switches high-level triggered and reverses the encoders of axes 1-4;
AxisInitial: axis 1 closed loop (Kp 20, Kd 10, bias 10), axis 2 open loop, axes 3 and 4 pulse output (pulse +
direction, CW/CCW pulses).

C -> Python changes (syntax only): ``GT_SetSmpl Tm`` (L539, a line break in the print) is ``GT_SetSmplTm``;
``for(int i=1; i<5; i++;)`` is ``for i in range(1, 5)``; the comments "Set to output analog amount" on the
CtrlMode(1) lines are the manual's (1 = pulse output, L760-766).
"""

import math

import servobench as sb
from servobench import card_io
from servobench.dialects.gt import (GT_Axis, GT_AxisOn, GT_ClrSts, GT_CloseLp, GT_CtrlMode, GT_EncSns, GT_LmtSns,
                                    GT_Open, GT_OpenLp, GT_Reset, GT_SetIntrMsk, GT_SetKaff, GT_SetKd, GT_SetKi,
                                    GT_SetKp, GT_SetKvff, GT_SetMtrBias, GT_SetSmplTm, GT_StepDir, GT_StepPulse,
                                    GT_SwitchtoCardNo, GT_Update)


def error(rtn):
    """Sample 2-1 (L430-452): prints the meaning of a return value."""
    if rtn == -1:
        print("error: communication error")
    elif rtn == 0:
        pass  # no error, continue
    elif rtn == 1:
        print("error: command error")
    elif rtn in (2, 3, 4, 5, 7):
        print("error: parameter error")
    elif rtn == 6:
        print("error: map is error")


def GTInitial():
    """Example 3-3 (L528-543): initialization of the motion control card (PCI card)."""
    rtn = GT_Open(); error(rtn)  # Open the motion controller.
    rtn = GT_Reset(); error(rtn)  # Reset motion controller.
    # Set No. 1 card as the current card (only for multi-card system, and this line can be cancelled for
    # single-card system).
    rtn = GT_SwitchtoCardNo(1); error(rtn)
    rtn = GT_SetSmplTm(200); error(rtn)  # Set control period as 200us.
    for i in range(1, 5):  # Screen each axis interrupt.
        rtn = GT_Axis(i)
        rtn = GT_SetIntrMsk(0)


def InputCfg():
    """Example 3-4 (L595-619): parameters of the dedicated input signals."""
    LmtSense = 0  # set the parameter of limit switch as high-level triggering.
    EncSense = 0xF  # Opposite the direction of 1-4 axes encoders to original direction, 1 and 2 auxiliary
    # encoder keep the original direction.
    rtn = GT_LmtSns(LmtSense); error(rtn)  # Specify 1-4 axes positive and negative limit switches as high-level
    # triggering.
    rtn = GT_EncSns(EncSense); error(rtn)  # Specify the direction of encoder.


def AxisInitial():
    """Example 3-6 (L697-742): initialization of the control axes (SV card)."""
    rtn = GT_Axis(1); error(rtn)  # Set the first axis as current axis.
    rtn = GT_ClrSts(); error(rtn)  # Clear the wrong status of current axis.
    rtn = GT_CtrlMode(0); error(rtn)  # Set to output analog amount.
    rtn = GT_CloseLp(); error(rtn)  # Set as close loop control.
    rtn = GT_SetKp(20); error(rtn)  # Set percentage gain as 20.
    rtn = GT_SetKi(0); error(rtn)  # Set integral gain as 0.
    rtn = GT_SetKd(10); error(rtn)  # Set differential gain as 10.
    rtn = GT_SetKvff(0); error(rtn)  # Set velocity feedback as 0.
    rtn = GT_SetKaff(0); error(rtn)  # Set acceleration feedback as 0.
    rtn = GT_SetMtrBias(10); error(rtn)  # Set output zero point excursion as 10.
    rtn = GT_Update(); error(rtn)  # Update parameter (Validate parameter).
    rtn = GT_AxisOn(); error(rtn)  # Activate drive.

    rtn = GT_Axis(2); error(rtn)  # Set the second axis as current axis.
    rtn = GT_ClrSts(); error(rtn)  # Clear the wrong status of current axis.
    rtn = GT_CtrlMode(0); error(rtn)  # Set to output analog amount.
    rtn = GT_OpenLp(); error(rtn)  # Set as close loop control.
    rtn = GT_AxisOn(); error(rtn)  # Activate drive.

    rtn = GT_Axis(3); error(rtn)  # Set the third axis as current axis.
    rtn = GT_ClrSts(); error(rtn)  # Clear the wrong status of current axis.
    rtn = GT_CtrlMode(1); error(rtn)  # Set to output analog amount.
    rtn = GT_StepDir(); error(rtn)  # Set to output pulse + direction signal.
    rtn = GT_AxisOn(); error(rtn)  # Activate drive.

    rtn = GT_Axis(4); error(rtn)  # Set the fourth axis as current axis.
    rtn = GT_ClrSts(); error(rtn)  # Clear the wrong status of current axis.
    rtn = GT_CtrlMode(1); error(rtn)  # Set to output analog amount.
    rtn = GT_StepPulse(); error(rtn)  # Set to output positive and negative pulse signal.
    rtn = GT_AxisOn(); error(rtn)  # Activate drive.


# -- the simulated machine (not the manual's) -----------------------------------------------------------------------
COUNTS_PER_REV = 8000                       # encoder counts per motor revolution (pulse)
HOME_EDGE, HOME_END = 30000, 40000          # the Home switch of axis 1, load position, pulse
INDEX_AT = 2000                             # the encoder's index mark, counts into each revolution


def machine() -> list:
    """Two GT-400-SV cards in one PC (card 1 is the program's): axes 1-2 analog speed-mode servo drives, axes
    3-4 pulse-input drives; encoders of axes 1-4 wired to count against the motors (as InputCfg corrects); axis 1
    has its Home switch from 30000 to 40000 pulse and an 8000-count encoder with its index at count 2000."""
    rad = 2 * math.pi / COUNTS_PER_REV
    cards = []
    for _ in range(2):
        # a stiff speed-mode servo drive: 300 rad/s per volt, speed loop 1 N*m*s/rad, 200 N*m/rad
        drive = sb.VelocityDrive(speed_per_volt_rad_s=300.0, kp_nms=1.0, ki_nm_per_rad=200.0)
        analog: dict = dict(law=sb.GtServoLaw(), drive=drive, servo_period_s=200e-6,
                      encoder=sb.Encoder(counts_per_rev=COUNTS_PER_REV, index_angle_rad=INDEX_AT * rad))
        axes = [sb.Axis(switches=sb.Switches(home_min_rad=HOME_EDGE * rad, home_max_rad=HOME_END * rad), **analog),
                sb.Axis(**analog),
                sb.Axis(drive=sb.ServoPositionDrive(), servo_period_s=200e-6),
                sb.Axis(drive=sb.StepperDrive(), servo_period_s=200e-6)]
        card = sb.Card(axes)
        card_io.of(card).encoder_reversed = 0xF
        card.set_clock("program")
        cards.append(card)
    return cards
