// ADLINK interpolation: 2-6 axis lines with the reference axis's profile, 2-D / 3-D arcs, spirals and the
// seven continuous-interpolation modes. Manual: ../shared/seeds/004_b417b1b5a6e5a740.txt (ADLINK PCI-8254/8258)
// §4.8, L2813-3150; digest adlink.md §6.7 and test vectors T19-T21. Units: pulse, pulse/s, 1 ms motion cycle.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "servobench/motion/adlink_interpolation.hpp"
#include "servobench/motion/generator.hpp"

namespace sm = servobench::motion;
using SP = sm::SpacePoint;
using Spec = sm::AdlinkMoveSpec;
using Mode = sm::BlendMode;

namespace {
constexpr double kPi = 3.14159265358979323846;

sm::AdlinkPtpParams params(double vm, double acc, double dec = 0, double vs = 0, double ve = 0, double sf = 0) {
  sm::AdlinkPtpParams p;
  p.vm = vm;
  p.acc = acc;
  p.dec = dec > 0 ? dec : acc;
  p.vs = vs;
  p.ve = ve;
  p.sf = sf;
  return p;
}

Spec line_to(std::vector<double> t, bool rel = false) {
  Spec s;
  s.kind = Spec::Kind::Line;
  s.relative = rel;
  for (std::size_t k = 0; k < t.size(); ++k) s.target[k] = t[k];
  return s;
}

double dist(const SP& a, const SP& b, int dim) {
  double s = 0;
  for (int k = 0; k < dim; ++k) s += (a[static_cast<std::size_t>(k)] - b[static_cast<std::size_t>(k)]) * (a[static_cast<std::size_t>(k)] - b[static_cast<std::size_t>(k)]);
  return std::sqrt(s);
}

struct Row {
  double t;
  SP pos, vel;
  double speed;
};
std::vector<Row> run(sm::AdlinkInterpolator& g, long max = 1000000) {
  std::vector<Row> out;
  for (long k = 0; k < max && !g.done(); ++k) {
    const auto& s = g.step();
    out.push_back({s.t_s, s.pos, s.vel, s.speed});
  }
  return out;
}
}  // namespace

TEST(AdlinkInterpolation, T19_LineAxisVelocitiesFromTheReferenceAxisProfile) {
  // ADLINK L2829-2855 (T19): dX = 3, dY = 4, V = 10 -> Vx = 6, Vy = 8 (here x1000). The first axis of the array
  // is the reference axis: its VM drives the path (L2819-2825).
  sm::AdlinkInterpolator g({1, 0});
  g.set_axis_params(1, params(10000, 1e6));
  g.set_axis_params(0, params(500, 1e5));  // not the reference: ignored
  g.push(line_to({3000, 4000}));
  const auto r = run(g);
  EXPECT_NEAR(r[r.size() / 2].vel[0], 6000, 1e-6);
  EXPECT_NEAR(r[r.size() / 2].vel[1], 8000, 1e-6);
  EXPECT_DOUBLE_EQ(r.back().pos[0], 3000);
  EXPECT_DOUBLE_EQ(r.back().pos[1], 4000);
  EXPECT_NEAR(r.back().t, 0.5 + 0.01, 0.0011);  // 5000 at 10000 pulse/s + one 10 ms ramp
  // Six axes, the _v form's VM.
  sm::AdlinkInterpolator h({0, 1, 2, 3, 4, 5});
  h.set_axis_params(0, params(10000, 1e6));
  h.push(line_to({100, 200, 300, 400, 500, 600}), Mode::Buffered, 0.0, 5000);
  const auto q = run(h);
  double vmax = 0;
  for (const auto& k : q) vmax = std::max(vmax, k.speed);
  EXPECT_NEAR(vmax, 5000, 1e-6);
  EXPECT_DOUBLE_EQ(q.back().pos[5], 600);
  EXPECT_THROW(sm::AdlinkInterpolator({0}), std::invalid_argument);
  EXPECT_THROW(sm::AdlinkInterpolator({0, 0}), std::invalid_argument);
  sm::AdlinkInterpolator noparams({0, 1});
  EXPECT_THROW(noparams.push(line_to({1, 1})), std::invalid_argument);
}

