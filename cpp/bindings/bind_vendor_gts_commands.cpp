// The GUC-ECAT / iDEABOX vendor functions (vendor/googol/gts_commands.hpp: profiles, stops, crd, look-ahead, PVT
// tables; gts_config.hpp: system configuration and read-backs): thin, each returns the manual's code as an int (a
// read: a tuple (code, value...)); servobench.dialects.gts and _gts_config have one row per command over these.
// Card axes and profiles from 1, as the manuals print them.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>

#include "arrays.hpp"
#include "lock_table.hpp"
#include "object_lock.hpp"
#include "servobench/machine/card.hpp"
#include "servobench/vendor/googol/gts_commands.hpp"
#include "servobench/vendor/googol/gts_config.hpp"

namespace servobench::bindings {

namespace py = pybind11;
using machine::Card;
using Vec = std::vector<double>;

void bind_vendor_gts_commands(py::module_& m) {
  namespace g = vendor::googol;
  auto code = [](g::GucCode c) { return static_cast<int>(c); };
  m.def("gts_set_trap_prm", [code](Card& k, double p, double acc, double dec, double vs, double st) {
        return code(g::gts_set_trap_prm(k, p, acc, dec, vs, st)); }, py::arg("card"), py::arg("profile"),
        py::arg("acc"), py::arg("dec"), py::arg("vel_start"), py::arg("smooth_time"),
        "GT_SetTrapPrm: acc, dec > 0 pulse/ms^2; vel_start = smooth_time = 0");
  m.def("gts_set_jog_prm", [code](Card& k, double p, double acc, double dec, double smooth) {
        return code(g::gts_set_jog_prm(k, p, acc, dec, smooth)); }, py::arg("card"), py::arg("profile"),
        py::arg("acc"), py::arg("dec"), py::arg("smooth"), "GT_SetJogPrm: acc, dec > 0 pulse/ms^2; smooth 0..1");
  m.def("gts_stop", [code](Card& k, double mask, double option) { return code(g::gts_stop(k, mask, option)); },
        py::arg("card"), py::arg("mask"), py::arg("option"), "GT_Stop: bit k axis k+1, bits 12/13 crd 1/2");
  m.def("gts_set_crd_prm", [code](Card& k, double crd, double dim, const Vec& profile, double vel, double acc,
                                  double even, double origin_flag, const Vec& origin) {
        return code(g::gts_set_crd_prm(k, crd, g::GtsCrdPrm{dim, profile, vel, acc, even, origin_flag, origin}));
      }, py::arg("card"), py::arg("crd"), py::arg("dimension"), py::arg("profile"), py::arg("syn_vel_max"),
      py::arg("syn_acc_max"), py::arg("even_time"), py::arg("set_origin_flag"), py::arg("origin_pos"),
      "GT_SetCrdPrm: TCrdPrm's fields (pulse/ms, pulse/ms^2, ms, pulse)");
  m.def("gts_get_crd_prm", [](Card& k, double crd) -> py::tuple {
        const auto [c, p] = g::gts_get_crd_prm(k, crd);
        if (c != g::GucCode::Success) return py::make_tuple(static_cast<int>(c), py::none());
        return py::make_tuple(0, p.dimension, std::vector<int>(p.profile.begin(), p.profile.end()), p.syn_vel_max,
                              p.syn_acc_max, static_cast<int>(p.even_time_ms), static_cast<int>(p.set_origin),
                              Vec(p.origin_pos.begin(), p.origin_pos.end()));
      }, py::arg("card"), py::arg("crd"),
      "GT_GetCrdPrm: (0, dimension, profile, synVelMax, synAccMax, evenTime, setOriginFlag, originPos) or (code, None)");
  m.def("gts_init_lookahead", [code](Card& k, double crd, double fifo, double t, double acc, double n) {
        return code(g::gts_init_lookahead(k, crd, fifo, t, acc, n)); }, py::arg("card"), py::arg("crd"),
        py::arg("fifo"), py::arg("t_ms"), py::arg("acc_max"), py::arg("n"), "GT_InitLookAhead");
  m.def("gts_crd_data", [code](Card& k, double crd, bool null_data, double fifo) {
        return code(g::gts_crd_data(k, crd, null_data, fifo)); }, py::arg("card"), py::arg("crd"),
        py::arg("null_data"), py::arg("fifo"), "GT_CrdData(crd, NULL, fifo)");
  // PVT tables: arrays of the manual's units (ms, pulse, pulse/ms, percent 0..100, pulse/ms^2), first count used
  m.def("gts_pvt_table", [code](Card& k, double id, double n, const Vec& t, const Vec& p, const Vec& v) {
        return code(g::gts_pvt_table(k, id, n, t, p, v)); }, py::arg("card"), py::arg("table_id"), py::arg("count"),
        py::arg("time_ms"), py::arg("pos"), py::arg("vel"), "GT_PvtTable");
  m.def("gts_pvt_table_ex", [code](Card& k, double id, double n, const Vec& t, const Vec& p, const Vec& vb,
                                   const Vec& ve) { return code(g::gts_pvt_table_ex(k, id, n, t, p, vb, ve)); },
        py::arg("card"), py::arg("table_id"), py::arg("count"), py::arg("time_ms"), py::arg("pos"),
        py::arg("vel_begin"), py::arg("vel_end"), "GT_PvtTableEx");
  m.def("gts_pvt_table_complete", [code](Card& k, double id, double n, const Vec& t, const Vec& p, double vb,
                                         double ve) { return code(g::gts_pvt_table_complete(k, id, n, t, p, vb, ve)); },
        py::arg("card"), py::arg("table_id"), py::arg("count"), py::arg("time_ms"), py::arg("pos"),
        py::arg("vel_begin"), py::arg("vel_end"), "GT_PvtTableComplete");
  m.def("gts_pvt_table_percent", [code](Card& k, double id, double n, const Vec& t, const Vec& p, const Vec& q,
                                        double vb) { return code(g::gts_pvt_table_percent(k, id, n, t, p, q, vb)); },
        py::arg("card"), py::arg("table_id"), py::arg("count"), py::arg("time_ms"), py::arg("pos"),
        py::arg("percent"), py::arg("vel_begin"), "GT_PvtTablePercent");
  m.def("gts_pvt_table_continuous", [code](Card& k, double id, double n, const Vec& p, const Vec& v, const Vec& qa,
                                           const Vec& qd, const Vec& vm, const Vec& a, const Vec& d, double tb,
                                           bool ex) {
        return code(g::gts_pvt_table_continuous(k, id, n, {p, v, qa, qd, vm, a, d}, tb, ex)); },
        py::arg("card"), py::arg("table_id"), py::arg("count"), py::arg("pos"), py::arg("vel"),
        py::arg("acc_percent"), py::arg("dec_percent"), py::arg("vel_max"), py::arg("acc"), py::arg("dec"),
        py::arg("time_begin_ms"), py::arg("ex"), "GT_PvtTableContinuous (ex false) / GT_PvtTableContinuousEx");
  m.def("gts_pvt_percent_calculate", [](double n, const Vec& t, const Vec& p, const Vec& q, double vb) {
        const auto [c, v] = g::gts_pvt_percent_calculate(n, t, p, q, vb);
        return py::make_tuple(static_cast<int>(c), c == g::GucCode::Success ? py::object(to_array(v)) : py::none());
      }, py::arg("count"), py::arg("time_ms"), py::arg("pos"), py::arg("percent"), py::arg("vel_begin"),
      "GT_PvtPercentCalculate: (0, node velocities pulse/ms) or (7, None)");
  m.def("gts_pvt_continuous_calculate", [](double n, const Vec& p, const Vec& v, const Vec& q, const Vec& vm,
                                           const Vec& a, const Vec& d) {
        const auto [c, t] = g::gts_pvt_continuous_calculate(n, {p, v, q, q, vm, a, d});
        return py::make_tuple(static_cast<int>(c), c == g::GucCode::Success ? py::object(to_array(t)) : py::none());
      }, py::arg("count"), py::arg("pos"), py::arg("vel"), py::arg("percent"), py::arg("vel_max"), py::arg("acc"),
      py::arg("dec"), "GT_PvtContinuousCalculate: (0, point times ms, time[0] = 0) or (7, None)");
  // the command table and the runner (gts_commands.hpp, decisions GX1-GX3)
  m.def("gts_command_table", [] {
        py::list rows;
        for (const auto& r : g::gts_command_table()) rows.append(py::make_tuple(r.name, r.params, r.fail, r.doc));
        return rows;
      }, "The GTS commands (vendor/googol/gts_commands.hpp): (name, parameters, a read's failure placeholders "
      "as a Python literal or '' for a command, doc).");
  m.def("gts_command_names", &g::gts_command_names, "The commands gts_command runs.");
  m.def("gts_command", [](Card& k, const std::string& name, const Vec& args) -> py::object {
        g::GtsReply r;
        {  // the card's state lock, as the Card's own methods hold it (a realtime clock may be ticking it)
          auto lk = lock_releasing_gil(locks_of(&k)->state);
          r = g::gts_command(k, name, args);
        }
        if (r.kinds.empty()) return py::int_(static_cast<int>(r.code));
        if (r.kinds == "l") return py::make_tuple(0, r.values);
        py::list out;
        out.append(0);
        for (std::size_t i = 0; i < r.values.size(); ++i)
          out.append(r.kinds[i] == 'i' ? py::object(py::int_(static_cast<long long>(r.values[i])))
                                       : py::object(py::float_(r.values[i])));
        return py::tuple(out);
      }, py::arg("card"), py::arg("name"), py::arg("args"),
      "Runs GTS command `name` (arguments as doubles in the manual's units): its code, or (0, values...) for a "
      "read that succeeded (a failing read: its code alone).");
  m.def("gts_follow_data_complete", [code](Card& k, double p, double f, double n, const Vec& ms, const Vec& ss,
                                           double vb, double ve) {
        auto lk = lock_releasing_gil(locks_of(&k)->state);
        return code(g::gts_follow_data_complete(k, p, f, n, ms, ss, vb, ve)); }, py::arg("card"), py::arg("profile"),
        py::arg("fifo"), py::arg("n"), py::arg("master"), py::arg("slave"), py::arg("ratio_begin"),
        py::arg("ratio_end"), "GT_FollowDataCompleteEx: n knots, cumulative pulse");
  // system configuration and read-backs (gts_config.hpp)
  m.def("gts_alarm", [code](Card& k, double a, bool on) { return code(g::gts_alarm(k, a, on)); }, py::arg("card"),
        py::arg("axis"), py::arg("on"), "GT_AlarmOn / GT_AlarmOff");
  m.def("gts_limits", [code](Card& k, double a, double t, bool on) { return code(g::gts_limits(k, a, t, on)); },
        py::arg("card"), py::arg("axis"), py::arg("limit_type"), py::arg("on"), "GT_LmtsOn / GT_LmtsOff");
  m.def("gts_limit_sense", [code](Card& k, double s) { return code(g::gts_limit_sense(k, s)); }, py::arg("card"),
        py::arg("sense"), "GT_LmtSns");
  m.def("gts_enc_sense", [code](Card& k, double s) { return code(g::gts_enc_sense(k, s)); }, py::arg("card"),
        py::arg("sense"), "GT_EncSns");
  m.def("gts_scale", [code](Card& k, double a, double al, double be) { return code(g::gts_scale(k, a, al, be)); },
        py::arg("card"), py::arg("axis"), py::arg("alpha"), py::arg("beta"), "GT_ProfileScale / GT_EncScale");
  m.def("gts_get_di", [](Card& k, double t) {
        const auto [c, w] = g::gts_get_di(k, t);
        return py::make_tuple(static_cast<int>(c), w); }, py::arg("card"), py::arg("di_type"), "GT_GetDi");
  m.def("gts_set_adc_filter", [code](Card& k, double a, double t) { return code(g::gts_set_adc_filter(k, a, t)); },
        py::arg("card"), py::arg("adc"), py::arg("filter_time"), "GT_SetAdcFilter");
  m.def("gts_get_stop_dec", [](Card& k, double p) {
        const auto [c, s, a] = g::gts_get_stop_dec(k, p);
        return py::make_tuple(static_cast<int>(c), s, a); }, py::arg("card"), py::arg("profile"), "GT_GetStopDec");
  m.def("gts_get_crd_stop_dec", [](Card& k, double crd) {
        const auto [c, s, a] = g::gts_get_crd_stop_dec(k, crd);
        return py::make_tuple(static_cast<int>(c), s, a); }, py::arg("card"), py::arg("crd"), "GT_GetCrdStopDec");
  m.def("gts_set_stop_io", [code](Card& k, double a, double st, double it, double ix) {
        return code(g::gts_set_stop_io(k, a, st, it, ix)); }, py::arg("card"), py::arg("axis"), py::arg("stop_type"),
        py::arg("input_type"), py::arg("index"), "GT_SetStopIo");
  m.def("gts_get_acc", [](Card& k, double p) {
        const auto [c, acc, smooth] = g::gts_get_acc(k, p);
        return py::make_tuple(static_cast<int>(c), acc, smooth); }, py::arg("card"), py::arg("profile"),
        "GT_GetTrapPrm / GT_GetJogPrm: (code, staged acc pulse/ms^2, jog smooth)");
  m.def("gts_get_vel_filter", [](Card& k, double a, bool enc) {
        const auto [c, e] = g::gts_get_vel_filter(k, a, enc);
        return py::make_tuple(static_cast<int>(c), e); }, py::arg("card"), py::arg("axis"), py::arg("encoder"),
        "GT_GetAxisPrfVelFilter / GT_GetAxisEncVelFilter");
  m.def("gts_get_enc_vel", [](Card& k, double a) {
        const auto [c, v] = g::gts_get_enc_vel(k, a);
        return py::make_tuple(static_cast<int>(c), v); }, py::arg("card"), py::arg("axis"), "GT_GetEncVel, pulse/ms");
}

}  // namespace servobench::bindings
