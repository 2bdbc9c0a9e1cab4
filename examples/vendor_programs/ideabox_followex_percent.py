"""iDEABOX manual (seed 003) §4.2.3 例程 4-1 "FollowEx Percent 描述方式" (FollowEx, Percent data), L556-742: the
master (axis 1) jogs at 50 pulse/ms; the slave (axis 2) in FollowEx mode follows the master's planned position
along Table 4-2 (L564-570): a first segment (master 20000, slave 10000, NORMAL, 60 % S), 1000 EVEN segments of
(20, 20) and a STOP segment (20000, 10000, 60 %), written as cumulative positions; infinite loop; start event PASS
at master 50000 in the positive direction.

What the manual says (L558-562): the slave starts following once the master has passed 50000 pulse; it accelerates
along an S curve, follows at the master's speed, and decelerates along an S curve: per pass (60000 master pulses)
the slave gains 10000 + 20000 + 10000 = 40000 pulse, and the passes repeat (loop 0 = infinite, L7302).

C -> Python (syntax only): the PLC program ``PLC_PRG`` runs one task cycle (``IF NOT xInitDone`` then ``IF xStart
AND xInitDone``; ``xStart``, the operator's start input, is TRUE); ``ADR(x)`` out-parameters are returned
(``rtn, iEcatSts = GT_IsEcatReady()``); ``RETURN`` leaves main; ``SHL(WORD#1, Slave-1)`` is ``1 << (Slave - 1)``;
``FOR idx := 2 TO 1001`` is ``range(2, 1002)``; ``rtn:=rtn:=`` (L661, a misprint) is one assignment; TJogPrmExt is
the dialect's dataclass; ``GT_Open()`` where the PLC runtime opens the controller. GT_LoadConfig('./GTS800.cfg')
returns 1 (the file's format is not given; decision GS11): the machine below is built as that file configures it
(alarms and limits off, L621-623); the program does not check that return code.
"""

import servobench as sb
from servobench.dialects import gts
from servobench.dialects.gts import (FOLLOW_EVENT_PASS, FOLLOW_MASTER_PROFILE, FOLLOW_SEGMENT_EVEN,
                                     FOLLOW_SEGMENT_NORMAL, FOLLOW_SEGMENT_STOP, GT_AxisOn, GT_ClrSts,
                                     GT_FollowClearEx, GT_FollowDataPercentEx, GT_FollowSpaceEx, GT_FollowStartEx,
                                     GT_GetJogPrm, GT_IsEcatReady, GT_LoadConfig, GT_Open, GT_PrfFollowEx, GT_PrfJog,
                                     GT_SetFollowEventEx, GT_SetFollowExMaxSegment, GT_SetFollowLoopEx,
                                     GT_SetFollowMasterEx, GT_SetFollowMemoryEx, GT_SetJogPrm, GT_SetVel,
                                     GT_UpdateMx, GT_ZeroPos)


def main():
    xInitDone = False
    Master = 1
    Slave = 2
    xStart = True  # the operator's start (an input of the PLC program)
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
        # before the FollowEx buffer is allocated dynamically, its maximum number of segments
        rtn = GT_SetFollowExMaxSegment(Slave, 5000)
        # dynamically allocated FollowEx buffer
        rtn = GT_SetFollowMemoryEx(Slave, 2)
        # empty the buffer
        rtn = GT_FollowClearEx(Slave, 0)
        # the master; by default the master's planned position
        rtn = GT_SetFollowMasterEx(Slave, Master, FOLLOW_MASTER_PROFILE, 0)
        # free space of the FollowEx FIFO
        rtn, diSpace = GT_FollowSpaceEx(Slave, 0)
        # add motion data to the FIFO
        masterPos = 20000
        slavePos = 10000
        rtn = GT_FollowDataPercentEx(Slave, masterPos, slavePos,
                                     FOLLOW_SEGMENT_NORMAL, 60, 0)
        # add many segments to the FIFO
        for idx in range(2, 1002):
            masterPos = masterPos + 20
            slavePos = slavePos + 20
            rtn = GT_FollowDataPercentEx(Slave, masterPos, slavePos,
                                         FOLLOW_SEGMENT_EVEN, 0, 0)
        # add the end segment to the FIFO
        masterPos = masterPos + 20000
        slavePos = slavePos + 10000
        rtn = GT_FollowDataPercentEx(Slave, masterPos, slavePos,
                                     FOLLOW_SEGMENT_STOP, 60, 0)
        # infinite loop
        rtn = GT_SetFollowLoopEx(Slave, 0)
        # start condition of the following
        rtn = GT_SetFollowEventEx(Slave, FOLLOW_EVENT_PASS, 1, 50000)
        # start the slave's FollowEx motion
        rtn = GT_FollowStartEx(1 << (Slave - 1), 0)
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
# sets them (L621). ---------------------------------------------------------------------------------------------------
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
    gts.controller().run_ms(3000)
    print(gts.GT_GetPrfPos(1), gts.GT_GetPrfPos(2))