TEST(AdlinkGeometry, T20_CenterEndDirGivesAngleThetaPlusDirTimes360) {
  // ADLINK L2943-2958 (T20): theta = 30 deg, Dir 0, 1, 2, -1, -2 -> 30, 390, 750, -330, -690 deg.
  const double r = 1000;
  const SP start{r, 0, 0}, c{0, 0, 0}, end{r * std::cos(kPi / 6), r * std::sin(kPi / 6), 0};
  const int dirs[] = {0, 1, 2, -1, -2};
  const double expect[] = {30, 390, 750, -330, -690};
  for (int i = 0; i < 5; ++i) {
    const auto a2 = sm::SpaceSegment::arc2_ce(start, c, end, dirs[i]);
    const auto a3 = sm::SpaceSegment::arc3_ce(start, c, end, dirs[i]);
    EXPECT_NEAR(a2.sweep_rad() * 180 / kPi, expect[i], 1e-9);
    EXPECT_NEAR(a3.sweep_rad() * 180 / kPi, expect[i], 1e-9);  // normal (start - c) x (end - c) = +Z
    EXPECT_NEAR(a3.length(), r * std::fabs(expect[i]) * kPi / 180, 1e-6);
    EXPECT_EQ(a3.point_at(a3.length()), a3.end());
    EXPECT_DOUBLE_EQ(a3.end()[1], end[1]);  // the centre-end form ends exactly (L2926-2928)
  }
  // Half and full circles are refused by the centre-end form (L2930-2933).
  EXPECT_THROW(sm::SpaceSegment::arc3_ce(start, c, SP{-r, 0, 0}, 0), std::invalid_argument);
  EXPECT_THROW(sm::SpaceSegment::arc2_ce(start, c, SP{-r, 0, 0}, 0), std::invalid_argument);
  EXPECT_THROW(sm::SpaceSegment::arc2_ce(start, c, start, 1), std::invalid_argument);
  EXPECT_THROW(sm::SpaceSegment::arc3_ce(start, c, SP{0, 2 * r, 0}, 0), std::invalid_argument);  // off the circle
}

TEST(AdlinkGeometry, Arc3CenterAngleCorrectsTheNormalAndRunsLaps) {
  // L2909-2921: a normal not orthogonal to centre->start is corrected by Gram-Schmidt; 720 deg = 2 laps; the
  // right-hand rule about the normal gives the direction.
  const SP start{0, 0, 100}, c{0, 0, 0};  // centre->start along +Z
  const auto a = sm::SpaceSegment::arc3_ca(start, c, {1, 0, 0}, 90);
  const auto b = sm::SpaceSegment::arc3_ca(start, c, {1, 0, 5}, 90);  // same after the correction
  for (double s : {0.0, 30.0, a.length()}) EXPECT_LT(dist(a.point_at(s), b.point_at(s), 3), 1e-9);
  EXPECT_NEAR(a.end()[1], -100, 1e-9);  // +90 deg about +X takes +Z to -Y
  EXPECT_NEAR(a.end()[2], 0, 1e-9);
  const auto laps = sm::SpaceSegment::arc3_ca(start, c, {1, 0, 0}, 720);
  EXPECT_NEAR(laps.length(), 2 * 2 * kPi * 100, 1e-9);
  EXPECT_LT(dist(laps.end(), start, 3), 1e-9);
  EXPECT_THROW(sm::SpaceSegment::arc3_ca(start, c, {0, 0, 1}, 90), std::invalid_argument);  // normal // start
  EXPECT_THROW(sm::SpaceSegment::arc3_ca(start, c, {1, 0, 0}, 0), std::invalid_argument);
  EXPECT_THROW(sm::SpaceSegment::arc3_ca(start, start, {1, 0, 0}, 90), std::invalid_argument);
}

