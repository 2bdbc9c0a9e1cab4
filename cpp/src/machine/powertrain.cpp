#include "servobench/machine/powertrain.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "servobench/common/elementary.hpp"
#include "servobench/common/validate.hpp"
#include "servobench/plant/zoh.hpp"

namespace servobench::machine {

namespace {
drive::VelocityDriveParams speed_loop_params(const DriveParams& d) {
  if (const auto* v = std::get_if<drive::VelocityDriveParams>(&d)) return *v;
  if (const auto* sp = std::get_if<drive::ServoPositionDriveParams>(&d)) return sp->speed_loop();
  drive::VelocityDriveParams unused;
  return unused;
}

// Speed-loop updates per servo tick; the servo period must hold a whole number of them.
int loop_updates_per_tick(const char* owner, double loop_rate_hz, double servo_period_s) {
  const double per_tick = servo_period_s * loop_rate_hz;
  const double m = std::round(per_tick);
  if (m < 1 || std::fabs(per_tick - m) > 1e-6 * m)
    throw_invalid(owner, "loop_rate_hz", loop_rate_hz,
                  "must be a whole multiple of the servo rate " + format_value(1.0 / servo_period_s) +
                      " Hz (the speed loop runs a whole number of times per servo tick)");
  return static_cast<int>(m);
}
}  // namespace

PowerTrain::PowerTrain(const DriveParams& drive, const plant::Mechanics& mechanics, double servo_period_s,
                       int substeps)
    : drive_(drive), mech_(mechanics), speed_loop_(speed_loop_params(drive)) {
  check_positive("PowerTrain", "servo_period_s", servo_period_s);
  check_integer("Axis", "substeps", substeps, 1, 1000);
  servo_period_s_ = servo_period_s;
  double bw = 0.0;
  if (const auto* t = std::get_if<drive::TorqueDriveParams>(&drive_)) {
    t->validate();
    kt_ = t->kt;
    i_max_ = t->max_current_a();
    amps_per_volt_ = t->amps_per_volt;
    alarm_at_s_ = t->alarm_at_s;
    bw = t->current_bw_hz;
    n_sub_ = substeps;
    loop_every_ = substeps;
  } else if (const auto* v = std::get_if<drive::VelocityDriveParams>(&drive_)) {
    v->validate();
    mode_ = Mode::kVelocity;
    velocity_mode_ = true;
    kt_ = v->kt;
    alarm_at_s_ = v->alarm_at_s;
    bw = v->current_bw_hz;
    n_sub_ = loop_updates_per_tick("VelocityDrive", v->loop_rate_hz, servo_period_s) * substeps;
    loop_every_ = substeps;
  } else if (const auto* st = std::get_if<drive::StepperDriveParams>(&drive_)) {
    st->validate();
    mode_ = Mode::kStepper;
    kt_ = 1.0;
    bw = drive::kInf;  // no current-loop state: the torque-angle curve acts directly
    alarm_at_s_ = st->alarm_at_s;
    rad_per_pulse_ = 2.0 * M_PI / st->pulses_per_rev();
    stepper_teeth_ = st->teeth();
    holding_torque_ = st->holding_torque_nm;
    n_sub_ = substeps;
    loop_every_ = substeps;
  } else {
    const auto& sp = std::get<drive::ServoPositionDriveParams>(drive_);
    sp.validate();
    mode_ = Mode::kServoPosition;
    velocity_mode_ = true;
    kt_ = sp.kt;
    alarm_at_s_ = sp.alarm_at_s;
    bw = sp.current_bw_hz;
    rad_per_pulse_ = 2.0 * M_PI / sp.pulses_per_rev;
    kpp_ = sp.kpp_per_s;
    speed_ff_ = sp.speed_feedforward;
    n_sub_ = loop_updates_per_tick("ServoPositionDrive", sp.loop_rate_hz, servo_period_s) * substeps;
    loop_every_ = substeps;
  }
  h_ = servo_period_s / n_sub_;

  const drive::DriveLti d = drive::current_loop_lti(kt_, bw);
  const Eigen::Index nd = d.a.rows();
  const Eigen::Index np = mech_.a.rows();
  const Eigen::Index n = nd + np;
  if (n > kMaxStates) throw std::invalid_argument("PowerTrain: too many states");
  drive_states_ = static_cast<int>(nd);
  const int off = drive_states_;
  motor_angle_ = off + mech_.motor_angle;
  motor_speed_ = off + mech_.motor_speed;
  load_angle_ = off + mech_.load_angle;
  load_speed_ = off + mech_.load_speed;

  // Series connection: the current loop (i_cmd -> torque) feeds the mechanics' motor-torque input.
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  Eigen::MatrixXd b = Eigen::MatrixXd::Zero(n, 3);
  a.topLeftCorner(nd, nd) = d.a;
  a.bottomLeftCorner(np, nd) = mech_.b.col(0) * d.c;
  a.bottomRightCorner(np, np) = mech_.a;
  b.topLeftCorner(nd, 1) = d.b;
  b.bottomLeftCorner(np, 1) = mech_.b.col(0) * d.d;
  b.bottomRightCorner(np, 2) = mech_.b.rightCols(2);
  const plant::Zoh z = plant::discretize_zoh(a, b, h_);
  phi_ = z.phi;
  gamma_ = z.gamma;
  x_ = Vec::Zero(n);
  x_free_ = Vec::Zero(n);

  if (mech_.bodies.size() > 2) throw std::invalid_argument("PowerTrain: at most two bodies");
  nb_ = mech_.bodies.size();
  for (std::size_t i = 0; i < nb_; ++i) {
    const plant::Body& body = mech_.bodies[i];
    body_index_[i] = plant::BodyIndex{off + body.angle_index, off + body.speed_index, body.torque_input};
    dry_[i] = body.friction.dry();
  }
  const unsigned masks = 1u << nb_;
  phi_locked_.assign(masks, phi_);
  gamma_locked_.assign(masks, gamma_);
  for (unsigned mask = 1; mask < masks; ++mask) {
    Eigen::MatrixXd al = a, bl = b;
    for (std::size_t i = 0; i < nb_; ++i) {
      if (!(mask & (1u << i))) continue;
      for (int r : {body_index_[i].angle, body_index_[i].speed}) {
        al.row(r).setZero();
        bl.row(r).setZero();
      }
    }
    const plant::Zoh zl = plant::discretize_zoh(al, bl, h_);
    Mat pl = zl.phi;
    InMat gl = zl.gamma;
    for (std::size_t i = 0; i < nb_; ++i) {
      if (!(mask & (1u << i))) continue;
      for (int r : {body_index_[i].angle, body_index_[i].speed}) {  // exactly frozen, not frozen up to rounding
        pl.row(r).setZero();
        pl(r, r) = 1.0;
        gl.row(r).setZero();
      }
    }
    phi_locked_[mask] = pl;
    gamma_locked_[mask] = gl;
  }
  stuck_.assign(nb_, 1);
  const auto fill = [&](auto& f) {
    for (unsigned mask = 0; mask < masks; ++mask) {
      f.phi[mask] = phi_locked_[mask];
      f.gamma[mask] = gamma_locked_[mask];
    }
  };
  switch (n) {
    case 2: fill(fixed_.emplace<Fixed<2>>()); break;
    case 3: fill(fixed_.emplace<Fixed<3>>()); break;
    case 4: fill(fixed_.emplace<Fixed<4>>()); break;
    case 5: fill(fixed_.emplace<Fixed<5>>()); break;
    default: break;  // other sizes (velocity drives with more states): the run-time-sized path
  }
  reset();
}

void PowerTrain::reset(double angle_rad) {
  x_.setZero();
  if (mech_.rest.size() > 0) {  // a user's linear plant (plant/lti.hpp): its own rest direction
    if (angle_rad != 0.0 && !mech_.rest_anywhere)
      throw_invalid("PowerTrain.reset", "angle_rad", angle_rad,
                    "must be 0: this plant has no rest state away from angle 0 (no free integrator in its A)");
    x_.segment(drive_states_, mech_.rest.size()) = angle_rad * mech_.rest;
  } else {
    x_[motor_angle_] = angle_rad;
    x_[load_angle_] = angle_rad;
  }
  for (auto& s : stuck_) s = 1;
  volts_ = 0.0;
  i_cmd_ = 0.0;
  alarm_ = false;
  substep_count_ = 0;
  speed_loop_.reset();
  cmd_start_ = cmd_end_ = cmd_angle_ = angle_origin_ = angle_rad;
  pulse_primed_ = false;
  stepper_torque_ = 0.0;
}

void PowerTrain::set_pulse_input(double pulses) {
  if (!pulse_primed_) {  // the first command pulse count is where the axis stands
    angle_origin_ = x_[motor_angle_] - pulses * rad_per_pulse_;
    pulse_primed_ = true;
    cmd_end_ = x_[motor_angle_];
  }
  cmd_start_ = cmd_end_;
  cmd_end_ = angle_origin_ + pulses * rad_per_pulse_;
}

void PowerTrain::set_state(double motor_angle_rad, double motor_speed_rad_s, double load_angle_rad,
                           double load_speed_rad_s) {
  for (double v : {motor_angle_rad, motor_speed_rad_s, load_angle_rad, load_speed_rad_s})
    if (!std::isfinite(v)) throw_invalid("PowerTrain", "state", v, "is not a finite number");
  if (mech_.rigid() && (load_angle_rad != motor_angle_rad || load_speed_rad_s != motor_speed_rad_s))
    throw std::invalid_argument("PowerTrain.state: a rigid plant's load angle and speed equal the motor's");
  x_[motor_angle_] = motor_angle_rad;
  x_[motor_speed_] = motor_speed_rad_s;
  x_[load_angle_] = load_angle_rad;
  x_[load_speed_] = load_speed_rad_s;
  for (std::size_t b = 0; b < nb_; ++b) stuck_[b] = x_[body_index_[b].speed] == 0.0;
}

void PowerTrain::set_input(double volts) {
  volts_ = volts;
  if (!velocity_mode_) {
    const double i = amps_per_volt_ * volts;
    i_cmd_ = alarm_ ? 0.0 : (i > i_max_ ? i_max_ : (i < -i_max_ ? -i_max_ : i));
  }
}

void PowerTrain::advance_tick() {
  for (int s = 0; s < n_sub_; ++s) {
    sub_in_tick_ = s;
    substep();
  }
}

void PowerTrain::substep() {
  if (!alarm_ && static_cast<double>(substep_count_) * h_ >= alarm_at_s_) {
    alarm_ = true;
    speed_loop_.reset();
  }
  if (pulse_input()) {  // the step train arrives evenly over the tick
    cmd_angle_ = cmd_start_ + (cmd_end_ - cmd_start_) * (static_cast<double>(sub_in_tick_ + 1) / n_sub_);
  }
  if (alarm_) {
    i_cmd_ = 0.0;
  } else if (velocity_mode_ && substep_count_ % loop_every_ == 0) {
    if (mode_ == Mode::kServoPosition) {
      const double ff = speed_ff_ * (cmd_end_ - cmd_start_) / servo_period_s_;
      i_cmd_ = speed_loop_.update_speed(kpp_ * (cmd_angle_ - x_[motor_angle_]) + ff, x_[motor_speed_]);
    } else {
      i_cmd_ = speed_loop_.update(volts_, x_[motor_speed_]);
    }
  }
  ++substep_count_;

  // External torques held over the sub-step (N*m): motor-body and load-body columns.
  const plant::Disturbances& dist = mech_.disturbances;
  double t_motor = 0.0;
  if (dist.cogging_nm != 0.0) t_motor = dist.cogging_nm * sin_inline(dist.cogging_periods * x_[motor_angle_]);
  if (mode_ == Mode::kStepper) {  // the stepper's torque-angle curve
    stepper_torque_ = alarm_ ? 0.0 : holding_torque_ * std::sin(stepper_teeth_ * (cmd_angle_ - x_[motor_angle_]));
    t_motor += stepper_torque_;
  }
  double t_load = -dist.load_nm;
  if (dist.unbalance_nm != 0.0) t_load -= dist.unbalance_nm * sin_inline(x_[load_angle_]);

  friction_step(t_motor, t_load);
}

void PowerTrain::friction_step(double t_motor, double t_load) {
  switch (fixed_.index()) {
    case 1: fixed_step(*std::get_if<Fixed<2>>(&fixed_), t_motor, t_load); return;
    case 2: fixed_step(*std::get_if<Fixed<3>>(&fixed_), t_motor, t_load); return;
    case 3: fixed_step(*std::get_if<Fixed<4>>(&fixed_), t_motor, t_load); return;
    case 4: fixed_step(*std::get_if<Fixed<5>>(&fixed_), t_motor, t_load); return;
    default:
      plant::advance_with_dry_friction(nb_, body_index_, dry_, phi_locked_, gamma_locked_, i_cmd_, t_motor, t_load,
                                       x_, x_free_, stuck_.data());
  }
}

template <int N>
void PowerTrain::fixed_step(const Fixed<N>& f, double t_motor, double t_load) {
  Eigen::Matrix<double, N, 1> x = x_, x_free;
  plant::advance_with_dry_friction(nb_, body_index_, dry_, f.phi, f.gamma, i_cmd_, t_motor, t_load, x, x_free,
                                   stuck_.data());
  x_ = x;
}

TickModel PowerTrain::linear_tick_model() const {
  if (pulse_input())
    throw std::invalid_argument(
        "PowerTrain.linear_tick_model: a pulse-input drive (stepper, servo in position mode) has no voltage input");
  const Eigen::Index n = x_.size();
  const bool speed_loop = mode_ == Mode::kVelocity;
  const Eigen::Index na = n + (speed_loop ? 2 : 0);  // [x; speed-loop integrator; held current command]
  const Eigen::MatrixXd phi = phi_;
  const Eigen::VectorXd g = gamma_.col(0);
  // One sub-step with the current command held, and (velocity mode) one with a speed-loop update first.
  Eigen::MatrixXd a_hold = Eigen::MatrixXd::Identity(na, na), a_upd;
  Eigen::VectorXd b_hold = Eigen::VectorXd::Zero(na), b_upd;
  a_hold.topLeftCorner(n, n) = phi;
  if (!speed_loop) {
    b_hold.head(n) = g * amps_per_volt_;  // i_cmd = A/V * v, the same in every sub-step
  } else {
    const drive::VelocityDriveParams p = speed_loop_params(drive_);
    const double kitd = p.ki_nm_per_rad / p.loop_rate_hz, kv = p.speed_per_volt_rad_s;
    const Eigen::Index integ = n, hold = n + 1;
    a_hold.block(0, hold, n, 1) = g;  // x' = phi x + g i_hold
    // Update: e = kv v - w; integ' = integ + kitd e; i = (kp e + integ') / kt; i_hold' = i; x' = phi x + g i.
    Eigen::RowVectorXd i_row = Eigen::RowVectorXd::Zero(na);  // i as a function of z (the v part in i_v)
    i_row(motor_speed_) = -(p.kp_nms + kitd) / p.kt;
    i_row(integ) = 1.0 / p.kt;
    const double i_v = (p.kp_nms + kitd) * kv / p.kt;
    a_upd = Eigen::MatrixXd::Zero(na, na);
    b_upd = Eigen::VectorXd::Zero(na);
    a_upd.topLeftCorner(n, n) = phi;
    a_upd.topRows(n) += g * i_row;
    b_upd.head(n) = g * i_v;
    a_upd(integ, integ) = 1.0;
    a_upd(integ, motor_speed_) = -kitd;
    b_upd(integ) = kitd * kv;
    a_upd.row(hold) = i_row;
    b_upd(hold) = i_v;
  }
  TickModel m;
  m.a = Eigen::MatrixXd::Identity(na, na);
  m.b = Eigen::MatrixXd::Zero(na, 1);
  for (int s = 0; s < n_sub_; ++s) {
    const bool update = speed_loop && s % loop_every_ == 0;
    const Eigen::MatrixXd& as = update ? a_upd : a_hold;
    const Eigen::VectorXd& bs = update ? b_upd : b_hold;
    m.a = (as * m.a).eval();
    m.b = (as * m.b + bs).eval();
  }
  m.c_motor = Eigen::MatrixXd::Zero(1, na);
  m.c_load = Eigen::MatrixXd::Zero(1, na);
  m.c_motor(0, motor_angle_) = 1.0;
  m.c_load(0, load_angle_) = 1.0;
  return m;
}

double PowerTrain::mechanical_energy_j() const {
  double e = 0.0;
  for (std::size_t b = 0; b < nb_; ++b) {
    const double w = x_[body_index_[b].speed];
    e += 0.5 * mech_.bodies[b].inertia_kgm2 * w * w;
  }
  if (!mech_.rigid()) {
    const double k = -mech_.a(mech_.load_speed, mech_.load_angle) * mech_.bodies.back().inertia_kgm2;
    const double twist = x_[motor_angle_] - x_[load_angle_];
    e += 0.5 * k * twist * twist;
  }
  return e;
}

}  // namespace servobench::machine
