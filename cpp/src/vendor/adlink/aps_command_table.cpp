// The APS_* functions' descriptions (aps_command_table.hpp): one row per function the dialect writes out, moved
// verbatim from the dialect's docstrings in session 13 (AX2). Units: pulse, pulse/s, pulse/s^2, ms, V; manual lines
// of seed 004.
#include "servobench/vendor/adlink/aps_command_table.hpp"

namespace servobench::vendor::adlink {

const std::vector<ApsCommandDoc>& aps_commands() {
  static const std::vector<ApsCommandDoc> kCommands = {
      {"APS_initial", "mode: int=0, card: Card | None=None, **axis_parts",
       "``APS_initial(&BoardID_InBits, Mode)``: opens ``card`` (or a new 4-axis PCI-8254 Card with the "
       "ADLINK\nservo period 250 us, L1733, built from ``axis_parts``). Returns ``(rtn, board_id_in_bits)`` "
       "(board 0 -> 1).\nERR_DeviceAlreadyInitialed while a card is open."},
      {"APS_close", "",
       "``APS_close()``: releases the card."},
      {"APS_set_axis_param", "Axis_ID, AxisPara, Data",
       "``APS_set_axis_param(Axis_ID, AxisPara, I32 Data)``: sets a PRA_* parameter (integer value)."},
      {"APS_set_axis_param_f", "Axis_ID, AxisPara, Data",
       "``APS_set_axis_param_f(Axis_ID, AxisPara, F64 Data)``: sets a PRA_* parameter. Servo-law "
       "parameters\n(90h-A0h, 120h-12Bh) take effect at the next servo tick; motion parameters at the next "
       "move;\nlimits and PRA_ERR_POS_LEVEL at once."},
      {"APS_get_axis_param_f", "Axis_ID, AxisPara",
       "``APS_get_axis_param_f(Axis_ID, AxisPara, &Data)`` -> ``(rtn, data)`` (F64)."},
      {"APS_get_axis_param", "Axis_ID, AxisPara",
       "``APS_get_axis_param(Axis_ID, AxisPara, &Data)`` -> ``(rtn, data)`` (I32: the value truncated)."},
      {"APS_set_servo_on", "Axis_ID, Servo_on",
       "``APS_set_servo_on(Axis_ID, Servo_on)``: 1 servo on (SVON), 0 off (L1603). Servo on with the "
       "drive\nalarm latched is refused (ERR_FunctionNotAvailable)."},
      {"APS_relative_move", "Axis_ID, Distance, Max_Speed",
       "``APS_relative_move(Axis_ID, I32 Distance, I32 Max_Speed)``: point to point by ``Distance`` pulse "
       "from\nthe command position at ``Max_Speed`` pulse/s with PRA_ACC/DEC/VS/VE/SF (L2728-2740). During "
       "a PTP or\nvelocity move it changes the move on the fly (L2757-2767)."},
      {"APS_absolute_move", "Axis_ID, Position, Max_Speed",
       "``APS_absolute_move(Axis_ID, I32 Position, I32 Max_Speed)``: point to point to ``Position`` pulse."},
      {"APS_ptp", "Axis_ID, Option, Position, Wait=None",
       "``APS_ptp(Axis_ID, Option, F64 Position, ASYNCALL *Wait)``: point to point at PRA_VM with "
       "PRA_ACC/DEC/\nVS/VE/SF. Option bit 0 absolute (0) / relative (1); bit 8 (MF_WAIT, 0x100) waits "
       "for\n:func:`APS_move_trigger` (MTS WAIT on) (L3686-3691). The buffer modes (bits 12-15) are not "
       "simulated\n(ERR_FunctionNotAvailable); ``Wait`` must be None/0 (a synchronous call)."},
      {"APS_ptp_v", "Axis_ID, Option, Position, Vm, Wait=None",
       "``APS_ptp_v(Axis_ID, Option, F64 Position, F64 Vm, ASYNCALL *Wait)``: :func:`APS_ptp` at the "
       "given\nmaximum speed ``Vm`` pulse/s (L2728-2740)."},
      {"APS_ptp_all", "Axis_ID, Option, Position, Vs, Vm, Ve, Acc, Dec, SFac, Wait=None",
       "``APS_ptp_all(Axis_ID, Option, F64 Position, F64 Vs, F64 Vm, F64 Ve, F64 Acc, F64 Dec, F64 "
       "SFac,\nASYNCALL *Wait)``: :func:`APS_ptp` with every speed given (pulse/s, pulse/s^2, S-factor "
       "0..1); the\naxis parameters are not changed (L2716-2718)."},
      {"APS_move_trigger", "Dimension, Axis_ID_Array",
       "``APS_move_trigger(I32 Dimension, I32 *Axis_ID_Array)``: starts the waiting (MF_WAIT) moves of "
       "the\nlisted axes in the same servo tick (L3787-3790). Each axis then runs its own profile; an axis "
       "whose\nmove became impossible while waiting (a limit, EMG, ALM) is ignored with its stop code."},
      {"APS_home_move", "Axis_ID",
       "``APS_home_move(Axis_ID)``: starts homing with the PRA_HOME_* parameters (modes 0 ORG, 1 EL, 2 "
       "EZ;\nL2246-2556). Completion: MTS MDN; failure: MTS ASTP and :func:`APS_get_stop_code` "
       "(L2308-2326).\nRefused (ERR_FunctionNotAvailable) while the axis moves."},
      {"APS_jog_on", "Axis_ID, On",
       "``APS_jog_on(Axis_ID, On)``: the software JOG-ON signal (1 on, 0 off; L2653, L2672) with "
       "the\nPRA_JG_* parameters. Continuous mode moves while on and decelerates when off; step mode "
       "moves\nPRA_JG_OFFSET, waits PRA_JG_DELAY, then moves on while the signal stays on, stopping on a "
       "whole\nmultiple of the offset (L2645-2657). While jogging, other motion commands are refused; while "
       "another\nmotion runs, JOG-ON is ignored (ERR_FunctionNotAvailable, L2706-2708)."},
      {"APS_velocity_move", "Axis_ID, Max_Speed",
       "``APS_velocity_move(Axis_ID, I32 Max_Speed)``: velocity move at the signed ``Max_Speed`` pulse/s "
       "with\nPRA_ACC/DEC/SF until a stop; a new call changes the speed on the fly (L2560-2566)."},
      {"APS_vel", "Axis_ID, Dir, Vel, Wait=None",
       "``APS_vel(Axis_ID, Dir, F64 Vel, ASYNCALL *Wait)``: velocity move at ``Vel`` pulse/s, Dir 0 "
       "positive,\n1 negative (the example passes 0 with positive speeds, L2618; V50)."},
      {"APS_stop_move", "Axis_ID",
       "``APS_stop_move(Axis_ID)``: decelerating stop at PRA_SD_DEC (L2570-2574), a normal stop (V45)."},
      {"APS_emg_stop", "Axis_ID",
       "``APS_emg_stop(Axis_ID)``: immediate stop (L2576), a normal stop (V45)."},
      {"APS_start_gear", "Axis_ID, Mode",
       "``APS_start_gear(Axis_ID, Mode)`` (the manual prints ``APS_start_gear(slave axis ID)``, L3311; the "
       "Mode\nargument is the library's, V119): 1 engages the standard gear of slave ``Axis_ID`` on "
       "PRA_GEAR_MASTER, the\nratio ramping from 0 to PRA_GEAR_RATIO at PRA_GEAR_ENGAGE_RATE (ratio/s; 0 = "
       "at once; L3309-3313);\n0 releases it (the slave holds). 2 (gantry) is not simulated "
       "(ERR_FunctionNotAvailable, V122). Refused\n(ERR_FunctionNotAvailable) while the slave moves in "
       "another motion."},
      {"APS_line", "Dimension, Axis_ID_Array, Option, PositionArray, TransPara=0.0, Wait=None",
       "``APS_line(I32 Dimension, I32 *Axis_ID_Array, I32 Option, F64 *PositionArray, F64 "
       "*TransPara,\nASYNCALL *Wait)`` (L2855; argument list V113): a straight line of 2..6 axes; the first "
       "axis is the\nreference axis whose PRA_VS/VM/VE/ACC/DEC/SF give the vector profile (L2819-2855). "
       "Option bit 0\nrelative, bit 8 MF_WAIT, bits 12-15 the transition mode (ITP_OPT_*); TransPara the "
       "residual distance\n(pulse) or percent of the blend modes. ``Wait`` must be None/0."},
      {"APS_line_v", "Dimension, Axis_ID_Array, Option, PositionArray, TransPara, Vm, Wait=None",
       "``APS_line_v(..., F64 *TransPara, F64 Vm, ASYNCALL *Wait)``: :func:`APS_line` at vector speed Vm."},
      {"APS_line_all",
       "Dimension, Axis_ID_Array, Option, PositionArray, TransPara, Vs, Vm, Ve, Acc, Dec, SFac, Wait=None",
       "``APS_line_all(..., F64 *TransPara, F64 Vs, F64 Vm, F64 Ve, F64 Acc, F64 Dec, F64 SFac, "
       "ASYNCALL\n*Wait)``: :func:`APS_line` with every speed of the vector profile given (the PRA values "
       "unchanged)."},
      {"APS_absolute_linear_move", "Dimension, Axis_ID_Array, Position_Array, Max_Linear_Speed",
       "``APS_absolute_linear_move(I32 Dimension, I32 *Axis_ID_Array, I32 *Position_Array, "
       "I32\nMax_Linear_Speed)`` (L2867): a line to whole-pulse positions at vector speed Max_Linear_Speed "
       "pulse/s."},
      {"APS_relative_linear_move", "Dimension, Axis_ID_Array, Distance_Array, Max_Linear_Speed",
       "``APS_relative_linear_move(I32 Dimension, I32 *Axis_ID_Array, I32 *Distance_Array, "
       "I32\nMax_Linear_Speed)`` (L2870): a line by whole-pulse distances."},
      {"APS_get_position", "Axis_ID",
       "``APS_get_position(Axis_ID, &Position)`` -> ``(rtn, feedback position)``, whole pulses (L2085)."},
      {"APS_set_position", "Axis_ID, Position",
       "``APS_set_position(Axis_ID, Position)``: sets the feedback (and command) position, at rest "
       "only\n(ERR_FunctionNotAvailable while moving)."},
      {"APS_get_command", "Axis_ID",
       "``APS_get_command(Axis_ID, &Command)`` -> ``(rtn, command position)``, whole pulses (L2083)."},
      {"APS_get_error_position", "Axis_ID",
       "``APS_get_error_position(Axis_ID, &Err_Pos)`` -> ``(rtn, E)``: the law's error of the last servo "
       "tick\n(command - feedback), pulse (SAMP_SRC_ERR_POS, L3574)."},
      {"APS_motion_status", "Axis_ID",
       "``I32 APS_motion_status(Axis_ID)``: the motion status word (MTS_* bits) or a negative error code."},
      {"APS_motion_io_status", "Axis_ID",
       "``I32 APS_motion_io_status(Axis_ID)``: the motion I/O word (MIO_* bits) or a negative error code."},
      {"APS_get_stop_code", "Axis_ID",
       "``APS_get_stop_code(Axis_ID, &Code)`` -> ``(rtn, STOP_* code)`` of the last abnormal stop (0 none)."},
      {"APS_set_sampling_param", "Board_ID, ParaNum, ParaDat",
       "``APS_set_sampling_param(Board_ID, ParaNum, ParaDat)``: SAMP_PA_RATE (a sample every N servo "
       "ticks,\n1..65535; default the ticks of 1 ms, L3548), SAMP_PA_EDGE (0 rising, 1 falling, 2 no "
       "trigger: start at\nonce, the default; V80), SAMP_PA_LEVEL (in the trigger channel's unit), "
       "SAMP_PA_TRIGCH (0..3),\nSAMP_PA_SRC_CH0..3 (axis << 8 | source: SAMP_* of Table 4-5, PID_* of Table "
       "4-6)."},
      {"APS_get_sampling_param", "Board_ID, ParaNum",
       "``APS_get_sampling_param(Board_ID, ParaNum, &ParaDat)`` -> ``(rtn, ParaDat)``."},
      {"APS_wait_trigger_sampling", "Board_ID, Length, PreTrgLen, TimeOutMs",
       "``APS_wait_trigger_sampling(Board_ID, Length, PreTrgLen, TimeOutMs, STR_SAMP_DATA_4CH *DataArr)`` "
       "->\n``(rtn, DataArr)``: samples the four channels every SAMP_PA_RATE ticks, ``Length`` samples "
       "(1..1e6) of\nwhich ``PreTrgLen`` before the trigger (SAMP_PA_TRIGCH crossing SAMP_PA_LEVEL on "
       "SAMP_PA_EDGE), running\nthe card until the block is full or ``TimeOutMs`` simulated ms passed (-1: "
       "V83) -> ERR_TimeOut, no data.\nDataArr: a NumPy array of :data:`STR_SAMP_DATA_4CH` (``tick`` = card "
       "tick of the sample; ``data`` the\nchannels in their units: pulse, pulse/s, mV, bits; whole numbers "
       "for the I32 sources)."},
      {"APS_wait_trigger_sampling_async", "Board_ID, Length, PreTrgLen, TimeOutMs",
       "``APS_wait_trigger_sampling_async(...)`` -> ``(rtn, DataArr)``: starts the same sampling and "
       "returns at\nonce; the card fills ``DataArr`` as it runs (the samples taken so far are copied into "
       "it at each\nAPS_get_sampling_count call, V78); after ``TimeOutMs`` of card time without a full "
       "block the sampling\nstops."},
      {"APS_get_sampling_count", "Board_ID",
       "``APS_get_sampling_count(Board_ID, &SampCnt)`` -> ``(rtn, samples in DataArr)`` of the running "
       "or\nfinished asynchronous sampling (the pre-trigger samples count once the trigger came)."},
      {"APS_stop_wait_sampling", "Board_ID",
       "``APS_stop_wait_sampling(Board_ID)``: stops the sampling; DataArr keeps what was copied."},
      {"APS_set_trigger_param", "Board_ID, Param_No, Param_Val",
       "``APS_set_trigger_param(Board_ID, Param_No, Param_Val)``: TGR_LCMPx_SRC / TGR_TCMPx_SRC (axis n = "
       "its\nencoder, TGR_SRC_COMMAND + n its command position; V76), TGR_TCMPx_DIR (0 negative, 1 "
       "positive, 2 both),\nTGR_TRG_EN (bit x: TRGx on), TGR_TRGx_SRC (TRG_SRC_* bits, V77), TGR_TRGx_PWD "
       "(x 100 ns, 1..10^7),\nTGR_TRGx_LOGIC (0 active high, 1 active low), TGR_TRGx_TGL (0 pulse, 1 level "
       "toggle), the timer TIMR_ITV /\nTIMR_DIR / TIMR_RING_EN / TIMR_EN (APS_get_timer_counter, AF15). "
       "PCI-8254 (4 axes): TRG0-1 only."},
      {"APS_get_trigger_param", "Board_ID, Param_No",
       "``APS_get_trigger_param(Board_ID, Param_No, &Param_Val)`` -> ``(rtn, Param_Val)``."},
      {"APS_set_trigger_linear", "Board_ID, LCmpCh, StartPoint, RepeatTimes, Interval",
       "``APS_set_trigger_linear(Board_ID, LCmpCh, StartPoint, RepeatTimes, Interval)``: LCMP0/1 compares "
       "the\npoints StartPoint + i*Interval, i = 0..RepeatTimes-1, in the direction of Interval's sign "
       "(L3393)."},
      {"APS_set_trigger_table", "Board_ID, TCmpCh, DataArr, ArraySize",
       "``APS_set_trigger_table(Board_ID, TCmpCh, I32 *DataArr, ArraySize)``: TCMP0/1 compares the "
       "first\nArraySize points in order, in the TGR_TCMPx_DIR direction (L3397-3430; the library streams "
       "any length)."},
      {"APS_set_trigger_manual", "Board_ID, TrgCh",
       "``APS_set_trigger_manual(Board_ID, TrgCh)``: one pulse on TRGx now, if its source set "
       "has\nTRG_SRC_MANUAL and it is enabled (L3380-3385)."},
      {"APS_get_trigger_count", "Board_ID, TrgCh",
       "``APS_get_trigger_count(Board_ID, TrgCh, &TrgCnt)`` -> ``(rtn, pulses TRGx emitted)``."},
      {"APS_reset_trigger_count", "Board_ID, TrgCh",
       "``APS_reset_trigger_count(Board_ID, TrgCh)``: TRGx's counter to 0."},
      {"APS_get_trigger_linear_cmp", "Board_ID, LCmpCh",
       "``APS_get_trigger_linear_cmp(Board_ID, LCmpCh, &CmpVal)`` -> ``(rtn, next compare point)`` (0 once "
       "every\npoint has been compared, decision V128)."},
      {"APS_get_trigger_table_cmp", "Board_ID, TCmpCh",
       "``APS_get_trigger_table_cmp(Board_ID, TCmpCh, &CmpVal)`` -> ``(rtn, next compare point)`` (0 once "
       "every\npoint of the table has been compared, decision V128)."},
      {"APS_int_enable", "Board_ID, Enable",
       "``APS_int_enable(Board_ID, Enable)``: the main interrupt switch (1 on, 0 off); no event signals "
       "while\noff."},
      {"APS_set_int_factor", "Board_ID, Item_No, Factor_No, Enable",
       "``I32 APS_set_int_factor(Board_ID, Item_No, Factor_No, Enable)`` -> the interrupt number (item x 32 "
       "+\nfactor bit, V82) or a negative code. Items 0..3/7 axes (IALM..ISMEL, IEZ = the index mark "
       "passing; IPRED,\nIPOSTD not simulated:\nERR_FunctionNotAvailable), 8 system (IEMG, ILCF0/1, "
       "IFCF0/1; IMOV/IHOV never fire); 9/10 (DI edges): the\ncard has no digital inputs. Factor_No is the "
       "bit number; a one-bit mask such as the examples' (1 << 12)\nis read as its bit (L4271-4274, V82)."},
      {"APS_get_int_factor", "Board_ID, Item_No, Factor_No",
       "``APS_get_int_factor(Board_ID, Item_No, Factor_No, &Enable)`` -> ``(rtn, Enable)``."},
      {"APS_int_no_to_handle", "Int_No",
       "``HANDLE APS_int_no_to_handle(Int_No)``: the simulation's handle is the interrupt number itself."},
      {"APS_wait_single_int", "Int_No, Time_Out",
       "``APS_wait_single_int(Int_No, Time_Out)``: runs the card until the interrupt is signaled (at once "
       "if it\nalready is: reset it with APS_reset_int) or ``Time_Out`` simulated ms passed (ERR_TimeOut; "
       "-1: at most\none simulated hour, V83). ERR_InterruptNotEnable with the main switch or the factor "
       "off."},
      {"APS_wait_multiple_int", "Int_Count, Int_No_Array, Wait_All, Time_Out",
       "``APS_wait_multiple_int(Int_Count, *Int_No_Array, Wait_All, Time_Out)``: as APS_wait_single_int "
       "for\nthe first Int_Count numbers, until all (Wait_All 1) or any (0) are signaled."},
      {"APS_reset_int", "Int_No",
       "``APS_reset_int(Int_No)``: back to non-signaled (L4270)."},
      {"APS_set_int", "Int_No",
       "``APS_set_int(Int_No)``: signals the interrupt by software."},
      {"APS_stop_move_multi", "Dimension, Axis_ID_Array",
       "``APS_stop_move_multi(I32 Dimension, I32 *Axis_ID_Array)`` (L2578): :func:`APS_stop_move` on the "
       "first\nDimension axes in the same servo tick (each decelerates at its PRA_SD_DEC)."},
      {"APS_emg_stop_multi", "Dimension, Axis_ID_Array",
       "``APS_emg_stop_multi(I32 Dimension, I32 *Axis_ID_Array)`` (L2580): :func:`APS_emg_stop` (immediate) "
       "on\nthe first Dimension axes in the same servo tick."},
      {"APS_vel_all", "Axis_ID, Option, Vs, Vm, Ve, Acc, Dec, SFac, Wait=None",
       "``APS_vel_all(Axis_ID, Option, F64 Vs, F64 Vm, F64 Ve, F64 Acc, F64 Dec, F64 SFac, ASYNCALL "
       "*Wait)``\n(L2572): a velocity move at ``Vm`` pulse/s (Option 0 positive, 1 negative, as APS_vel, "
       "V50) from ``Vs``\nwith ``Acc``/``Dec`` pulse/s^2 and S-factor ``SFac``; the axis parameters are not "
       "changed. ``Ve`` (the end\nspeed of a move that never ends) is checked (0..1e9) and unused (AF13)."},
      {"APS_get_command_f", "Axis_ID",
       "``APS_get_command_f(I32 Axis_ID, F64 *Command)`` -> ``(rtn, command position)``, pulse, F64 (L2066)."},
      {"APS_set_command", "Axis_ID, Command",
       "``APS_set_command(I32 Axis_ID, I32 Command)`` (L2084): sets the command position, at rest only; "
       "the\nfeedback position moves with it so the following error is kept (closed loop, AF14)."},
      {"APS_get_encoder", "Axis_ID",
       "``APS_get_encoder(I32 Axis_ID, I32 *Encoder)`` -> ``(rtn, encoder counter)`` (L2094): the "
       "feedback\ncounter in motor pulses, 32-bit (= APS_get_position with unit factor 1, AF14)."},
      {"APS_get_command_counter", "Axis_ID",
       "``APS_get_command_counter(I32 Axis_ID, I32 *Counter)`` -> ``(rtn, command counter)`` (L2095): "
       "the\ncommand output in motor pulses, 32-bit (= APS_get_command with unit factor 1, AF14)."},
      {"APS_get_timer_counter", "Board_ID, TmrCh",
       "``APS_get_timer_counter(I32 Board_ID, I32 TmrCh, I32 *Cnt)`` -> ``(rtn, Cnt)`` (L3376): the "
       "compare\ntimer (TmrCh 0, the card's one timer): while TIMR_EN, +-1 every TIMR_ITV servo ticks "
       "(TIMR_DIR 0 up,\n1 down), wrapping at 32 bits with TIMR_RING_EN, else held at the I32 limits."},
      {"APS_set_timer_counter", "Board_ID, TmrCh, Cnt",
       "``APS_set_timer_counter(I32 Board_ID, I32 TmrCh, I32 Cnt)`` (L3378): sets the timer counter (I32)."},
      {"APS_wdt_set_action_event", "Board_ID, TimerNo, EventByBit",
       "``APS_wdt_set_action_event(board_id, timer_no, EventByBit)`` (L4037, L4071-4074): what the "
       "time-out\ndoes, bit 0 servo off (every axis), bit 1 digital outputs off, bit 2 PWM (VAO) outputs "
       "off."},
      {"APS_wdt_get_action_event", "Board_ID, TimerNo",
       "``APS_wdt_get_action_event(board_id, timer_no, &EventByBit)`` -> ``(rtn, EventByBit)`` (L4051)."},
      {"APS_wdt_start", "Board_ID, TimerNo, TimeOut",
       "``APS_wdt_start(board_id, timer_no, time_out)`` (L4041, L4053): starts the watchdog with a time-out "
       "of\n``time_out`` x 100 ms of card time (10 -> 1 s, L4070); 0 disables it. If the program does not "
       "call\nAPS_wdt_reset_counter within the time-out, the action event is carried out once (checked "
       "every 1 ms of\ncard time, AF16) and the watchdog stops."},
      {"APS_wdt_get_timeout_period", "Board_ID, TimerNo",
       "``APS_wdt_get_timeout_period(board_id, timer_no, &time_out)`` -> ``(rtn, time_out)`` x 100 ms "
       "(L4043)."},
      {"APS_wdt_reset_counter", "Board_ID, TimerNo",
       "``APS_wdt_reset_counter(board_id, timer_no)`` (L4045, L4058): restarts the time-out from now "
       "(a\nwatchdog that has fired or is off: ERR_FunctionNotAvailable)."},
      {"APS_write_d_output", "Board_ID, DO_Group, DO_Data",
       "``APS_write_d_output(Board_ID, DO_Group, DO_Data)`` (APS library): the digital outputs DO0..7 "
       "(group 0)\nas bits."},
      {"APS_read_d_output", "Board_ID, DO_Group",
       "``APS_read_d_output(Board_ID, DO_Group, &DO_Data)`` -> ``(rtn, DO0..7 as bits)`` (APS library), "
       "with the\npoint tables' instruction commands of the moves started so far carried out."},
      {"APS_set_board_param", "Board_ID, BOD_Param_No, BOD_Param",
       "``APS_set_board_param(Board_ID, BOD_Param_No, BOD_Param)`` (L3520): PRB_PWMx_MAP_DO (110h-113h): -1 "
       "no\nmapping, else bits 0-7 the DO channel and bit 8 the logic (1: DO on enables PWMx, 0: DO on "
       "disables it,\nL3530); PRS_EMG_LOGIC (00h, L1623): only 0 (the simulated EMG input is the active "
       "state; inverting its\nwiring is not simulated, AF17)."},
      {"APS_get_board_param", "Board_ID, BOD_Param_No",
       "``APS_get_board_param(Board_ID, BOD_Param_No, &BOD_Param)`` -> ``(rtn, BOD_Param)`` (APS library)."},
      {"APS_get_eep_curr_drv_ctrl_mode", "Board_ID",
       "``APS_get_eep_curr_drv_ctrl_mode(Board_ID, &ModeInBit)`` -> ``(rtn, ModeInBit)`` (L1498): bit k = "
       "1:\naxis k is driven by the analog (+-10 V) command, 0: by pulses (L1493-1498). The simulated axes "
       "are driven\nby the servo law's voltage: every bit 1 (AF18)."},
      {"APS_set_vao_param", "Board_ID, Param_No, Param_Val",
       "``APS_set_vao_param(Board_ID, Param_No, Param_Val)`` (L3461, L3504-3512) for table N = "
       "0..7:\nVAO_TABLE_OUTPUT_TYPE + 2N (1 PWM duty, 2 frequency at fixed width, 3 frequency at fixed "
       "duty),\nVAO_TABLE_INPUT_TYPE + 2N (0 feedback speed: not simulated, ERR_FunctionNotAvailable, AF19; "
       "1 command\nspeed; set it to 1 as the manual's examples do, L3537-3539), VAO_TABLE_PWM_Config + N "
       "(mode 1: Hz\n3..50e6; 2: ns 20..335544320; 3: duty x 0.05 %, 1..2000),\nVAO_TABLE_SRC + N (axis "
       "bits)."},
      {"APS_set_vao_table", "Board_ID, Table_No, MinVelocity, VelInterval, TotalPoints, MappingDataArray",
       "``APS_set_vao_table(Board_ID, Table_No, I32 MinVelocity, I32 VelInterval, I32 TotalPoints, "
       "I32\n*MappingDataArray)`` (L3540; arguments of the APS library, AF20): table 0..7 of 1..32 points, "
       "point k at\nthe composite speed MinVelocity + k * VelInterval pulse/s with power "
       "MappingDataArray[k] (the output type's\nunit and range, L3489-3495)."},
      {"APS_switch_vao_table", "Board_ID, Table_No",
       "``APS_switch_vao_table(Board_ID, Table_No)`` (L3540): VAO controller 0 uses table 0..7 from now "
       "(the\nlibrary call names no controller; controller 1 switches through APS_pt_ext_set_table_no, "
       "AF21)."},
      {"APS_start_vao", "Board_ID, Output_Ch, Enable",
       "``APS_start_vao(Board_ID, Output_Ch, Enable)`` (L3501): turns the PWM output of VAO "
       "controller\n``Output_Ch`` (0..1 = PWM0..1, AF21) on (1) or off (0); its active table must be "
       "set\n(ERR_FunctionNotAvailable otherwise)."},
  };
  return kCommands;
}

// The arc and spiral commands (L2899-3063; argument lists V113), moved from the dialect's _ARCS in session 14 (AY4):
// each in three forms, the PRA speeds, _v (at vector speed Vm, pulse/s) and _all (every speed given). Positions in
// pulse, angles in degrees; Option and TransPara as APS_line; Wait must be None/0.
const std::vector<ApsCommandDoc>& aps_arc_commands() {
  static const std::vector<ApsCommandDoc> kCommands = {
      {"APS_arc2_ca", "Axis_ID_Array, Option, CenterArray, Angle, TransPara=0.0, Wait=None",
       "``APS_arc2_ca(I32 *Axis_ID_Array, I32 Option, F64 *CenterArray, F64 Angle, F64 *TransPara, ASYNCALL "
       "*Wait)`` (L2978): a 2-D arc about the centre by Angle degrees (+ CCW, ``|Angle|`` > 360 = laps)."},
      {"APS_arc2_ca_v", "Axis_ID_Array, Option, CenterArray, Angle, TransPara, Vm, Wait=None",
       ":func:`APS_arc2_ca` at vector speed Vm (pulse/s)."},
      {"APS_arc2_ca_all", "Axis_ID_Array, Option, CenterArray, Angle, TransPara, Vs, Vm, Ve, Acc, Dec, SFac, Wait=None",
       ":func:`APS_arc2_ca` with every speed given (the PRA values unchanged)."},
      {"APS_arc2_ce", "Axis_ID_Array, Option, CenterArray, EndArray, Dir, TransPara=0.0, Wait=None",
       "``APS_arc2_ce(I32 *Axis_ID_Array, I32 Option, F64 *CenterArray, F64 *EndArray, I16 Dir, F64 *TransPa"
       "ra, ASYNCALL *Wait)`` (L2981): a 2-D arc to an exact end point, Angle = theta + Dir*360 (L2943-2958)"
       "; exactly 180 deg or 360 deg is ERR_ParametersInvalid (L2930-2933)."},
      {"APS_arc2_ce_v", "Axis_ID_Array, Option, CenterArray, EndArray, Dir, TransPara, Vm, Wait=None",
       ":func:`APS_arc2_ce` at vector speed Vm (pulse/s)."},
      {"APS_arc2_ce_all", "Axis_ID_Array, Option, CenterArray, EndArray, Dir, TransPara, Vs, Vm, Ve, Acc, Dec, SFac, "
                          "Wait=None",
       ":func:`APS_arc2_ce` with every speed given (the PRA values unchanged)."},
      {"APS_arc3_ca", "Axis_ID_Array, Option, CenterArray, NormalArray, Angle, TransPara=0.0, Wait=None",
       "``APS_arc3_ca(I32 *Axis_ID_Array, I32 Option, F64 *CenterArray, F64 *NormalArray, F64 Angle, F64 *Tr"
       "ansPara, ASYNCALL *Wait)`` (L2899): a 3-D arc, right-hand rule about the normal (Gram-Schmidt, L2911"
       ")."},
      {"APS_arc3_ca_v", "Axis_ID_Array, Option, CenterArray, NormalArray, Angle, TransPara, Vm, Wait=None",
       ":func:`APS_arc3_ca` at vector speed Vm (pulse/s)."},
      {"APS_arc3_ca_all", "Axis_ID_Array, Option, CenterArray, NormalArray, Angle, TransPara, Vs, Vm, Ve, Acc, Dec, "
                          "SFac, Wait=None",
       ":func:`APS_arc3_ca` with every speed given (the PRA values unchanged)."},
      {"APS_arc3_ce", "Axis_ID_Array, Option, CenterArray, EndArray, Dir, TransPara=0.0, Wait=None",
       "``APS_arc3_ce(I32 *Axis_ID_Array, I32 Option, F64 *CenterArray, F64 *EndArray, I16 Dir, F64 *TransPa"
       "ra, ASYNCALL *Wait)`` (L2900): a 3-D arc to an exact end point (no half or full circle)."},
      {"APS_arc3_ce_v", "Axis_ID_Array, Option, CenterArray, EndArray, Dir, TransPara, Vm, Wait=None",
       ":func:`APS_arc3_ce` at vector speed Vm (pulse/s)."},
      {"APS_arc3_ce_all", "Axis_ID_Array, Option, CenterArray, EndArray, Dir, TransPara, Vs, Vm, Ve, Acc, Dec, SFac, "
                          "Wait=None",
       ":func:`APS_arc3_ce` with every speed given (the PRA values unchanged)."},
      {"APS_sprial_ca", "Axis_ID_Array, Option, CenterArray, NormalArray, Angle, DeltaH, FinalR, TransPara=0.0, "
                        "Wait=None",
       "``APS_sprial_ca(I32 *Axis_ID_Array, I32 Option, F64 *CenterArray, F64 *NormalArray, F64 Angle, F64 D"
       "eltaH, F64 FinalR, F64 *TransPara, ASYNCALL *Wait)`` (the manual's spelling, L3047): a conical spira"
       "l, rise DeltaH along the normal, radius to FinalR (L3001-3035)."},
      {"APS_sprial_ca_v", "Axis_ID_Array, Option, CenterArray, NormalArray, Angle, DeltaH, FinalR, TransPara, Vm, "
                          "Wait=None",
       ":func:`APS_sprial_ca` at vector speed Vm (pulse/s)."},
      {"APS_sprial_ca_all", "Axis_ID_Array, Option, CenterArray, NormalArray, Angle, DeltaH, FinalR, TransPara, Vs, "
                            "Vm, Ve, Acc, Dec, SFac, Wait=None",
       ":func:`APS_sprial_ca` with every speed given (the PRA values unchanged)."},
      {"APS_sprial_ce", "Axis_ID_Array, Option, CenterArray, NormalArray, EndArray, Dir, TransPara=0.0, Wait=None",
       "``APS_sprial_ce(I32 *Axis_ID_Array, I32 Option, F64 *CenterArray, F64 *NormalArray, F64 *EndArray, I"
       "16 Dir, F64 *TransPara, ASYNCALL *Wait)`` (L3050): a spiral to an exact end point (L3037-3063)."},
      {"APS_sprial_ce_v", "Axis_ID_Array, Option, CenterArray, NormalArray, EndArray, Dir, TransPara, Vm, Wait=None",
       ":func:`APS_sprial_ce` at vector speed Vm (pulse/s)."},
      {"APS_sprial_ce_all", "Axis_ID_Array, Option, CenterArray, NormalArray, EndArray, Dir, TransPara, Vs, Vm, Ve, "
                            "Acc, Dec, SFac, Wait=None",
       ":func:`APS_sprial_ce` with every speed given (the PRA values unchanged)."},
  };
  return kCommands;
}

}  // namespace servobench::vendor::adlink