TEST(AdlinkGeometry, SpiralLengthIsExactAndTheSpeedUniform) {
  // L3001-3063: conical spiral from the start radius to the final radius with a rise along the normal.
  const SP start{1000, 0, 0}, c{0, 0, 0};
  const auto s = sm::SpaceSegment::spiral_ca(start, c, {0, 0, 1}, 3 * 360, 600, 200);
  // Polyline length converges to the closed form.
  double poly = 0;
  const int n = 200000;
  SP prev = start;
  for (int i = 1; i <= n; ++i) {
    const double psi = 6 * kPi * i / n;
    const double r = 1000 - 800 * i / double(n);
    const SP p{r * std::cos(psi), r * std::sin(psi), 600.0 * i / n};
    poly += dist(p, prev, 3);
    prev = p;
  }
  EXPECT_NEAR(s.length(), poly, 1e-6 * poly);
  EXPECT_NEAR(s.end()[0], 200, 1e-9);
  EXPECT_NEAR(s.end()[2], 600, 1e-9);
  // point_at inverts the arc length: equal small steps in s are equal chords (a constant path speed is a
  // constant speed in space).
  const double ds = s.length() / 1e6;
  for (int i = 0; i < 1000000; i += 99991) EXPECT_NEAR(dist(s.point_at(i * ds), s.point_at((i + 1) * ds), 3), ds, 1e-6 * ds);
  // The centre-end form ends exactly at its end point and agrees with the centre-angle form.
  const auto e = sm::SpaceSegment::spiral_ce(start, c, {0, 0, 1}, s.end(), 3);
  EXPECT_NEAR(e.sweep_rad(), s.sweep_rad(), 1e-9);
  EXPECT_NEAR(e.length(), s.length(), 1e-6);
  EXPECT_EQ(e.point_at(1e12), s.end());
  EXPECT_THROW(sm::SpaceSegment::spiral_ca(start, c, {0, 0, 1}, 90, 0, -1), std::invalid_argument);
  EXPECT_THROW(sm::SpaceSegment::spiral_ce(start, c, {0, 0, 1}, SP{500, 0, 50}, 0), std::invalid_argument);
}

TEST(AdlinkBlending, T21_ResidualPercentStartsTheNextMoveAt900Of1000) {
  // ADLINK L3138-3143 (T21): residual 10 % of a 1000-long move: the next starts at 900.
  sm::AdlinkInterpolator g({0, 1});
  g.set_axis_params(0, params(10000, 1e5));
  g.push(line_to({1000, 0}));
  g.push(line_to({1000, 1000}), Mode::BlendPercent, 10);
  const auto r = run(g);
  std::size_t k = 0;
  while (r[k].pos[1] <= 0) ++k;
  EXPECT_LT(r[k - 1].pos[0], 900 + 1e-9);
  EXPECT_GE(r[k].pos[0], 900 - 10.0);      // within one cycle at 10 pulse/ms
  EXPECT_LT(r[k].pos[0] - 900, 10.0 + 1e-9);
  EXPECT_DOUBLE_EQ(r.back().pos[0], 1000);
  EXPECT_DOUBLE_EQ(r.back().pos[1], 1000);
  // Residual distance: the same with 250 pulse.
  sm::AdlinkInterpolator h({0, 1});
  h.set_axis_params(0, params(10000, 1e5));
  h.push(line_to({1000, 0}));
  h.push(line_to({1000, 1000}), Mode::BlendDistance, 250);
  const auto q = run(h);
  k = 0;
  while (q[k].pos[1] <= 0) ++k;
  EXPECT_LT(q[k - 1].pos[0], 750 + 1e-9);
  EXPECT_LT(q[k].pos[0] - 750, 10.0 + 1e-9);
  EXPECT_THROW(h.push(line_to({0, 0}), Mode::BlendPercent, 100), std::invalid_argument);
  EXPECT_THROW(h.push(line_to({0, 0}), Mode::BlendDistance, 0), std::invalid_argument);
}

