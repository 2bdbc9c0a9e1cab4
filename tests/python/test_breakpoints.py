"""GT breakpoints with auto-update: position >=, position <=, motion complete and home (GT seed 000
L1239-1397, L3443-3470, L4312-4353, L4393-4405, L4717-4731; gt.md §3.7, test vectors §9 TV18-TV23)."""

import numpy as np
import pytest

import servobench as sb
from test_homing import ORG, make_axis


def _loop(start=0.0):
    return sb.MotionLoop(make_axis(start_pulse=start))


@pytest.mark.parametrize("sign", [1, -1])
def test_tv18_tv19_position_breakpoint_commits_the_staged_velocity(sign):
    # gt.md §9 TV18 (L1265-1295) and TV19 (L1301-1327): Vel 1, Acc 0.1, Pos +-50000, AuUpdtOn, BrkCn +-20000,
    # PosBrk/NegBrk, SetVel(4) staged. When the ACTUAL position passes BrkCn (L1263, L4347) status bit 2 is set
    # and the velocity goes to 4. Ideal tracking gives 27 536.25 ST in total (derived in gt.md).
    loop = _loop()
    loop.command(sb.GtTCurve(pos=sign * 50000, vel=1, acc=0.1))
    loop.auto_update = True
    loop.set_brk_cn(sign * 20000)
    loop.pos_brk() if sign > 0 else loop.neg_brk()
    loop.stage(sb.GtTCurve(pos=sign * 50000, vel=4, acc=0.1))
    run = loop.run_until_done(100000)
    fired = int(np.argmax(run.breakpoint))
    assert sign * run.actual_pos[fired] >= 20000 and sign * run.actual_pos[fired - 1] < 20000
    assert loop.breakpoint_flag and loop.breakpoint_armed == "none"  # one-shot (L1257)
    v = np.diff(run.pos)
    assert np.all(np.abs(v[: fired - 1]) <= 1.0 + 1e-9)
    assert np.max(np.abs(v[fired:])) == pytest.approx(4, abs=1)
    assert len(run) == pytest.approx(27536, abs=40)  # the actual lags the profile by a few ticks
    assert run.pos[-1] == sign * 50000


def test_breakpoint_compare_value_range_and_off():
    # GT L4721-4727: BrkCn -1073741824..1073741823; GT_BrkOff cancels an armed breakpoint (L2935-2956).
    loop = _loop()
    for bad in (1073741824, -1073741825, 0.5, float("nan")):
        with pytest.raises(ValueError, match="Breakpoint.brk_cn .*-1073741824..1073741823"):
            loop.set_brk_cn(bad)
    loop.set_brk_cn(100)
    loop.pos_brk()
    loop.brk_off()
    loop.command(sb.GtTCurve(pos=1000, vel=5, acc=0.1))
    loop.run_until_done(10000)
    assert not loop.breakpoint_flag


def test_tv21_motion_breakpoint_goes_there_and_back():
    # gt.md §9 TV21 (Ch. 11, L4322-4337): AuUpdtOn, MtnBrk, PrflT, Pos 10000, Vel 7, Acc 0.347, Update, then Pos 0
    # staged: the axis goes to 10000 and then automatically back to 0. (TV20, L1336-1361, has a missing Update.)
    loop = _loop()
    loop.auto_update = True
    loop.mtn_brk()
    loop.command(sb.GtTCurve(pos=10000, vel=7, acc=0.347))
    loop.stage(sb.GtTCurve(pos=0, vel=7, acc=0.347))
    run = loop.run(6000)
    assert run.pos.max() == 10000
    assert loop.breakpoint_flag and run.pos[-1] == 0 and not loop.moving


@pytest.mark.parametrize("tv", ["TV22", "TV23"])
def test_home_breakpoint_smooth_stops_at_the_home_capture(tv):
    # gt.md §9 TV22 (L1381-1394: CaptHome, ExtBrk, PrflV Vel 1, SmthStp staged; Acc set since the example has
    # none) and TV23 (L3460-3469: PrflT Pos 87654, Vel 32, Acc 1.1). On the home capture status bits 3 and 2 are
    # set, the smooth stop takes effect, and GetCapt is the home position.
    loop = _loop()
    loop.auto_update = True
    loop.capt_home()
    loop.ext_brk()
    if tv == "TV22":
        loop.command(sb.GtJog(vel=1, acc=0.01))
    else:
        loop.command(sb.GtTCurve(pos=87654, vel=32, acc=1.1))
    loop.stage_smooth_stop()
    run = loop.run(20000)
    assert loop.captured and loop.breakpoint_flag
    assert abs(loop.capture_value - ORG[0]) <= 1
    k = int(np.argmax(run.breakpoint))
    assert run.captured[k] == 1
    assert not loop.moving and run.pos[-1] < 87654
    assert ORG[0] <= run.pos[-1] <= ORG[0] + 32 * 32 / (2 * 1.1) + 64


def test_staged_commands_wait_for_update():
    # GT L1150-1156: writes go to shadow registers; Update commits them in the next sample time.
    loop = _loop()
    loop.stage(sb.GtTCurve(pos=1000, vel=5, acc=0.1))
    assert loop.staged_count == 1
    loop.run(10)
    assert loop.pos == 0
    loop.update()
    loop.run(10)
    assert loop.pos > 0 and loop.staged_count == 0
