// The APS runner's interpolation chapter (aps_commands.hpp): APS_line / _v / _all, the linear moves, the arcs and
// spirals (manual seed 004 L2813-3150; argument lists V113; transition modes L3085-3143, V114) onto the card's ADLINK
// interpolation group (adlink_group.hpp). Units: pulse, pulse/s, pulse/s^2, degrees; TransPara pulse (mode 6) or
// percent (mode 7). Decisions AY1, AY4; the checks are the ones the dialect made, in the same order.
#include <algorithm>
#include <cmath>
#include <optional>
#include <set>

#include "aps_commands_detail.hpp"
#include "servobench/vendor/adlink/adlink_group.hpp"

namespace servobench::vendor::adlink::detail {

namespace {

using C = AdlinkCode;
using machine::Card;
using motion::AdlinkMoveSpec;
using motion::AdlinkPtpParams;
using motion::BlendMode;
using K = AdlinkMoveSpec::Kind;

// The speeds of an _all form (pulse/s, pulse/s^2, S-factor), NaN where not a number.
struct AllSpeeds {
  double vs, vm, ve, acc, dec, sf;
};

// One interpolation command as the arguments give it, before its checks.
struct Interp {
  std::vector<double> ids;                 // the axis array
  double option = kNaN;                    // Option: bit 0 relative, bit 8 MF_WAIT, bits 12-15 the mode
  bool trans_none = false;                 // TransPara not given (None): 0
  double trans = 0.0;                      // TransPara
  std::optional<double> vm;                // the _v / _all forms' Vm
  std::optional<AllSpeeds> all;            // the _all form's speeds
  K kind = K::Line;
  std::vector<double> target, center, normal;  // pulse
  std::optional<double> angle, dir, height, final_r;  // deg, laps, pulse, pulse
};

bool finite_all(const std::vector<double>& v) {
  return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
}

// The checks and the card call of every interpolation command (L2813-3150).
C interp(const Call& c, const Interp& m) {
  if (c.card == nullptr) return C::DeviceNotInitial;
  Card& k = *c.card;
  std::vector<std::size_t> arr;
  for (double a : m.ids) {
    const auto i = c.axis_of(a);
    if (!i) return C::ParametersInvalid;
    arr.push_back(*i);
  }
  if (std::set<std::size_t>(arr.begin(), arr.end()).size() != arr.size() || arr.size() < 2 || arr.size() > 6 ||
      !whole(m.option))
    return C::ParametersInvalid;
  const auto o = std::fabs(m.option) > 4294967295.0 ? ~0LL : static_cast<long long>(m.option);
  const long long field = (o >> 12) & 0xF;
  if ((o & ~(1LL | kMfWait | 0xF000LL)) || field > 6) return C::ParametersInvalid;
  const auto mode = static_cast<BlendMode>(field + 1);  // the field value f is mode f + 1 (V114)
  const double t = m.trans_none ? 0.0 : m.trans;
  if (!std::isfinite(t)) return C::ParametersInvalid;
  vendor::adlink::AdlinkGroupMove mv;
  mv.blend = mode == BlendMode::BlendDistance || mode == BlendMode::BlendPercent ? t : 0.0;
  for (const auto& s : {m.angle, m.height, m.final_r})
    if (s && !std::isfinite(*s)) return C::ParametersInvalid;
  if (m.dir && (!whole(*m.dir) || std::fabs(*m.dir) > 32767)) return C::ParametersInvalid;  // I16 Dir
  if (!finite_all(m.target) || !finite_all(m.center) || !finite_all(m.normal)) return C::ParametersInvalid;
  if (m.all) {
    const AllSpeeds& s = *m.all;
    for (double x : {s.vs, s.vm, s.ve, s.acc, s.dec, s.sf})
      if (!std::isfinite(x)) return C::ParametersInvalid;
    const AdlinkPtpParams p{0.0, s.vs, s.vm, s.ve, s.acc, s.dec, s.sf, c.prm().axis(arr[0]).motion.sd_dec};
    if (!valid(p)) return C::ParametersInvalid;
    mv.all = p;
  }
  const double v = m.vm ? *m.vm : 0.0;
  if (!std::isfinite(v) || (m.vm && !(v > 0 && v <= 1e9))) return C::ParametersInvalid;
  for (std::size_t a : arr) aps_release_axis(k, a);
  const AdlinkGroup* g = adlink_group(k);
  if (g != nullptr && !g->busy()) aps_release_modes(k, arr[0]);
  for (std::size_t a : arr) {
    mv.params.push_back(c.prm().axis(a).motion);
    if (!valid(mv.params.back())) return C::ParametersInvalid;
  }
  mv.array = arr;
  AdlinkMoveSpec& spec = mv.spec;
  spec.kind = m.kind;
  spec.relative = (o & 1) != 0;
  std::copy(m.target.begin(), m.target.end(), spec.target.begin());
  std::copy(m.center.begin(), m.center.end(), spec.center.begin());
  if (!m.normal.empty()) spec.normal = {m.normal[0], m.normal[1], m.normal[2]};
  spec.angle_deg = m.angle.value_or(0.0);
  spec.dir = static_cast<int>(m.dir.value_or(0.0));
  spec.height = m.height.value_or(0.0);
  spec.final_radius = m.final_r.value_or(0.0);
  mv.mode = mode;
  mv.vm = v;
  mv.wait = (o & kMfWait) != 0;
  return run(k, [&] { adlink_group_move(k, mv); });
}

// -- APS_line / _v / _all and the linear moves --------------------------------------------------------------------
// APS_line*(Dimension, Axis_ID_Array, Option, PositionArray, TransPara, [speeds], Wait): the first Dimension axes.
C line(const Call& c, const std::vector<double>& ids, const std::vector<double>& pos, double option, bool trans_none,
       double trans, bool wait_ok, std::optional<double> vm, std::optional<AllSpeeds> all) {
  const double d = c.num(0);
  if (!wait_ok || !whole(d)) return c.bad();
  if (d < 0 || static_cast<double>(ids.size()) < d || static_cast<double>(pos.size()) < d) return C::ParametersInvalid;
  const auto n = static_cast<std::ptrdiff_t>(d);
  Interp m;
  m.ids.assign(ids.begin(), ids.begin() + n);
  m.target.assign(pos.begin(), pos.begin() + n);
  m.option = option;
  m.trans_none = trans_none;
  m.trans = trans;
  m.vm = vm;
  m.all = all;
  return interp(c, m);
}

std::optional<double> given(const Call& c, std::size_t k) {
  return c.none(k) ? std::nullopt : std::optional<double>(c.num(k));
}

ApsReply line_prm(const Call& c) {
  return code(line(c, c.vec(1), c.vec(3), c.num(2), c.none(4), c.num(4), c.wait_ok(5), std::nullopt, std::nullopt));
}
ApsReply line_v(const Call& c) {
  return code(line(c, c.vec(1), c.vec(3), c.num(2), c.none(4), c.num(4), c.wait_ok(6), given(c, 5), std::nullopt));
}
ApsReply line_all(const Call& c) {  // ..., TransPara 4, Vs 5, Vm 6, Ve 7, Acc 8, Dec 9, SFac 10, Wait 11
  const AllSpeeds s{c.num(5), c.num(6), c.num(7), c.num(8), c.num(9), c.num(10)};
  return code(line(c, c.vec(1), c.vec(3), c.num(2), c.none(4), c.num(4), c.wait_ok(11), given(c, 6), s));
}

// APS_absolute/relative_linear_move(Dimension, Axis_ID_Array, Position_Array, Max_Linear_Speed): whole pulses and
// a whole speed, then APS_line_v with Option 0 / 1.
template <int Relative>
ApsReply linear_move(const Call& c) {
  const std::vector<double>& vals = c.vec(2);
  for (double x : vals)
    if (!whole(x) || std::fabs(x) > kPosMax) return code(C::ParametersInvalid);
  const double s = c.num(3);
  if (!whole(s)) return code(C::ParametersInvalid);
  return code(line(c, c.vec(1), vals, Relative, false, 0.0, true, s, std::nullopt));
}

// -- arcs and spirals (L2899-3063) -------------------------------------------------------------------------------
enum class G { Center, End, Normal, Angle, Dir, DeltaH, FinalR };
struct Arc {
  K kind;
  std::size_t dim;
  std::vector<G> geom;  // the manual's geometry arguments after Option
};
const Arc kArcs[] = {
    {K::Arc2Ca, 2, {G::Center, G::Angle}},
    {K::Arc2Ce, 2, {G::Center, G::End, G::Dir}},
    {K::Arc3Ca, 3, {G::Center, G::Normal, G::Angle}},
    {K::Arc3Ce, 3, {G::Center, G::End, G::Dir}},
    {K::SpiralCa, 3, {G::Center, G::Normal, G::Angle, G::DeltaH, G::FinalR}},
    {K::SpiralCe, 3, {G::Center, G::Normal, G::End, G::Dir}},
};

// APS_<arc>[_v|_all](Axis_ID_Array, Option, geometry..., TransPara, [Vm | Vs, Vm, Ve, Acc, Dec, SFac], Wait).
template <int Row, int Form>
ApsReply arc(const Call& c) {
  const Arc& r = kArcs[Row];
  const std::size_t t = 2 + r.geom.size(), speeds = Form == 0 ? 0 : Form == 1 ? 1 : 6;
  if (!c.wait_ok(t + 1 + speeds)) return code(c.bad());
  Interp m;
  m.kind = r.kind;
  bool sizes_ok = c.vec(0).size() == r.dim;
  for (std::size_t g = 0; g < r.geom.size(); ++g) {
    const std::size_t k = 2 + g;
    switch (r.geom[g]) {
      case G::Center: m.center = c.vec(k), sizes_ok = sizes_ok && m.center.size() == r.dim; break;
      case G::End: m.target = c.vec(k), sizes_ok = sizes_ok && m.target.size() == r.dim; break;
      case G::Normal: m.normal = c.vec(k), sizes_ok = sizes_ok && m.normal.size() == 3; break;
      case G::Angle: m.angle = c.num(k); break;
      case G::Dir: m.dir = c.num(k); break;
      case G::DeltaH: m.height = c.num(k); break;
      case G::FinalR: m.final_r = c.num(k); break;
    }
  }
  if (!sizes_ok) return code(C::ParametersInvalid);
  m.ids = c.vec(0);
  m.option = c.num(1);
  m.trans_none = c.none(t);
  m.trans = c.num(t);
  if (Form == 1) m.vm = given(c, t + 1);
  if (Form == 2) {
    m.vm = given(c, t + 2);
    m.all = AllSpeeds{c.num(t + 1), c.num(t + 2), c.num(t + 3), c.num(t + 4), c.num(t + 5), c.num(t + 6)};
  }
  return code(interp(c, m));
}

// The argument kinds of an arc row's form: the array, Option, the geometry, TransPara, the speeds, Wait.
template <int Row, int Form>
Named arc_row(const char* name) {
  static const std::string kinds = [] {
    std::string s = "an";
    for (G g : kArcs[Row].geom) s += g == G::Center || g == G::End || g == G::Normal ? 'a' : 'n';
    return s + std::string(Form == 0 ? 0 : Form == 1 ? 1 : 6, 'n') + "nn";
  }();
  return {name, {&arc<Row, Form>, kinds.c_str(), ""}};
}

}  // namespace

const std::vector<Named>& interp_commands() {
  static const std::vector<Named> kRows = {
      {"APS_line", {&line_prm, "nanann", ""}},
      {"APS_line_v", {&line_v, "nanannn", ""}},
      {"APS_line_all", {&line_all, "nanannnnnnnn", ""}},
      {"APS_absolute_linear_move", {&linear_move<0>, "naan", ""}},
      {"APS_relative_linear_move", {&linear_move<1>, "naan", ""}},
      arc_row<0, 0>("APS_arc2_ca"), arc_row<0, 1>("APS_arc2_ca_v"), arc_row<0, 2>("APS_arc2_ca_all"),
      arc_row<1, 0>("APS_arc2_ce"), arc_row<1, 1>("APS_arc2_ce_v"), arc_row<1, 2>("APS_arc2_ce_all"),
      arc_row<2, 0>("APS_arc3_ca"), arc_row<2, 1>("APS_arc3_ca_v"), arc_row<2, 2>("APS_arc3_ca_all"),
      arc_row<3, 0>("APS_arc3_ce"), arc_row<3, 1>("APS_arc3_ce_v"), arc_row<3, 2>("APS_arc3_ce_all"),
      arc_row<4, 0>("APS_sprial_ca"), arc_row<4, 1>("APS_sprial_ca_v"), arc_row<4, 2>("APS_sprial_ca_all"),
      arc_row<5, 0>("APS_sprial_ce"), arc_row<5, 1>("APS_sprial_ce_v"), arc_row<5, 2>("APS_sprial_ce_all"),
  };
  return kRows;
}

}  // namespace servobench::vendor::adlink::detail
