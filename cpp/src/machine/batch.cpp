#include "servobench/machine/batch.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <type_traits>

namespace servobench::machine {

namespace {

// The numeric fields of each part, by name (the Python parameter classes' field names).
#define SB_F(T, f) {#f, &T::f}
template <class T>
struct FieldList;
template <>
struct FieldList<plant::RigidPlantParams> {
  using T = plant::RigidPlantParams;
  static constexpr std::pair<const char*, double T::*> items[] = {
      SB_F(T, inertia_kgm2), SB_F(T, viscous_nms),  SB_F(T, coulomb_nm),      SB_F(T, static_nm),
      SB_F(T, stribeck_speed_rad_s), SB_F(T, stribeck_exponent), SB_F(T, load_nm), SB_F(T, unbalance_nm),
      SB_F(T, cogging_nm),   SB_F(T, cogging_periods)};
};
template <>
struct FieldList<plant::TwoMassPlantParams> {
  using T = plant::TwoMassPlantParams;
  static constexpr std::pair<const char*, double T::*> items[] = {
      SB_F(T, jm_kgm2),          SB_F(T, jl_kgm2),         SB_F(T, k_nm_per_rad),
      SB_F(T, c_nms_per_rad),    SB_F(T, motor_viscous_nms), SB_F(T, motor_coulomb_nm),
      SB_F(T, motor_static_nm),  SB_F(T, motor_stribeck_speed_rad_s), SB_F(T, motor_stribeck_exponent),
      SB_F(T, load_viscous_nms), SB_F(T, load_coulomb_nm), SB_F(T, load_static_nm),
      SB_F(T, load_stribeck_speed_rad_s), SB_F(T, load_stribeck_exponent), SB_F(T, load_nm),
      SB_F(T, unbalance_nm),     SB_F(T, cogging_nm),      SB_F(T, cogging_periods)};
};
template <>
struct FieldList<control::GtServoLawParams> {
  using T = control::GtServoLawParams;
  static constexpr std::pair<const char*, double T::*> items[] = {
      SB_F(T, kp), SB_F(T, ki), SB_F(T, kd), SB_F(T, kvff), SB_F(T, kaff), SB_F(T, ilmt), SB_F(T, bias),
      SB_F(T, mtr_lmt)};
};
template <>
struct FieldList<control::ApsServoLawParams> {
  using T = control::ApsServoLawParams;
  static constexpr std::pair<const char*, double T::*> items[] = {
      SB_F(T, kp),       SB_F(T, ki),         SB_F(T, kd),        SB_F(T, kvff),           SB_F(T, kaff),
      SB_F(T, kp_shift), SB_F(T, ki_shift),   SB_F(T, kd_shift),  SB_F(T, kvff_shift),     SB_F(T, kaff_shift),
      SB_F(T, pid_shift), SB_F(T, integral_limit), SB_F(T, v_bias), SB_F(T, v_limit)};
};
template <>
struct FieldList<drive::TorqueDriveParams> {
  using T = drive::TorqueDriveParams;
  static constexpr std::pair<const char*, double T::*> items[] = {
      SB_F(T, amps_per_volt), SB_F(T, kt), SB_F(T, current_limit_a), SB_F(T, torque_limit_nm),
      SB_F(T, current_bw_hz), SB_F(T, alarm_at_s)};
};
template <>
struct FieldList<drive::VelocityDriveParams> {
  using T = drive::VelocityDriveParams;
  static constexpr std::pair<const char*, double T::*> items[] = {
      SB_F(T, speed_per_volt_rad_s), SB_F(T, kp_nms), SB_F(T, ki_nm_per_rad), SB_F(T, loop_rate_hz), SB_F(T, kt),
      SB_F(T, current_limit_a), SB_F(T, torque_limit_nm), SB_F(T, current_bw_hz), SB_F(T, alarm_at_s)};
};
template <>
struct FieldList<plant::EncoderParams> {
  using T = plant::EncoderParams;
  static constexpr std::pair<const char*, double T::*> items[] = {
      SB_F(T, counts_per_rev), SB_F(T, noise_counts), SB_F(T, seed), SB_F(T, index_angle_rad)};
};
template <>
struct FieldList<drive::DacParams> {
  using T = drive::DacParams;
  static constexpr std::pair<const char*, double T::*> items[] = {SB_F(T, bits), SB_F(T, full_scale_v)};
};
#undef SB_F

template <class T, class = void>
struct HasFields : std::false_type {};
template <class T>
struct HasFields<T, std::void_t<decltype(FieldList<T>::items)>> : std::true_type {};

// Sets field `field` of p; false if p's type has no such field.
template <class T>
bool set_field(T& p, const std::string& field, double value) {
  if constexpr (HasFields<T>::value) {
    for (const auto& [name, member] : FieldList<T>::items) {
      if (field == name) {
        p.*member = value;
        return true;
      }
    }
  }
  return false;
}

template <class T>
void append_names(const T&, const char* part, std::vector<std::string>& out) {
  if constexpr (HasFields<T>::value) {
    for (const auto& item : FieldList<T>::items) out.push_back(std::string(part) + "." + item.first);
  }
}

template <class V>
bool set_in_variant(V& v, const std::string& field, double value) {
  return std::visit([&](auto& p) { return set_field(p, field, value); }, v);
}

}  // namespace

void set_axis_parameter(AxisConfig& c, const std::string& name, double value) {
  const auto dot = name.find('.');
  const std::string part = dot == std::string::npos ? "" : name.substr(0, dot);
  const std::string field = dot == std::string::npos ? name : name.substr(dot + 1);
  bool ok = false;
  if (part == "law") ok = set_in_variant(c.law, field, value);
  else if (part == "drive") ok = set_in_variant(c.drive, field, value);
  else if (part == "plant") ok = set_in_variant(c.plant, field, value);
  else if (part == "encoder") ok = set_field(c.encoder, field, value);
  else if (part == "dac") ok = set_field(c.dac, field, value);
  if (!ok) {
    std::string all;
    for (const auto& s : axis_parameter_names(c)) all += (all.empty() ? "" : ", ") + s;
    throw std::invalid_argument("parameters: unknown parameter '" + name + "' for this axis; the parameters are: " +
                                all);
  }
}

std::vector<std::string> axis_parameter_names(const AxisConfig& c) {
  std::vector<std::string> out;
  std::visit([&](const auto& p) { append_names(p, "law", out); }, c.law);
  std::visit([&](const auto& p) { append_names(p, "drive", out); }, c.drive);
  std::visit([&](const auto& p) { append_names(p, "plant", out); }, c.plant);
  append_names(c.encoder, "encoder", out);
  append_names(c.dac, "dac", out);
  return out;
}

MoveMetricsRow move_metrics(const double* cmd, const double* fb, std::size_t n, double ts, double band) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double start = cmd[0], target = cmd[n - 1];
  const double distance = target - start;
  const double sgn = distance > 0 ? 1.0 : -1.0;
  std::size_t first10 = n, first90 = n, t_end = 0;
  double over = -std::numeric_limits<double>::infinity(), peak = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const double progress = (fb[k] - start) / distance;
    if (first10 == n && progress >= 0.1) first10 = k;
    if (first90 == n && progress >= 0.9) first90 = k;
    over = std::max(over, (fb[k] - target) * sgn);
    peak = std::max(peak, std::fabs(cmd[k] - fb[k]));
    if (cmd[k] != target) t_end = k + 1;
  }
  std::size_t last_out = n;  // last index >= t_end outside the band, n = none
  for (std::size_t k = n; k-- > t_end;) {
    if (std::fabs(fb[k] - target) > band) {
      last_out = k;
      break;
    }
  }
  MoveMetricsRow m{};
  const double t10 = first10 < n ? static_cast<double>(first10) * ts : nan;
  const double t90 = first90 < n ? static_cast<double>(first90) * ts : nan;
  m.rise_time_s = t90 - t10;
  m.overshoot_pulse = std::max(0.0, over);
  m.overshoot_pct = 100.0 * m.overshoot_pulse / std::fabs(distance);
  if (last_out == n) m.settling_time_s = 0.0;
  else if (last_out == n - 1) m.settling_time_s = nan;
  else m.settling_time_s = static_cast<double>(last_out + 1) * ts - static_cast<double>(t_end) * ts;
  m.peak_following_error_pulse = peak;
  m.final_error_pulse = cmd[n - 1] - fb[n - 1];
  return m;
}