TEST(AdlinkBlending, BlendAtDecelerationKeepsCollinearSpeedAndBufferedStops) {
  // L3124-3129: blending from the deceleration start; with ACC = DEC the collinear speed stays at VM. L3117-3122:
  // buffered moves follow their own profiles (VE = 0: the speed returns to 0 between them).
  for (Mode mode : {Mode::BlendDecel, Mode::Buffered}) {
    sm::AdlinkInterpolator g({0, 1});
    g.set_axis_params(0, params(10000, 1e5));
    g.push(line_to({5000, 0}));
    g.push(line_to({10000, 0}), mode);
    const auto r = run(g);
    double vmin_mid = 1e9;
    for (const auto& k : r)
      if (k.pos[0] > 1000 && k.pos[0] < 9000) vmin_mid = std::min(vmin_mid, k.speed);
    if (mode == Mode::BlendDecel) {
      EXPECT_NEAR(vmin_mid, 10000, 1e-6);
      EXPECT_NEAR(r.back().t, 1.0 + 0.1, 0.0011);
    } else {
      EXPECT_LT(vmin_mid, 1e-6);
      EXPECT_NEAR(r.back().t, 2 * (0.5 + 0.1), 0.0011);
    }
    EXPECT_DOUBLE_EQ(r.back().pos[0], 10000);
  }
  // A corner blended at the deceleration start: smooth axis velocities (no step above ACC * cycle), a rounded
  // corner (the path never reaches (5000, 0)), exact end.
  sm::AdlinkInterpolator g({0, 1});
  g.set_axis_params(0, params(10000, 1e5));
  g.push(line_to({5000, 0}));
  g.push(line_to({5000, 5000}), Mode::BlendDecel);
  const auto r = run(g);
  double dmin = 1e9;
  for (std::size_t k = 1; k < r.size(); ++k) {
    for (int i = 0; i < 2; ++i) EXPECT_LE(std::fabs(r[k].vel[i] - r[k - 1].vel[i]), 1e5 * 1e-3 + 1e-6);
    dmin = std::min(dmin, dist(r[k].pos, SP{5000, 0}, 2));
  }
  EXPECT_GT(dmin, 100);
  EXPECT_DOUBLE_EQ(r.back().pos[1], 5000);
}

TEST(AdlinkBlending, AbortModesFlushAndSwitchAtOnce) {
  // L3087-3115: aborting modes switch at once and flush the pending moves.
  auto make = [] {
    sm::AdlinkInterpolator g({0, 1});
    auto p = params(10000, 1e5);
    p.sd_dec = 5e4;
    g.set_axis_params(0, p);
    g.push(line_to({10000, 0}));
    g.push(line_to({10000, 10000}));  // pending: flushed by the abort
    for (int k = 0; k < 300; ++k) g.step();  // at x = 2500 + ..., cruising at 10000 pulse/s
    return g;
  };
  {  // 2 AbortForced: from the present position, at the present speed, exact line; velocity jumps.
    auto g = make();
    const SP p0 = g.state().pos;
    g.push(line_to({p0[0], 5000}), Mode::AbortForced);
    EXPECT_EQ(g.pending(), 0u);
    const auto r = run(g);
    EXPECT_NEAR(r.front().speed, 10000, 1e-6);
    EXPECT_NEAR(r.front().vel[0], 0, 1e-9);  // the direction jumped
    for (const auto& k : r) EXPECT_NEAR(k.pos[0], p0[0], 1e-9);
    EXPECT_DOUBLE_EQ(r.back().pos[1], 5000);
  }
  {  // 3 AbortStop: decelerate at SD_DEC to rest, then the new move; relative target from the abort point.
    auto g = make();
    const SP p0 = g.state().pos;
    g.push(line_to({0, 3000}, true), Mode::AbortStop);
    const auto r = run(g);
    std::size_t k = 0;
    while (r[k].speed > 0) ++k;
    EXPECT_NEAR(r[k].pos[0], p0[0] + 10000.0 * 10000.0 / (2 * 5e4), 10.0 + 1e-6);  // the stop distance
    EXPECT_NEAR(r[k].t - r.front().t, 0.2, 0.0011);
    // The relative target is measured from the abort point, not from the stop point (L3111-3115).
    EXPECT_NEAR(r.back().pos[0], p0[0], 1e-9);
    EXPECT_NEAR(r.back().pos[1], p0[1] + 3000, 1e-9);
  }
  {  // 1 AbortBlend: no stop, smooth axis velocities, exact end point.
    auto g = make();
    g.push(line_to({3000, 8000}), Mode::AbortBlend);
    const auto r = run(g);
    double vmin = 1e9;
    for (std::size_t k = 1; k < r.size() / 2; ++k) {
      vmin = std::min(vmin, r[k].speed);
      for (int i = 0; i < 2; ++i) EXPECT_LE(std::fabs(r[k].vel[i] - r[k - 1].vel[i]), 1e5 * 1e-3 + 1e-6);
    }
    EXPECT_GT(vmin, 1000);
    EXPECT_NEAR(r.back().pos[0], 3000, 1e-9);
    EXPECT_NEAR(r.back().pos[1], 8000, 1e-9);
  }
  {  // stop_move: SD_DEC to rest and flush; emg_stop: at once.
    auto g = make();
    g.stop_move();
    EXPECT_EQ(g.pending(), 0u);
    const auto r = run(g);
    EXPECT_NEAR(r.back().t - r.front().t, 0.2, 0.0011);
    auto h = make();
    const SP p0 = h.state().pos;
    h.emg_stop();
    EXPECT_TRUE(h.done());
    EXPECT_EQ(h.step().pos, p0);
  }
}

