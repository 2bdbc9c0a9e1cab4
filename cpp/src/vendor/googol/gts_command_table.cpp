// The GTS command table (vendor/googol/gts_commands.hpp): one row per GUC-ECAT / iDEABOX function that
// servobench.dialects.gts generates, with the manual's description (units, lines) that becomes the Python function's
// docstring (decision GX2; the docstrings were moved verbatim from the dialect by a script). Rows in the dialect's
// order: profiles, stops, coordinate systems and PVT downloads; the basic axis calls; paths and buffered commands;
// PVT; FollowEx; the system configuration, stop inputs, read-backs, velocity filters and EtherCAT calls.
#include "servobench/vendor/googol/gts_commands.hpp"

namespace servobench::vendor::googol {

const std::vector<GtsCommandRow>& gts_command_table() {
  static const std::vector<GtsCommandRow> rows = {
    {"GT_SetTrapPrm", "profile, acc, dec=None, velStart=0, smoothTime=0", "",
     "TTrapPrm acc (and dec), pulse/ms^2 > 0, as scalars or a :class:`TTrapPrm` as ``acc`` (GUC L2898-2908 reads "
     "it with GT_GetTrapPrm and writes it back). One acceleration for both ramps: dec is taken equal to acc "
     "(decision V61); velStart and smoothTime must be 0."},
    {"GT_SetJogPrm", "profile, acc, dec=None, smooth=0", "",
     "Jog acc (dec taken equal, V61), pulse/ms^2 > 0, smooth 0..1 (recorded, GS17): scalars or a "
     ":class:`TJogPrmExt` as ``acc`` (iDEABOX Ex 4-1 L726-730)."},
    {"GT_Stop", "mask, option=0", "",
     "Stops the masked axes (bit k = axis k+1) and coordinate systems (bit 12 = crd 1, 13 = crd 2, iDEABOX "
     "L1793); option bit set = abrupt, clear = smooth (at the GT_SetStopDec deceleration, GS7). A stopped crd "
     "keeps its breakpoint (resume with GT_CrdStart)."},
    {"GT_SetCrdPrm", "crd, prm: TCrdPrm", "",
     "Sets up coordinate system ``crd`` (1..2) from a :class:`TCrdPrm` (GUC L369-388, L736-792; iDEABOX "
     "L7095-7176). 7 for values out of range or a profile mapped twice (L785); 1 while a mapped axis moves or is "
     "in the other crd (L743, L7168-7174)."},
    {"GT_GetCrdPrm", "crd", "(None,)",
     "(rtn, TCrdPrm) of ``crd``; (1, 0) when it is not set up."},
    {"GT_InitLookAhead", "crd, fifo, T, accMax, n, pLookAheadBuf=None", "",
     "Look-ahead on a FIFO: corner time T (0, 1000] ms, accMax (0, 32767] pulse/ms^2, window n 0..32766 segments "
     "(0 = off) (GUC L725-732, L908-995; iDEABOX L5848-5879). The buffer argument is not used."},
    {"GT_CrdData", "crd, pCrdData=None, fifo=0", "",
     "With pCrdData None (NULL): moves the look-ahead window into the FIFO; 1 when the FIFO filled first (call "
     "again after GT_CrdSpace) (GUC L975-977; iDEABOX L4465-4498). Raw TCrdData records: not simulated (7)."},
    {"GT_PvtTable", "tableId, count, pTime, pPos, pVel", "",
     "PVT data, the first ``count`` points (ms, pulse, pulse/ms), replaces table 1..32 (GUC L1169; iDEABOX L6404)."},
    {"GT_PvtTableEx", "tableId, count, pTime, pPos, pVelBegin, pVelEnd", "",
     "PVT-Ex data with a begin and an end velocity per point, pulse/ms (iDEABOX L6446-6472)."},
    {"GT_PvtTableComplete", "tableId, count, pTime, pPos, pA=None, pB=None, pC=None, velBegin=0, velEnd=0", "",
     "Complete data (t ms, p pulse) with velBegin / velEnd pulse/ms: C2 spline (GUC L1181-1191; iDEABOX L6585). "
     "pA/pB/pC are the manual's work arrays (not used)."},
    {"GT_PvtTablePercent", "tableId, count, pTime, pPos, pPercent, velBegin=0", "",
     "Percent data: times ms, positions pulse, percent 0..100 (GUC L1436-1457; iDEABOX L6931)."},
    {"GT_PvtPercentCalculate", "count, pTime, pPos, pPercent, velBegin=0", "(None,)",
     "(rtn, node velocities pulse/ms) of Percent data, nothing downloaded; (7, None) for bad data (GUC L1436; "
     "iDEABOX L6259)."},
    {"GT_PvtTableContinuous", "tableId, count, pPos, pVel, pPercent, pVelMax, pAcc, pDec, timeBegin=0", "",
     "Continuous data (p pulse, v pulse/ms, percent, vMax pulse/ms, acc/dec pulse/ms^2 per point), start at "
     "timeBegin ms (GUC L1475-1504; iDEABOX L6690)."},
    {"GT_PvtTableContinuousEx",
     "tableId, count, pPos, pVel, pAccPercent, pDecPercent, pVelMax, pAcc, pDec, timeBegin=0", "",
     "Continuous-Ex data: as GT_PvtTableContinuous with separate S shares (0..100) for the acceleration and the "
     "deceleration phase of each segment (iDEABOX L6745-6803)."},
    {"GT_PvtContinuousCalculate", "count, pPos, pVel, pPercent, pVelMax, pAcc, pDec", "(None,)",
     "(rtn, point times ms, time[0] = 0) of Continuous data; (7, None) for bad data (GUC L1230; iDEABOX "
     "L6222-6251)."},
    {"GT_AxisOn", "axis", "",
     "Enables the drive of ``axis`` (1..)."},
    {"GT_AxisOff", "axis", "",
     "Disables the drive of ``axis``."},
    {"GT_ClrSts", "axis, count=1", "",
     "Clears the latched status of ``count`` axes from ``axis`` (iDEABOX L629)."},
    {"GT_ZeroPos", "axis, count=1", "",
     "Actual (encoder) = target = profile position = 0 on ``count`` axes from ``axis`` (pulse), the mechanism "
     "unmoved (iDEABOX L647/L848; the Googol meaning, GT L5196-5206, GE L5907-5913; decision VF3): at rest only. "
     "1 with nothing changed if any of the axes moves, runs a sequence, or is in gear or a crd; 7 for a bad axis "
     "or count."},
    {"GT_GetSts", "axis, count=1", "(0,)",
     "(rtn, status) of ``axis``: the card's status word (GT layout; bit 10 = 0x400 the profile moves, the only "
     "bit the GUC seed uses, L2643-2645; decision V60)."},
    {"GT_GetPrfPos", "profile, count=1", "(0.0,)",
     "(rtn, profile position, pulse)."},
    {"GT_GetPrfVel", "profile, count=1", "(0.0,)",
     "(rtn, profile velocity, pulse/ms); with GT_SetAxisPrfVelFilter the mean over the last 2^exp ticks (iDEABOX "
     "L3801; GS9)."},
    {"GT_GetEncPos", "axis, count=1", "(0.0,)",
     "(rtn, encoder (actual) position, pulse)."},
    {"GT_PrfTrap", "profile", "",
     "Point-to-point (trapezoid) mode (refused while moving)."},
    {"GT_PrfJog", "profile", "",
     "Jog mode (refused while moving)."},
    {"GT_SetVel", "profile, vel", "",
     "Target velocity, pulse/ms (signed in jog mode) (staged)."},
    {"GT_SetPos", "profile, pos", "",
     "Target position, pulse (staged)."},
    {"GT_Update", "mask", "",
     "Starts the staged motion of the masked axes (bit k = axis k+1)."},
    {"GT_LnXY", "crd, x, y, synVel, synAcc, velEnd=0, fifo=0", "",
     "Line to (x, y) absolute, pulse; synVel pulse/ms, synAcc pulse/ms^2, velEnd (ignored under look-ahead) (GUC "
     "L449-481; iDEABOX L5881)."},
    {"GT_LnXYZ", "crd, x, y, z, synVel, synAcc, velEnd=0, fifo=0", "",
     "3-D line (iDEABOX L5975)."},
    {"GT_LnXYZA", "crd, x, y, z, a, synVel, synAcc, velEnd=0, fifo=0", "",
     "4-D line (iDEABOX L6026); no look-ahead on a 4-D crd (7)."},
    {"GT_LnXYG0", "crd, x, y, synVel, synAcc, fifo=0", "",
     "G0 line: ends at rest even under look-ahead (GUC L322-327, iDEABOX L1594-1606)."},
    {"GT_LnXYZG0", "crd, x, y, z, synVel, synAcc, fifo=0", "",
     "3-D G0 line."},
    {"GT_LnXYZAG0", "crd, x, y, z, a, synVel, synAcc, fifo=0", "",
     "4-D G0 line."},
    {"GT_ArcXYR", "crd, x, y, radius, circleDir, synVel, synAcc, velEnd=0, fifo=0", "",
     "XY arc to the end point with radius (> 0: <= 180 deg, < 0: > 180 deg), circleDir 0 CW / 1 CCW; 7 when no "
     "such arc exists (GUC L509-587, L892, L906; iDEABOX L3874)."},
    {"GT_ArcYZR", "crd, y, z, radius, circleDir, synVel, synAcc, velEnd=0, fifo=0", "",
     "YZ arc to the end point with radius (> 0: <= 180 deg, < 0: > 180 deg), circleDir 0 CW / 1 CCW; 7 when no "
     "such arc exists (GUC L509-587, L892, L906; iDEABOX L4002)."},
    {"GT_ArcZXR", "crd, z, x, radius, circleDir, synVel, synAcc, velEnd=0, fifo=0", "",
     "ZX arc to the end point with radius (> 0: <= 180 deg, < 0: > 180 deg), circleDir 0 CW / 1 CCW; 7 when no "
     "such arc exists (GUC L509-587, L892, L906; iDEABOX L4131)."},
    {"GT_ArcXYC", "crd, x, y, xCenter, yCenter, circleDir, synVel, synAcc, velEnd=0, fifo=0", "",
     "XY arc to the end point about the centre offset from the start; end = start is a full circle (GUC L904; "
     "iDEABOX L3812)."},
    {"GT_ArcYZC", "crd, y, z, yCenter, zCenter, circleDir, synVel, synAcc, velEnd=0, fifo=0", "",
     "YZ arc to the end point about the centre offset from the start; end = start is a full circle (GUC L904; "
     "iDEABOX L3941)."},
    {"GT_ArcZXC", "crd, z, x, zCenter, xCenter, circleDir, synVel, synAcc, velEnd=0, fifo=0", "",
     "ZX arc to the end point about the centre offset from the start; end = start is a full circle (GUC L904; "
     "iDEABOX L4070)."},
    {"GT_BufIO", "crd, doType, doMask, doValue, fifo=0", "",
     "Buffered digital output: MC_GPO / MC_ENABLE / MC_CLEAR, bits of doValue where doMask is 1 (GUC L588-597)."},
    {"GT_BufDelay", "crd, delayTime, fifo=0", "",
     "Buffered dwell, ms, 0..16383 (GUC L598-602)."},
    {"GT_BufDA", "crd, chn, daValue, fifo=0", "",
     "Buffered analog output, channel 1..8, -32768..32767 (GUC L603-608)."},
    {"GT_BufLmtsOn", "crd, axis, limitType=-1, fifo=0", "",
     "Buffered limit enable: limitType 0 positive, 1 negative, -1 both (GUC L609-624)."},
    {"GT_BufLmtsOff", "crd, axis, limitType=-1, fifo=0", "",
     "Buffered limit disable: limitType 0 positive, 1 negative, -1 both (GUC L609-624)."},
    {"GT_BufSetStopIo", "crd, axis, stopType, inputType, inputIndex, fifo=0", "",
     "Buffered stop-input mapping: stopType 0 emergency / 1 smooth, inputType 0..4, index 1..8 (GPI 1..16) (GUC "
     "L625-645)."},
    {"GT_BufMove", "crd, moveAxis, pos, vel, acc, modal, fifo=0", "",
     "Buffered point-to-point move of an axis outside the crd to the absolute ``pos`` (pulse) at vel (pulse/ms) "
     "and acc (pulse/ms^2); modal 1 blocks the FIFO until it ends (GUC L646-656, L1052-1055)."},
    {"GT_BufGear", "crd, gearAxis, pos, fifo=0", "",
     "Buffered follow of the next segment by an axis outside the crd over the relative ``pos`` (pulse) (GUC "
     "L657-661, L1058-1060)."},
    {"GT_SetUserSegNum", "crd, segNum, fifo=0", "",
     "Buffered user segment number (GUC L662-665)."},
    {"GT_GetUserSegNum", "crd, fifo=0", "(0,)",
     "(rtn, user segment number) (GUC L666-670)."},
    {"GT_GetRemainderSegNum", "crd, fifo=0", "(0,)",
     "(rtn, segments not finished) (GUC L671-675)."},
    {"GT_CrdSpace", "crd, fifo=0", "(0,)",
     "(rtn, free FIFO entries) (GUC L979)."},
    {"GT_CrdClear", "crd, fifo=0", "",
     "Clears a FIFO and its segment count (refused while it moves) (GUC L697-699, L855-857)."},
    {"GT_CrdStart", "mask, option=0", "",
     "Starts (or resumes) the masked crds (bit 0 crd 1, bit 1 crd 2) on FIFO0 or, option bit set, FIFO1; 1 when a "
     "crd is not set up, the other FIFO moves, FIFO0 resumes away from its breakpoint (GUC L1005, iDEABOX L4560) "
     "or the e-stop / an alarm is active (GUC L684-690; iDEABOX L4527-4566)."},
    {"GT_CrdStatus", "crd, fifo=0", "(0, 0)",
     "(rtn, run, segment): run 1 while the FIFO interpolates, segment = segments completed since the crd was set "
     "up or cleared (GUC L692-700; iDEABOX L4574-4599)."},
    {"GT_SetOverride", "crd, synVelRatio", "",
     "Feed override (0, 1] (GUC L701-703; iDEABOX L7419-7441)."},
    {"GT_SetCrdStopDec", "crd, decSmoothStop, decAbruptStop", "",
     "Path stop decelerations, (0, 32767) pulse/ms^2 each (GUC L704-709; iDEABOX L7182-7201)."},
    {"GT_GetCrdPos", "crd", "([],)",
     "(rtn, [dimension] crd coordinates, pulse) (GUC L5499-5519; crd = profile - origin)."},
    {"GT_GetCrdVel", "crd", "(0.0,)",
     "(rtn, path speed, pulse/ms) (iDEABOX L5581-5595)."},
    {"GT_PrfPvt", "profile", "",
     "PVT mode (refused while moving) (GUC L1141; iDEABOX L6201)."},
    {"GT_PvtTableSelect", "profile, tableId", "",
     "Selects the table (at rest at once, while moving at the end of the pass); 1 on an empty table (GUC L1279, "
     "L1308; iDEABOX L7030-7048)."},
    {"GT_SetPvtLoop", "profile, loop", "",
     "Passes, 0 = infinite (GUC L1150, L1312; iDEABOX L7443)."},
    {"GT_GetPvtLoop", "profile", "(0, 0)",
     "(rtn, passes done, loop setting) (GUC L1156-1159; iDEABOX L5765-5779)."},
    {"GT_PvtStart", "mask", "",
     "Starts the masked axes (bit k = axis k+1) on the same tick; 1 on an empty table or an axis not in PVT mode "
     "(GUC L1279-1310; iDEABOX L6305-6321)."},
    {"GT_PvtStatus", "profile, count=1", "(0, 0.0)",
     "(rtn, table id, PVT time ms) (GUC L1285-1289; iDEABOX L6374-6390)."},
    {"GT_PrfFollowEx", "profile, dir=0", "",
     "FollowEx mode, dir 0 both master directions, 1 positive only, -1 negative only (L6173-6199). The master is "
     "axis 1 (axis 2 for profile 1) until GT_SetFollowMasterEx (decision V62)."},
    {"GT_SetFollowMasterEx", "profile, masterIndex, masterType=2, masterItem=0", "",
     "Master axis and signal: type 1 encoder, 2 profile, 3 axis (item 0 planned / 1 encoder); masterIndex != "
     "profile (L7316-7363)."},
    {"GT_GetFollowMasterEx", "profile", "(0, 0, 0)",
     "(rtn, masterIndex, masterType, masterItem)."},
    {"GT_SetFollowMemoryEx", "profile, memory", "",
     "FIFO size: 0 16 segments, 1 512, 2 GT_SetFollowExMaxSegment (before any data, L489-514)."},
    {"GT_GetFollowMemoryEx", "profile", "(0,)",
     "(rtn, memory)."},
    {"GT_SetFollowExMaxSegment", "profile, maxsegment", "",
     "Dynamic FIFO size, 1..2147483647 (L497-501, L7254)."},
    {"GT_FollowClearEx", "profile, fifo=0", "",
     "Clears a FIFO (refused while it is in use) (L4612-4619)."},
    {"GT_FollowDataPercentEx", "profile, masterSegment, slaveSegment, type=0, percent=0, fifo=0", "",
     "One segment, cumulative master/slave positions from the follow start (decision M30), type NORMAL / EVEN / "
     "STOP / CONTINUE, percent 0..100; 1 when the FIFO is full (the data is lost, L532-534, L4740)."},
    {"GT_FollowDataCompleteEx",
     "profile, fifo, n, pMasterSegment, pSlaveSegment, pA=None, pB=None, pC=None, velRatioBegin=0.0, "
     "velRatioEnd=0.0", "",
     "Complete data: n knots (cumulative), clamped C2 spline with the end ratios (L4644-4677); pA/pB/pC are the "
     "manual's work arrays (not used)."},
    {"GT_FollowSpaceEx", "profile, fifo=0", "(0,)",
     "(rtn, free segments) (L4796)."},
    {"GT_SetFollowEventEx", "profile, event, masterDir=1, pos=0", "",
     "Start event: 1 START, 2 PASS (the master crosses pos moving in masterDir +-1) (L536-542, L7212-7240)."},
    {"GT_GetFollowEventEx", "profile", "(0, 0, 0)",
     "(rtn, event, masterDir, pos)."},
    {"GT_SetFollowLoopEx", "profile, loop", "",
     "Passes; < 1 = infinite (L7287-7302)."},
    {"GT_GetFollowLoopEx", "profile", "(0,)",
     "(rtn, completed passes) (L5649-5661)."},
    {"GT_FollowStartEx", "mask, option=0", "",
     "Starts the masked slaves (bit k = axis k+1) on FIFO 0 or, option bit set, FIFO 1 (L4827-4916); 1 for an "
     "axis not in FollowEx mode, already following, or with an empty FIFO."},
    {"GT_FollowSwitchEx", "mask", "",
     "Switches the masked slaves to their other FIFO at the end of the pass; only while moving, the other FIFO "
     "must hold data (L5196-5293)."},
    {"GT_AlarmOn", "axis", "",
     "The drive-alarm input of ``axis`` stops it and switches its drive off (default) (GUC L198, L215)."},
    {"GT_AlarmOff", "axis", "",
     "The drive-alarm input of ``axis`` is ignored (GUC L197, L213)."},
    {"GT_LmtsOn", "axis, limitType=-1", "",
     "Limit switches of ``axis`` stop it (default): limitType MC_LIMIT_POSITIVE 0, MC_LIMIT_NEGATIVE 1, -1 both "
     "(GUC L199, L217-222). One side alone only when the other side is already in that state (returns 1 "
     "otherwise, nothing changed: the card has one enable per axis, decision GS3)."},
    {"GT_LmtsOff", "axis, limitType=-1", "",
     "Limit switches of ``axis`` ignored (GUC L200, L223-228); one side alone as in GT_LmtsOn (GS3)."},
    {"GT_LmtSns", "sense", "",
     "Limit polarity, bit 2k axis k+1 positive, 2k+1 negative: 0 triggers on a high level (normally closed, "
     "default), 1 on a low level (GUC L294-305, Tab 3-4)."},
    {"GT_EncSns", "sense", "",
     "Encoder count direction, bit k = axis k+1 (bit 8 the auxiliary encoder), 1 = reversed (GUC L284-290, Tab "
     "3-3). The simulated encoder counts the drive's positive direction as positive: 0 bits are accepted, a set "
     "bit returns 1 (reversing it would turn the closed loop into positive feedback; GS4)."},
    {"GT_ProfileScale", "axis, alpha, beta", "",
     "Profile scale alpha/beta, each -32768..32767 (GUC L201, L232-235): 1:1 (alpha = beta) is the simulated "
     "axis; another ratio returns 1 (decision GS5)."},
    {"GT_EncScale", "axis, alpha, beta", "",
     "Encoder scale alpha/beta (GUC L202, L236-239): as GT_ProfileScale (GS5)."},
    {"GT_GpiSns", "sense", "",
     "General-input polarity, bit k = GPI k+1: 0 GT_GetDi reads the level, 1 the inverted level (GUC L206, "
     "L267-276)."},
    {"GT_GetDi", "diType", "(0,)",
     "(rtn, input word): MC_LIMIT_POSITIVE / MC_LIMIT_NEGATIVE bit k = the limit of axis k+1 triggers, MC_ALARM "
     "bit k = drive alarm of axis k+1, MC_GPI bit k = GPI k+1 after GT_GpiSns (GUC L206, L267-276). MC_HOME / "
     "MC_ARRIVE: 1 (not wired in the simulated machine, decision GS6)."},
    {"GT_SetAdcFilter", "adc, filterTime", "",
     "ADC input filter, adc 1..8, filterTime 1..50 (GUC L207, L278-280; GTS-400-PX only): the simulated card has "
     "no analog inputs: 1 (UNSUPPORTED); 7 for values out of range."},
    {"GT_SetStopDec", "profile, decSmoothStop, decAbruptStop", "",
     "Stop decelerations of ``profile``, (0, 32767] pulse/ms^2 each (GUC L203, L240-243): GT_Stop decelerates a "
     "point-to-point or jog axis at decSmoothStop (smooth) or decAbruptStop (abrupt option bit) instead of its "
     "acc / at once (decision GS7)."},
    {"GT_GetStopDec", "profile", "(0.0, 0.0)",
     "(rtn, decSmoothStop, decAbruptStop) pulse/ms^2 set by GT_SetStopDec; (0, 0) before (GUC L204, L244-247)."},
    {"GT_GetCrdStopDec", "crd", "(0.0, 0.0)",
     "(rtn, decSmoothStop, decAbruptStop) pulse/ms^2 of ``crd`` 1..2 set by GT_SetCrdStopDec; (0, 0) before (GUC "
     "L362, L710-712; iDEABOX L5551-5560)."},
    {"GT_SetStopIo", "axis, stopType, inputType, inputIndex", "",
     "Maps an input to a stop of ``axis`` 1..8: stopType 0 emergency / 1 smooth; inputType MC_LIMIT_POSITIVE, "
     "MC_LIMIT_NEGATIVE, MC_ALARM (index 1..8), MC_GPI (index 1..16) (GUC L205, L248-266). While the input is "
     "active the axis stops at its GT_SetStopDec decelerations (checked every tick, decision GS8). MC_HOME / "
     "MC_ARRIVE: 1 (not wired, GS6)."},
    {"GT_GetTrapPrm", "profile", "(None,)",
     "(rtn, TTrapPrm): acc = dec = the staged acceleration (pulse/ms^2; one acceleration for both ramps, decision "
     "V61), velStart 0, smoothTime 0 (GUC basic library; the combined-motion example L2900 reads it)."},
    {"GT_GetJogPrm", "profile", "(None,)",
     "(rtn, TJogPrmExt): acc = dec = the staged acceleration pulse/ms^2 (V61), smooth as set (iDEABOX Ex 4-1 "
     "L726)."},
    {"GT_SetAxisPrfVelFilter", "axis, filterNumExp", "",
     "Profile-velocity filter of ``axis``: window 2^filterNumExp ticks, filterNumExp 0..7 (iDEABOX L3801, "
     "L7075-7091). GT_GetPrfVel then reads the mean over that window (decision GS9)."},
    {"GT_GetAxisPrfVelFilter", "axis", "(0,)",
     "(rtn, filterNumExp) of the profile-velocity filter, 0 by default (iDEABOX L5474-5495)."},
    {"GT_SetAxisEncVelFilter", "axis, filterNumExp", "",
     "Encoder-velocity filter of ``axis``: window 2^filterNumExp ticks, 0..7 (iDEABOX L3793-3797, L7056-7071). "
     "GT_GetEncVel then reads the mean over that window (GS9)."},
    {"GT_GetAxisEncVelFilter", "axis", "(0,)",
     "(rtn, filterNumExp) of the encoder-velocity filter, 0 by default (iDEABOX L5450-5470)."},
    {"GT_GetEncVel", "axis, count=1", "(0.0,)",
     "(rtn, encoder velocity, pulse/ms): the actual-position change over the last 2^n ticks / 2^n (n = "
     "GT_SetAxisEncVelFilter, 0 = one tick). The history starts at the first velocity-filter setting or "
     "GT_GetEncVel call (before two samples it reads 0; decision GS9)."},
    {"GT_IsEcatReady", "", "(0,)",
     "(rtn, status): 1 = the EtherCAT bus is configured and running (iDEABOX Ex 4-1 L611-615). The simulated bus "
     "is up as soon as the card is open (decision GS10)."},
    {"GT_LoadConfig", "pCfgPath", "",
     "Loads a configuration file (iDEABOX L625; './GTS800.cfg'): the file's format is not given in the manuals; "
     "the simulated machine's configuration is the Card it opens. Returns 1 (UNSUPPORTED, GS11)."},
  };
  return rows;
}

}  // namespace servobench::vendor::googol
