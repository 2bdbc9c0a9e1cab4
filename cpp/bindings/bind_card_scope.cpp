// The card's scope (sampler), event watch, position compare and probe (machine/card_scope.hpp). Thin: axis
// indices 0-based; servobench.card and the dialects translate. Called from bind_card.cpp.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "arrays.hpp"
#include "flag.hpp"
#include "object_lock.hpp"
#include "card_axis.hpp"
#include "servobench/common/validate.hpp"
#include "servobench/machine/card.hpp"
#include "servobench/machine/card_scope.hpp"
#include "servobench/vendor/scope_words.hpp"

namespace servobench::bindings {

namespace py = pybind11;

using machine::Card;

std::vector<const void*> card_keys(Card& card);  // bind_card.cpp: the card and its axes

namespace {

// The card's scope with the vendor words every dialect samples and watches (vendor/scope_words.hpp).
machine::CardScope& scope_of(Card& k) {
  machine::CardScope& s = k.scope();
  if (!s.words().msts) s.set_words(vendor::scope_words());
  return s;
}

machine::SampleTrigger trigger_from(const std::string& s) {
  if (s == "immediate") return machine::SampleTrigger::Immediate;
  if (s == "rising") return machine::SampleTrigger::Rising;
  if (s == "falling") return machine::SampleTrigger::Falling;
  if (s == "event") return machine::SampleTrigger::Event;
  throw py::value_error("trigger: '" + s + "' is not one of immediate, rising, falling, event");
}

const char* state_name(machine::SamplerState s) {
  switch (s) {
    case machine::SamplerState::Idle: return "idle";
    case machine::SamplerState::Armed: return "armed";
    case machine::SamplerState::Filling: return "filling";
    case machine::SamplerState::Done: return "done";
  }
  return "?";
}

const char* word_name(machine::WatchWord w) {
  switch (w) {
    case machine::WatchWord::Events: return "events";
    case machine::WatchWord::Msts: return "msts";
    case machine::WatchWord::Mio: return "mio";
    case machine::WatchWord::System: return "system";
    case machine::WatchWord::Timer: return "timer";
  }
  return "?";
}

py::tuple block_tuple(const machine::SampleBlock& b, std::size_t nch) {
  py::array_t<long long> ticks(static_cast<py::ssize_t>(b.ticks.size()));
  std::copy(b.ticks.begin(), b.ticks.end(), ticks.mutable_data());
  py::array_t<double> values({static_cast<py::ssize_t>(b.ticks.size()), static_cast<py::ssize_t>(nch)});
  std::copy(b.values.begin(), b.values.end(), values.mutable_data());
  return py::make_tuple(ticks, values, b.trigger_tick);
}

py::list fired_list(const Card& c) {
  py::list out;
  if (!c.has_scope()) return out;
  for (const machine::FiredEvent& f : scope_of(const_cast<Card&>(c)).fired())
    out.append(py::make_tuple(f.tick, f.axis, word_name(f.word), f.bits));
  return out;
}

// Runs until an event fires (at most `ticks`), recording the named signals of every axis (the names of
// Card.run). Returns (ticks run, [per-axis dict of arrays], [(tick, axis, word, bits), ...]). The buffers grow
// in chunks, so a run that stops early costs what it ran, not what it might have.
py::tuple run_until_event(Card& card, double ticks, const std::vector<std::string>& wanted) {
  check_integer("Card.run_until_event", "ticks", ticks, 0, 1e9);
  scope_of(card);  // the vendor words, before the first tick watched
  const std::size_t n_ax = card.axis_count();
  const auto n = static_cast<std::size_t>(ticks);
  // The run usually ends at an event long before `ticks`: its buffers are checked before each growth.
  const auto too_big = [&](std::size_t m) {
    return static_cast<double>(m) * static_cast<double>(n_ax * wanted.size()) * 8.0 > kMaxRecordBytes;
  };
  std::vector<std::map<std::string, std::vector<double>>> buf(n_ax);
  std::size_t ran = 0;
  {
    RunLock lock(card_keys(card));
    py::gil_scoped_release release;
    constexpr std::size_t kChunk = 4096;
    std::vector<machine::CardTrace> tr;
    if (!wanted.empty()) tr.resize(n_ax);
    do {
      const std::size_t chunk = std::min(kChunk, n - ran);
      if (too_big(ran + chunk))
        throw_invalid("Card.run_until_event", "ticks", ticks,
                      "would record more than the 2 GB a run may record; record fewer signals or run in pieces");
      for (std::size_t i = 0; i < n_ax && !wanted.empty(); ++i) {
        auto& b = buf[i];
        for (const auto& w : wanted) b[w].resize(ran + chunk);
        machine::CardTrace& t = tr[i];
#define SERVOBENCH_POINT(name, unit, doc) \
  if (auto it = b.find(#name); it != b.end()) t.axis.name = it->second.data() + ran;
        SERVOBENCH_TRACE_SIGNALS(SERVOBENCH_POINT)
#undef SERVOBENCH_POINT
#define SERVOBENCH_POINT(name, unit, doc) \
  if (auto it = b.find(#name); it != b.end()) t.loop.name = it->second.data() + ran;
        SERVOBENCH_LOOP_SIGNALS(SERVOBENCH_POINT)
#undef SERVOBENCH_POINT
        if (auto it = b.find("events"); it != b.end()) t.events = it->second.data() + ran;
        if (auto it = b.find("moving"); it != b.end()) t.moving = it->second.data() + ran;
        if (auto it = b.find("servo_on"); it != b.end()) t.servo_on = it->second.data() + ran;
        if (auto it = b.find("prf_vel"); it != b.end()) t.prf_vel = it->second.data() + ran;
      }
      bool fired = false;
      {
        auto held = lock.chunk();
        ran += card.run_until_event(chunk, tr);
        fired = scope_of(card).run_ended();
      }
      if (fired || ran >= n) break;
      check_signals();
    } while (true);
  }
  py::list rec;
  for (std::size_t i = 0; i < n_ax; ++i) {
    py::dict d;
    for (const auto& w : wanted) {
      std::vector<double>& v = buf[i][w];
      v.resize(ran);
      d[py::str(w)] = to_array(v);
    }
    rec.append(d);
  }
  return py::make_tuple(ran, rec, fired_list(card));
}

}  // namespace

void bind_card_scope(py::module_& m, py::class_<Card>& c) {
  py::list sigs;
  for (int k = 0; k < machine::kSampleSignalCount; ++k) {
    const auto& info = machine::sample_signal_info(static_cast<machine::SampleSignal>(k));
    sigs.append(py::make_tuple(info.name, info.unit, info.doc));
  }
  m.attr("SAMPLE_SIGNALS") = sigs;

  c.def("sampler_start",
        [](Card& k, const std::vector<std::pair<AxisIndex, std::string>>& channels, double every_ticks, double depth,
           const std::string& trigger, double trigger_channel, double level, double event_axis, double event_bits,
           double pretrigger, Flag continuous) {
          machine::SamplerConfig cfg;
          for (const auto& [axis, name] : channels) {
            machine::SampleChannel ch;
            ch.signal = machine::sample_signal_from(name);
            // An axis goes through the one axis check; a trigger output's channel (0..3) is checked whole here and
            // against its range by SamplerConfig::validate.
            if (ch.signal == machine::SampleSignal::card_trg_pulses || ch.signal == machine::SampleSignal::card_trg_level) {
              check_integer("Sampler", "channel (trigger output)", axis.value, 0, 3);
              ch.axis = static_cast<int>(axis.value);
            } else {
              ch.axis = static_cast<int>(card_axis(k, axis));
            }
            cfg.channels.push_back(ch);
          }
          cfg.every_ticks = every_ticks;
          cfg.depth = depth;
          cfg.trigger = trigger_from(trigger);
          cfg.trigger_channel = trigger_channel;
          cfg.level = level;
          cfg.event_axis = event_axis;
          cfg.event_bits = event_bits;
          cfg.pretrigger = pretrigger;
          cfg.continuous = continuous;
          scope_of(k).start_sampler(cfg);
        },
        py::arg("channels"), py::arg("every_ticks") = 1.0, py::arg("depth") = 1000.0, py::arg("trigger") = "immediate",
        py::arg("trigger_channel") = 0.0, py::arg("level") = 0.0, py::arg("event_axis") = 0.0,
        py::arg("event_bits") = 1.0, py::arg("pretrigger") = 0.0, py::arg("continuous") = false)
      .def("sampler_stop", [](Card& k) { if (k.has_scope()) scope_of(k).sampler().stop(); })
      .def_property_readonly("sampler_state", [](Card& k) {
        return std::string(k.has_scope() ? state_name(scope_of(k).sampler().state()) : "idle");
      })
      .def_property_readonly("sampler_filled", [](Card& k) { return k.has_scope() ? scope_of(k).sampler().filled() : 0; })
      .def_property_readonly("sampler_blocks", [](Card& k) { return k.has_scope() ? scope_of(k).sampler().blocks().size() : 0; })
      .def_property_readonly("sampler_dropped", [](Card& k) { return k.has_scope() ? scope_of(k).sampler().dropped_blocks() : 0; })
      .def("sampler_pop_block", [](Card& k) -> py::object {
        if (!k.has_scope() || !scope_of(k).sampler().block_ready()) return py::none();
        const std::size_t nch = scope_of(k).sampler().config().channels.size();
        return block_tuple(scope_of(k).sampler().pop_block(), nch);
      })
      .def("sampler_snapshot", [](Card& k) -> py::object {
        if (!k.has_scope()) return py::none();
        const std::size_t nch = scope_of(k).sampler().config().channels.size();
        return block_tuple(scope_of(k).sampler().snapshot(), nch);
      })
      .def("set_watch", [](Card& k, AxisIndex i, double events, double msts, double mio) {
             check_integer("Card", "events", events, 0, 4095);
             check_integer("Card", "msts", msts, 0, 4294967295.0);
             check_integer("Card", "mio", mio, 0, 4294967295.0);
             scope_of(k).set_watch(card_axis(k, i), static_cast<std::uint32_t>(events), static_cast<std::uint32_t>(msts),
                                 static_cast<std::uint32_t>(mio));
           }, py::arg("axis"), py::arg("events"), py::arg("msts") = 0.0, py::arg("mio") = 0.0)
      .def("set_system_watch", [](Card& k, double bits) {
             check_integer("Card", "system_bits", bits, 0, 31);
             scope_of(k).set_system_watch(static_cast<std::uint32_t>(bits));
           }, py::arg("bits"))
      .def("set_timer", [](Card& k, double t) { scope_of(k).set_timer(t); }, py::arg("ticks"))
      .def_property_readonly("fired", [](const Card& k) { return fired_list(k); })
      .def("run_until_event", &run_until_event, py::arg("ticks"), py::arg("signals") = std::vector<std::string>{})
      .def("set_probe_time", [](Card& k, std::optional<double> t) {
             if (t) check_range("Card.set_probe_time", "t_s", *t, 0.0, 1e9, "s on the card clock; None = never");
             k.set_probe_time(t ? *t : std::nan(""));
           }, py::arg("t_s"), "The probe input EXI0's edge at t_s (s on the card clock, 0..1e9; None: never).")
      .def("set_probe_position", [](Card& k, AxisIndex axis, double pos) {
             scope_of(k).set_probe_position(card_axis(k, axis), pos);
           },
           py::arg("axis"), py::arg("pos"))
      .def("clear_probe_position", [](Card& k) { if (k.has_scope()) scope_of(k).clear_probe_position(); })
      .def("capture_armed", [](Card& k, AxisIndex i) {
             return std::string(machine::to_string(k.loop(card_axis(k, i)).capture().armed()));
           }, py::arg("axis"))
      .def("capture_source", [](Card& k, AxisIndex i) {
             return std::string(machine::to_string(k.loop(card_axis(k, i)).capture().source()));
           }, py::arg("axis"))
      // position compare
      .def("compare_set_source", [](Card& k, double comp, AxisIndex axis, Flag command) {
             check_integer("Card", "comparator", comp, 0, 3);
             machine::CompareSource s;
             s.axis = static_cast<int>(card_axis(k, axis));
             s.command = command;
             scope_of(k).compare().set_source(static_cast<int>(comp), s, k.axis_count());
           }, py::arg("comparator"), py::arg("axis"), py::arg("command") = false)
      .def("compare_source", [](Card& k, double comp) {
             check_integer("Card", "comparator", comp, 0, 3);
             const auto& s = scope_of(k).compare().source(static_cast<int>(comp));
             return py::make_tuple(s.axis, s.command);
           }, py::arg("comparator"))
      .def("compare_set_linear", [](Card& k, double ch, double start, double count, double interval) {
             check_integer("Card", "channel", ch, 0, 1);
             scope_of(k).compare().set_linear(static_cast<int>(ch), start, count, interval);
           }, py::arg("channel"), py::arg("start"), py::arg("count"), py::arg("interval"))
      .def("compare_set_table", [](Card& k, double ch, const std::vector<double>& pts) {
             check_integer("Card", "channel", ch, 0, 1);
             scope_of(k).compare().set_table(static_cast<int>(ch), pts);
           }, py::arg("channel"), py::arg("points"))
      .def("compare_set_table_direction", [](Card& k, double ch, double dir) {
             check_integer("Card", "channel", ch, 0, 1);
             check_integer("Card", "direction", dir, -1, 1);
             scope_of(k).compare().set_table_direction(static_cast<int>(ch), static_cast<int>(dir));
           }, py::arg("channel"), py::arg("direction"))
      .def("compare_table_direction", [](Card& k, double ch) {
             check_integer("Card", "channel", ch, 0, 1);
             return scope_of(k).compare().table_direction(static_cast<int>(ch));
           }, py::arg("channel"))
      .def("compare_set_output", [](Card& k, double trg, double sources, double width, Flag active_low, Flag toggle) {
             check_integer("Card", "output", trg, 0, 3);
             check_integer("Card", "sources", sources, 0, 31);
             machine::TriggerOutputConfig o;
             o.sources = static_cast<std::uint32_t>(sources);
             o.pulse_width_s = width;
             o.active_low = active_low;
             o.toggle = toggle;
             scope_of(k).compare().set_output(static_cast<int>(trg), o);
           }, py::arg("output"), py::arg("sources"), py::arg("pulse_width_s") = 1e-7, py::arg("active_low") = false,
           py::arg("toggle") = false)
      .def("compare_output", [](Card& k, double trg) {
             check_integer("Card", "output", trg, 0, 3);
             const auto& o = scope_of(k).compare().output(static_cast<int>(trg));
             py::dict d;
             d["sources"] = o.sources;
             d["pulse_width_s"] = o.pulse_width_s;
             d["active_low"] = o.active_low;
             d["toggle"] = o.toggle;
             return d;
           }, py::arg("output"))
      .def("compare_enable", [](Card& k, double mask) {
             check_integer("Card", "enable_mask", mask, 0, 15);
             scope_of(k).compare().set_enabled_mask(static_cast<std::uint32_t>(mask));
           }, py::arg("mask"))
      .def_property_readonly("compare_enabled", [](Card& k) { return scope_of(k).compare().enabled_mask(); })
      .def("compare_manual", [](Card& k, double trg) {
             check_integer("Card", "output", trg, 0, 3);
             scope_of(k).compare().manual(static_cast<int>(trg), static_cast<double>(k.tick()) * k.servo_period_s(), k.tick());
           }, py::arg("output"))
      .def("compare_count", [](Card& k, double trg) {
             check_integer("Card", "output", trg, 0, 3);
             return scope_of(k).compare().count(static_cast<int>(trg));
           }, py::arg("output"))
      .def("compare_reset_count", [](Card& k, double trg) {
             check_integer("Card", "output", trg, 0, 3);
             scope_of(k).compare().reset_count(static_cast<int>(trg));
           }, py::arg("output"))
      .def("compare_level", [](Card& k, double trg) {
             check_integer("Card", "output", trg, 0, 3);
             return scope_of(k).compare().level(static_cast<int>(trg));
           }, py::arg("output"))
      .def("compare_next_point", [](Card& k, double comp) {
             check_integer("Card", "comparator", comp, 0, 3);
             return scope_of(k).compare().next_point(static_cast<int>(comp));
           }, py::arg("comparator"))
      .def("compare_remaining", [](Card& k, double comp) {
             check_integer("Card", "comparator", comp, 0, 3);
             return scope_of(k).compare().remaining(static_cast<int>(comp));
           }, py::arg("comparator"))
      .def("compare_log", [](Card& k) {
             const auto& log = scope_of(k).compare().log();
             std::vector<double> t, tick, out, comp, pt;
             for (const auto& e : log) {
               t.push_back(e.time_s);
               tick.push_back(static_cast<double>(e.tick));
               out.push_back(e.output);
               comp.push_back(e.comparator);
               pt.push_back(e.point);
             }
             py::dict d;
             d["time_s"] = to_array(t);
             d["tick"] = to_array(tick);
             d["output"] = to_array(out);
             d["comparator"] = to_array(comp);
             d["point"] = to_array(pt);
             return d;
           })
      .def("compare_clear_log", [](Card& k) { scope_of(k).compare().clear_log(); });
}

}  // namespace servobench::bindings