TEST(AdlinkInterpolation, BufferSizeAndArcsAndSpiralsAlongThePath) {
  sm::AdlinkInterpSetup setup;
  setup.buffer_size = 3;
  sm::AdlinkInterpolator g({0, 1, 2}, setup);
  g.set_axis_params(0, params(20000, 2e5));
  Spec arc;
  arc.kind = Spec::Kind::Arc3Ca;
  arc.center = {1000, 1000, 0};
  arc.normal = {0, 0, 1};
  arc.angle_deg = 180;
  g.push(line_to({1000, 0, 0}));
  g.push(arc);  // from (1000, 0, 0) about (1000, 1000, 0): to (1000, 2000, 0)
  Spec sp;
  sp.kind = Spec::Kind::SpiralCa;
  sp.center = {1000, 1000, 0};
  sp.normal = {0, 0, 1};
  sp.angle_deg = 360;
  sp.height = 500;
  sp.final_radius = 1000;
  g.push(sp, Mode::BlendDecel);
  EXPECT_THROW(g.push(line_to({0, 0, 0})), sm::MotionCommandRefused);  // 4th pending move
  const auto r = run(g);
  EXPECT_NEAR(r.back().pos[0], 1000, 1e-6);
  EXPECT_NEAR(r.back().pos[1], 2000, 1e-6);
  EXPECT_NEAR(r.back().pos[2], 500, 1e-9);
  for (const auto& k : r) EXPECT_LE(k.speed, 2 * 20000 + 1e-6);
}

TEST(AdlinkInterpolation, DwellHoldsThePositionBetweenMoves) {
  // APS_pt_dwell (L3838, decision AF12): a Dwell holds the position dwell_s after the moves before it have
  // ended, whatever the next move's mode; the next move starts when it ends.
  sm::AdlinkInterpolator g({0, 1});  // 1 ms motion cycle
  g.set_axis_params(0, params(10000, 1e5));
  g.push(line_to({1000, 0}));
  Spec dw;
  dw.kind = Spec::Kind::Dwell;
  dw.dwell_s = 0.05;
  g.push(dw, Mode::BlendPercent, 50.0);  // a dwell is always buffered
  g.push(line_to({1000, 1000}), Mode::BlendDistance, 500.0);
  const auto r = run(g);
  int held = 0, longest = 0;
  for (std::size_t k = 1; k < r.size(); ++k) {
    const bool still = r[k].pos == r[k - 1].pos && r[k].pos[0] == 1000 && r[k].pos[1] == 0;
    held = still ? held + 1 : 0;
    longest = std::max(longest, held);
    EXPECT_FALSE(r[k].pos[1] > 0 && r[k].pos[0] < 1000) << "the second line started before the first ended";
  }
  EXPECT_GE(longest, 49);  // 50 motion cycles, less the fraction of a cycle at either end
  EXPECT_LE(longest, 51);
  EXPECT_NEAR(r.back().pos[1], 1000, 1e-9);
  Spec bad = dw;
  bad.dwell_s = 0;
  EXPECT_THROW(g.push(bad), std::invalid_argument);
}
