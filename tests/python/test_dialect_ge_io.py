"""GE functions the dialect used to answer with 1 (issue 25: "7 always return 1"), now simulated through
servobench.card_io or listed in ge.UNSUPPORTED (GE manual seed 001, `Lnnn` its lines; decisions GF3, GF7, GF17)."""

import pytest

import servobench as sb
from servobench import card_io
from servobench.dialects import ge
from servobench.dialects.ge import GeController


def sx():
    c = GeController("SX", 4)
    assert c.GT_Open(sb.Card(4, law=sb.GtServoLaw(fractional_gains=True))) == 0 and c.GT_Reset() == 0
    return c


@pytest.mark.parametrize("variant, rate_hz", [("PX", 4000.0), ("SX", 770.0)])
def test_get_adc_example_10_4_and_table_10_4_l2898_2943(variant, rate_hz):
    c = GeController(variant, 4)
    assert c.GT_Open(sb.Card(4, law=sb.GtServoLaw(fractional_gains=True))) == 0
    io = card_io.of(c.card)
    io.adc_volts[0] = 10.0
    io.adc_volts[1] = -10.0
    io.adc_volts[2] = lambda t: 5.0 if t >= 1e-3 else 0.0
    # Example 10-4 (L2898-2920): GT_GetAdc(1, &voltage) == 0 and the value; Table 10-4: +10 V 2047, -10 V -2048
    assert c.GT_GetAdc(1) == (0, 2047) and c.GT_GetAdc(2) == (0, -2048) and c.GT_GetAdc(3) == (0, 0)
    c.run(5)                                              # 1 ms: the voltage changed at 1 ms ...
    sample = c.GT_GetAdc(3)[1]
    assert sample == (1024 if rate_hz == 4000.0 else 0)   # ... PX converted at 1 ms, SX's next one is at 1.3 ms
    c.run(2)
    assert c.GT_GetAdc(3) == (0, 1024)
    assert c.GT_GetAdc(9) == (7, 0) and c.GT_GetAdc(0) == (7, 0)


def test_set_adc_chn_raises_the_sx_sampling_rate_l5447_5455():
    c = sx()
    io = card_io.of(c.card)
    io.adc_volts[0] = lambda t: 2.5 if t >= 0.1e-3 else 0.0
    c.run(1)                                              # 0.2 ms: the 770 Hz conversion is still the one of t = 0
    assert c.GT_GetAdc(1) == (0, 0)
    assert c.GT_SetAdcChn(1) == 0                         # one channel: 8 x 770 Hz = 6.16 kHz, every 0.162 ms
    assert c.GT_GetAdc(1) == (0, 512)
    assert c.GT_SetAdcChn(0) == 7 and c.GT_SetAdcChn(9) == 7
    px = GeController("PX", 4)
    assert px.GT_Open() == 0 and px.GT_SetAdcChn(1) == 1  # SX only


def test_spindle_example_10_6_l3001_3020():
    # Example 10-6: SetSpindleVel(32767) -> +10 V (16-bit, -32768..32767 for -10..+10 V, L5728); 10 s; CloseSpindle
    c = sx()
    io = card_io.of(c.card)
    assert c.GT_SetSpindleVel(32767) == 0 and io.spindle_volts == pytest.approx(10.0, abs=1e-3)
    c.delay(10)
    assert io.spindle_volts == pytest.approx(32767 * 10 / 32768)
    assert c.GT_CloseSpindle() == 0 and io.spindle_volts == 0
    assert c.GT_SetSpindleVel(-32768) == 0 and io.spindle_volts == -10.0
    assert c.GT_SetSpindleVel(32768) == 7 and io.spindle_volts == -10.0


def test_enc_pos_reads_the_auxiliary_encoder_l4002_4023():
    c = sx()
    card_io.of(c.card).aux_encoders[0] = card_io.AuxEncoder(lambda t: 1000.0 + 5000.0 * t)
    assert c.GT_EncPos(1) == (0, 1000) and c.GT_EncPos(2) == (0, 0)   # nothing on No. 2
    c.run(1000)                                                      # 0.2 s
    assert c.GT_EncPos(1) == (0, 2000)
    assert c.GT_EncPos(3) == (7, 0)


def test_ge_unsupported_table_and_codes():
    assert set(ge.UNSUPPORTED) == {"GT_HandWheel", "GT_ExitHWheel", "GT_Axis"}
    c = sx()
    assert c.GT_HandWheel(1, 0.5) == 1 and c.card.last_fault == "not_simulated"
    assert c.GT_ExitHWheel() == 1
    assert c.GT_Axis(2) == 1 and c.card.last_fault == "not_simulated"
    assert GeController().GT_Axis(1) == -1


def test_ge_open_uses_the_machine():
    card = sb.Card(4, law=sb.GtServoLaw(fractional_gains=True))
    c = GeController("PX", 4)
    c.use_machine(card)
    assert c.GT_Open() == 0 and c.card is card
    c.use_machine(None)
    assert c.GT_Open() == 0 and c.card is not card                   # the next card: a new one
