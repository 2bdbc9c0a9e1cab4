"""The vendor bindings take the card's lock (cpp/bindings/card_locks.cpp; decision VK12): every `_core` function
whose first parameter is the card, and every method of a vendor module a card returns, waits for the running
chunk of a `Card.run` on another thread, as the card's own methods do (issue 21.1's thread safety)."""

import gc
import inspect
import threading

import servobench as sb
from servobench import _core

# The card's vendor modules, by the _core function that returns each.
MODULES = ["ge_registers", "ge_list", "ge_watch", "gt_card", "gts_card", "aps_scope", "aps_interrupts",
           "aps_parameters", "aps_outputs", "aps_point_tables", "aps_watchdog"]


def small_card(n=4):
    card = sb.Card(n, law=sb.GtServoLaw(kp=38, ki=60, kd=830, kaff=12870),
                   plant=sb.RigidPlant(inertia_kgm2=1e-4, viscous_nms=1e-4))
    card.axis_on(0)
    return card


def card_first_functions():
    names = []
    for name, f in vars(_core).items():
        if callable(f) and not isinstance(f, type) and not name.startswith("_"):
            line = (f.__doc__ or "").split("\n")[0]
            if line.startswith(name + "(card: "):
                names.append(name)
    return names


def test_every_function_taking_the_card_first_holds_its_lock():
    names = card_first_functions()
    assert len(names) >= 50  # the GT/GE/GTS/ADLINK status words, command runners and module factories
    assert set(names) <= set(_core._CARD_LOCKED_FUNCTIONS)
    # The wrapper keeps the signature help() and inspect show.
    assert "card" in inspect.signature(_core.ge_command).parameters


def test_the_vendor_modules_share_their_cards_locks():
    card = small_card()
    other = small_card()
    for name in MODULES:
        module = getattr(_core, name)(card.kernel)
        assert _core._shares_card_locks(module, card.kernel), name
        assert not _core._shares_card_locks(module, other.kernel), name


def test_vendor_calls_from_a_second_thread_while_the_card_runs():
    card = small_card(4)
    card.stage_acc(0, 0.05)
    card.stage_vel(0, 4.0)
    card.stage_pos(0, 10**6)
    card.update(1)
    k = card.kernel
    errors = []

    def run():
        try:
            for _ in range(20):
                card.run(5000, signals=["pos"])
        except Exception as e:  # pragma: no cover - reported below
            errors.append(e)

    t = threading.Thread(target=run)
    t.start()
    reads = 0
    while t.is_alive():
        status = _core.gt_axis_status(k, 0)
        assert status & (1 << 9)  # the servo stays on
        regs = _core.ge_registers(k)
        assert regs is not None
        reads += 1
    t.join()
    assert not errors
    assert card.tick == 20 * 5000
    assert reads > 0


def test_a_collected_card_forgets_its_modules_locks():
    for _ in range(3):
        card = small_card()
        modules = [getattr(_core, name)(card.kernel) for name in MODULES]
        assert all(_core._shares_card_locks(m, card.kernel) for m in modules)
        del modules, card
        gc.collect()
    fresh = small_card()
    assert _core.gt_axis_status(fresh.kernel, 0) & (1 << 9)