int run_batch(const BatchInput& in, const BatchOutput& out, const BatchOptions& options) {
  if (in.n == 0 || in.pos == nullptr) throw std::invalid_argument("run_batch: the command has no ticks");
  if (out.metrics && (in.n < 2 || in.pos[in.n - 1] == in.pos[0]))
    throw std::invalid_argument(
        "metrics: the move metrics need a command that moves (command[-1] != command[0]) over >= 2 ticks");
  if (out.metrics && !(out.settle_band_pulse > 0 && std::isfinite(out.settle_band_pulse)))
    throw std::invalid_argument("settle_band_pulse must be a finite number > 0 (pulse)");
  // Resolve every column name once, on the base configuration (same part types for every row).
  {
    AxisConfig probe = in.base;
    for (const auto& name : in.parameter_names) set_axis_parameter(probe, name, 0.0);
  }
  const std::size_t np = in.parameter_names.size();
  const std::size_t plants = in.plants;
  int threads = options.threads > 0 ? options.threads : static_cast<int>(std::thread::hardware_concurrency());
  threads = static_cast<int>(std::max<std::size_t>(1, std::min<std::size_t>(static_cast<std::size_t>(std::max(threads, 1)), plants)));

  // A command without its own velocity or acceleration gets them here, once for every plant: the differences each
  // axis would otherwise take tick by tick from power-on (Axis::run's loop: the first tick's velocity is
  // pos[0] - pos[0], its acceleration that minus 0), so the same doubles; with both given, a plant recording its
  // feedback only runs the plain kernel (decision FV27).
  std::vector<double> vel_buf, acc_buf;
  const double* vel = in.vel;
  const double* acc = in.acc;
  if (vel == nullptr || acc == nullptr) {
    vel_buf.resize(in.n);
    acc_buf.resize(in.n);
    double prev_cmd = in.pos[0], prev_vel = 0.0;
    for (std::size_t k = 0; k < in.n; ++k) {
      vel_buf[k] = vel ? vel[k] : in.pos[k] - prev_cmd;
      acc_buf[k] = acc ? acc[k] : vel_buf[k] - prev_vel;
      prev_cmd = in.pos[k];
      prev_vel = vel_buf[k];
    }
    vel = vel_buf.data();
    acc = acc_buf.data();
  }
  std::vector<std::string> errors(plants);  // per plant: the validation message, empty = fine
  // Plants are handed out in blocks of `block` from a shared counter (dynamic scheduling: a worker on a busy core
  // takes fewer blocks); each plant's result depends on its row only (decision FV28).
  const std::size_t per_thread = plants / (16 * static_cast<std::size_t>(threads));
  const std::size_t block = std::min<std::size_t>(64, per_thread + 1);
  std::atomic<std::size_t> next{0}, done{0};
  std::atomic<bool> stop{false};
  auto work = [&]() {
    std::vector<double> fb_scratch(out.metrics ? in.n : 0);
    for (;;) {
      if (stop.load(std::memory_order_relaxed)) return;
      const std::size_t begin = next.fetch_add(block, std::memory_order_relaxed);
      if (begin >= plants) return;
      const std::size_t end = std::min(plants, begin + block);
      for (std::size_t i = begin; i < end; ++i) {
        try {
          AxisConfig c = in.base;
          for (std::size_t j = 0; j < np; ++j)
            set_axis_parameter(c, in.parameter_names[j], in.parameters[i * np + j]);
          Axis axis(c);
          Trace t;
          const std::size_t off = i * in.n;
#define SB_ROW(name, unit, doc) \
  if (out.signals.name) t.name = out.signals.name + off;
          SERVOBENCH_TRACE_SIGNALS(SB_ROW)
#undef SB_ROW
          if (out.metrics && !t.fb_pos) t.fb_pos = fb_scratch.data();
          CommandInput cmd;
          cmd.pos = in.pos;
          cmd.vel = vel;
          cmd.acc = acc;
          cmd.n = in.n;
          axis.run(cmd, t);
          if (out.metrics)
            out.metrics[i] = move_metrics(in.pos, t.fb_pos, in.n, axis.servo_period_s(), out.settle_band_pulse);
        } catch (const std::exception& e) {
          errors[i] = e.what();
        }
      }
      done.fetch_add(end - begin, std::memory_order_release);
    }
  };
  if (!options.poll && threads == 1) {
    work();
  } else {
    // The workers, and the calling thread polling (options.poll) until they have all finished.
    std::vector<std::thread> pool;
    pool.reserve(static_cast<std::size_t>(threads));
    std::mutex m;
    std::condition_variable cv;
    int running = threads;
    for (int w = 0; w < threads; ++w)
      pool.emplace_back([&] {
        work();
        std::lock_guard<std::mutex> g(m);
        if (--running == 0) cv.notify_all();
      });
    bool go_on = true;
    std::exception_ptr failed;  // what the poll callback threw: rethrown once every worker has stopped
    {
      std::unique_lock<std::mutex> lk(m);
      const auto period = std::chrono::duration<double>(options.poll_seconds > 0 ? options.poll_seconds : 0.05);
      while (running > 0) {
        cv.wait_for(lk, period, [&] { return running == 0; });
        if (running > 0 && options.poll && go_on) {
          lk.unlock();
          try {
            go_on = options.poll(done.load(std::memory_order_acquire), plants);
          } catch (...) {
            failed = std::current_exception();
            go_on = false;
          }
          if (!go_on) stop.store(true, std::memory_order_relaxed);
          lk.lock();
        }
      }
    }
    for (auto& th : pool) th.join();
    if (failed) std::rethrow_exception(failed);
    if (!go_on) throw BatchStopped();
    if (options.poll && !options.poll(done.load(std::memory_order_acquire), plants)) throw BatchStopped();
  }
  for (std::size_t i = 0; i < plants; ++i) {
    if (!errors[i].empty())
      throw std::invalid_argument("parameters row " + std::to_string(i) + ": " + errors[i]);
  }
  return threads;
}

}  // namespace servobench::machine
