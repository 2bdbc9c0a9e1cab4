"""The card kernel's layout (issue 24 points 1, 2 and 5; decisions VK1-VK9): the kernel includes no vendor header,
the kernel's per-axis state names no vendor field, no friend class, every C++ source file under ~600 lines, and the
card bindings take axis indices through the one check as ``int``."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
CPP = ROOT / "cpp"
# Empty: the ADLINK interpolation group (vendor/adlink/adlink_group.*, AV1) and the GE SX crd (vendor/googol/ge_crd.*,
# GV2) moved to vendor/ in session 11; the kernel includes no vendor header, without exception.
GROUP_MODULES: set[str] = set()
# None: identify/time_fit.cpp was split into time_fit.cpp (the solve) and shooting_model.cpp (the model and the
# shooting problem) in session 11.
LONG_ALLOWED: set[str] = set()


def _kernel_files():
    for folder in (CPP / "include" / "servobench" / "machine", CPP / "src" / "machine"):
        for f in sorted(folder.iterdir()):
            if f.suffix in (".cpp", ".hpp") and f.name not in GROUP_MODULES:
                yield f


def test_kernel_includes_no_vendor_header():
    bad = [f"{f.relative_to(ROOT)}: {line.strip()}" for f in _kernel_files()
           for line in f.read_text().splitlines() if re.match(r'\s*#include\s+"servobench/vendor/', line)]
    assert not bad, bad


def test_kernel_axis_state_has_no_vendor_field():
    text = (CPP / "include" / "servobench" / "machine" / "card.hpp").read_text()
    state = text[text.index("struct CardAxisState {"):]
    state = state[:state.index("};")]
    for field in ("wait_trigger", "waiting", "limit_decelerate", "limit_dec", "limit_stopping", "pre_event",
                  "post_event", "ptp_active", "move_start", "move_target", "error_level_pulse", "in_position_pulse"):
        assert not re.search(rf"\b{field}\b", state), f"CardAxisState still holds the ADLINK field {field}"
    adlink = (CPP / "include" / "servobench" / "vendor" / "adlink" / "adlink_axes.hpp").read_text()
    assert "struct AdlinkAxisState" in adlink and "error_level_pulse" in adlink


def test_no_friend_class():
    bad = [str(f.relative_to(ROOT)) for f in CPP.rglob("*.[ch]pp") if re.search(r"^\s*friend\s", f.read_text(), re.M)]
    assert not bad, bad


def test_every_cpp_file_is_under_600_lines():
    long = {str(f.relative_to(ROOT)): n for f in CPP.rglob("*.[ch]pp")
            if (n := len(f.read_text().splitlines())) > 600}
    assert set(long) <= LONG_ALLOWED, long


def test_card_bindings_take_int_axes_through_the_one_check():
    for f in sorted((CPP / "bindings").glob("bind_card*.cpp")):
        text = f.read_text()
        assert not re.search(r"\bdouble (i|axis|master|first)\b", text), f"{f.name}: a double axis argument"
    sb = pytest.importorskip("servobench")
    doc = sb._core.Card.axis_on.__doc__
    assert "axis: int" in doc, doc


def test_one_line_and_arc_geometry():
    """Issue 24.5: one line/arc geometry type for every vendor (decision LK2): only motion/segment_geometry defines a
    point along a segment; the Googol and ADLINK names are aliases of its two instantiations."""
    owners = sorted(str(f.relative_to(ROOT)) for f in CPP.rglob("*.[ch]pp") if re.search(r"\bpoint_at\(double", f.read_text()))
    assert owners == ["cpp/include/servobench/motion/segment_geometry.hpp", "cpp/src/motion/segment_geometry.cpp"], owners
    header = (CPP / "include" / "servobench" / "motion" / "segment_geometry.hpp").read_text()
    assert "using PathSegmentGeometry = SegmentGeometry<kCrdMaxDim>;" in header
    assert "using SpaceSegment = SegmentGeometry<kSpaceMaxDim>;" in header


def test_scope_axis_fields_are_integers():
    """Issue 24.5 "axis counts and indices are integers everywhere" (decision LK4): the sampler's channel axis and the
    position compare's source axis are ints; the binding takes the sampler's axes through the one axis check."""
    for header, struct in (("sampler.hpp", "struct SampleChannel {"), ("position_compare.hpp", "struct CompareSource {")):
        text = (CPP / "include" / "servobench" / "machine" / header).read_text()
        body = text[text.index(struct):]
        body = body[:body.index("};")]
        assert re.search(r"\bint axis = 0;", body), (header, body)
    binding = (CPP / "bindings" / "bind_card_scope.cpp").read_text()
    assert "std::vector<std::pair<AxisIndex, std::string>>& channels" in binding
