"""iDEABOX manual (seed 003) §4.2.3 例程 4-2 "FollowEx Complete 描述方式" (FollowEx, Complete data), L746-929:
the master (axis 1) jogs at 50 pulse/ms; the slave (axis 2) in FollowEx mode (FIFO of 512 segments) follows the
master's planned position along a C2 spline through 15 knots (lrMPos, lrSPos, cumulative from the follow start; the
first knot is the curve start, decision M31) with velocity ratio 1.0 at both ends; infinite loop; start event
START: the slave follows as soon as the master starts (L748-750).

What the manual says (L748-750): the slave follows at once; along the knots: when the master has travelled
lrMPos[k] - lrMPos[0], the slave has moved lrSPos[k] - lrSPos[0] (80000 per knot), 1120000 per pass of 1132347.6
master pulses, starting and ending at the master's speed (ratio 1.0).

C -> Python (syntax only): as ideabox_followex_percent.py (one PLC task cycle, ``xStart`` TRUE, out-parameters
returned, ``SHL`` as ``<<``, ``rtn:=rtn:=`` (L857) one assignment, ``GT_Open()`` for the PLC runtime,
GT_LoadConfig returns 1 and the machine is configured as GTS800.cfg, GS11); the named arguments of
GT_FollowDataCompleteEx are Python keywords; ``profile:= iSlave`` (L875, a misprint: iSlave is not declared) is
``Slave``; ``ADR(lrMPos[0])`` is the list.
"""

import servobench as sb
from servobench.dialects import gts
from servobench.dialects.gts import (FOLLOW_EVENT_START, FOLLOW_MASTER_PROFILE, GT_AxisOn, GT_ClrSts,
                                     GT_FollowClearEx, GT_FollowDataCompleteEx, GT_FollowSpaceEx, GT_FollowStartExMx,
                                     GT_GetJogPrm, GT_IsEcatReady, GT_LoadConfig, GT_Open, GT_PrfFollowEx, GT_PrfJog,
                                     GT_SetFollowEventEx, GT_SetFollowLoopEx, GT_SetFollowMasterEx,
                                     GT_SetFollowMemoryEx, GT_SetJogPrm, GT_SetVel, GT_UpdateMx, GT_ZeroPos)

lrMPos = [80413.3639047272, 157154.737891984, 234538.731662469,
          312552.345216181, 391204.578553119, 470496.431673285,
          550428.904576678, 630986.997263298, 712186.709733145,
          794025.041986219, 876494.994022521, 959612.56584205,
          1043352.7574448, 1127738.56883079, 1212761]
lrSPos = [40000, 120000, 200000, 280000, 360000,
          440000, 520000, 600000, 680000, 760000,
          840000, 920000, 1000000, 1080000, 1160000]


def main():
    xInitDone = False
    Master = 1
    Slave = 2
    xStart = True  # the operator's start (an input of the PLC program)
    lrPA = [0.0] * 15
    lrPB = [0.0] * 15
    lrPC = [0.0] * 15
    rtn = GT_Open()

    if not xInitDone:
        # check that EtherCAT is configured
        rtn, iEcatSts = GT_IsEcatReady()
        if iEcatSts != 1:
            return rtn
        # configure the motion controller
        # note: the configuration file switches off the alarms and limits of every axis
        strCfgPath = './GTS800.cfg'
        rtn = GT_LoadConfig(strCfgPath)
        # clear the alarms and limits of every axis
        rtn = GT_ClrSts(1, 8)
        # servo on
        rtn = GT_AxisOn(Master)
        rtn = GT_AxisOn(Slave)
        xInitDone = True

    if xStart and xInitDone:
        # zero the positions
        rtn = GT_ZeroPos(Master, 1)
        rtn = GT_ZeroPos(Slave, 1)
        # slave in FollowEx mode
        rtn = GT_PrfFollowEx(Slave, 0)
        # FollowEx buffer of 512 segments
        rtn = GT_SetFollowMemoryEx(Slave, 1)
        # empty the buffer
        rtn = GT_FollowClearEx(Slave, 0)
        # the master; by default the master's planned position
        rtn = GT_SetFollowMasterEx(Slave, Master, FOLLOW_MASTER_PROFILE, 0)
        # free space of the FollowEx FIFO
        rtn, diSpace = GT_FollowSpaceEx(Slave, 0)
        # add motion data to the FIFO
        rtn = GT_FollowDataCompleteEx(
            profile=Slave,           # profile axis
            fifo=0,                  # buffer
            n=15,                    # number of data
            pMasterSegment=lrMPos,   # master positions
            pSlaveSegment=lrSPos,    # slave positions
            pA=lrPA,                 # pA, pB, pC: internal work arrays, no values needed
            pB=lrPB,
            pC=lrPC,
            velRatioBegin=1.0,       # slave / master velocity ratio at the start
            velRatioEnd=1.0)         # slave / master velocity ratio at the end
        # infinite loop
        rtn = GT_SetFollowLoopEx(Slave, 0)
        # start condition of the following
        rtn = GT_SetFollowEventEx(Slave, FOLLOW_EVENT_START, 1, 0)
        # start the slave's FollowEx motion
        rtn = GT_FollowStartExMx(1, 1 << (Slave - 1), 0)
        # master in Jog mode
        rtn = GT_PrfJog(Master)
        # the master's motion parameters
        rtn, jogPrm = GT_GetJogPrm(Master)
        jogPrm.acc = 1
        rtn = GT_SetJogPrm(Master, jogPrm)
        rtn = GT_SetVel(Master, 50)
        # start the master
        rtn = GT_UpdateMx(1, 1 << (Master - 1))
        xStart = False
    return rtn


# -- the simulated machine (not the manual's): an iDEABOX Pro with 8 EtherCAT servo axes under the tuned GT law,
# 200 us servo period (the tuned law's), program-mode clock; alarms and limits off as the example's GTS800.cfg
# sets them (L822). ---------------------------------------------------------------------------------------------------
def machine() -> sb.Card:
    card = sb.Card(8, law=sb.GtServoLaw(kp=38, ki=60, kd=830, kaff=12870), servo_period_s=200e-6)
    for a in range(8):
        card.set_alarm_enabled(a, False)
        card.set_limits(a, card.limits(a).replace(enabled=False))
    card.set_clock("program")
    return card


if __name__ == "__main__":
    gts.use_machine(machine)
    print(main())
    gts.controller().run_ms(5000)
    print(gts.GT_GetPrfPos(1), gts.GT_GetPrfPos(2))
