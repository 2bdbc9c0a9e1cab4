// GucProgram: the GUC-ECAT motion program's threads, pages and symbols (vendor/googol/guc_program.hpp).
#include "servobench/vendor/googol/guc_program.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace servobench::vendor::googol {

namespace {

bool whole_in(double v, double lo, double hi) { return std::isfinite(v) && v == std::floor(v) && lo <= v && v <= hi; }

}  // namespace

GucProgram::GucProgram(machine::Card& /*card*/) {}

GucProgram& guc_program(machine::Card& card) { return card.module<GucProgram>(); }

// -- download ----------------------------------------------------------------------------------------------------------
void GucProgram::load(std::vector<GucFunction> functions, std::vector<std::string> globals, std::vector<double> values) {
  if (globals.size() != values.size())
    throw std::invalid_argument("GucProgram.load: " + std::to_string(globals.size()) + " global names but " +
                                std::to_string(values.size()) + " values");
  for (const auto& f : functions)
    if (f.param_has_default.size() > f.vars.size())
      throw std::invalid_argument("GucProgram.load: function '" + f.name + "' has more parameters than variables");
  threads_ = {};
  pages_ = {};
  functions_ = std::move(functions);
  global_names_ = std::move(globals);
  globals_ = std::move(values);
  current_ = -1;
  loaded_ = true;
}

void GucProgram::stop_all() {
  for (auto& t : threads_) {
    t.active = t.start = t.paused = false;
    t.sts.run = 0;
  }
  current_ = -1;
}

void GucProgram::reset() { stop_all(); }

// -- symbols -------------------------------------------------------------------------------------------------------------
const GucFunction* GucProgram::function_named(const std::string& name) const {
  for (const auto& f : functions_)
    if (f.name == name) return &f;
  return nullptr;
}

std::pair<GucCode, int> GucProgram::fun_id(const std::string& name) const {
  for (std::size_t k = 0; k < functions_.size(); ++k)
    if (functions_[k].name == name) return {GucCode::Success, static_cast<int>(k) + 1};
  return {GucCode::CommandError, 0};
}

std::pair<GucCode, GucVarInfo> GucProgram::var_id(const std::string& function, const std::string& var) const {
  if (!loaded_) return {GucCode::CommandError, {}};
  const std::vector<std::string>* names = &global_names_;
  if (!function.empty()) {
    const GucFunction* f = function_named(function);
    if (f == nullptr) return {GucCode::CommandError, {}};
    names = &f->vars;
  }
  const auto it = std::find(names->begin(), names->end(), var);
  if (it == names->end()) return {GucCode::CommandError, {}};
  return {GucCode::Success, GucVarInfo{static_cast<int>(it - names->begin()), function, var}};
}

// -- threads -------------------------------------------------------------------------------------------------------------
GucProgram::Thread* GucProgram::thread_at(double thread) {
  return whole_in(thread, 0, kThreads - 1) ? &threads_[static_cast<std::size_t>(thread)] : nullptr;
}

const GucProgram::Thread* GucProgram::thread_at(double thread) const {
  return whole_in(thread, 0, kThreads - 1) ? &threads_[static_cast<std::size_t>(thread)] : nullptr;
}

GucCode GucProgram::bind(double thread, double fun_id, double page) {
  Thread* t = thread_at(thread);
  if (t == nullptr || !whole_in(page, 0, kPages - 1) || !whole_in(fun_id, 1, 32768)) return GucCode::ParameterError;
  if (t->sts.run != 0 || fun_id > static_cast<double>(functions_.size())) return GucCode::CommandError;  // L2256
  const int p = static_cast<int>(page);
  for (const auto& o : threads_)
    if (&o != t && o.page == p) return GucCode::CommandError;  // one page, one thread (L2258)
  t->fun_id = static_cast<int>(fun_id);
  t->page = p;
  return GucCode::Success;
}

GucCode GucProgram::run_thread(double thread) {
  Thread* t = thread_at(thread);
  if (t == nullptr) return GucCode::ParameterError;
  if (t->paused) {  // resumes where it stood (L2178-2182)
    t->paused = false;
    t->sts.run = 1;
    return GucCode::Success;
  }
  if (t->sts.run != 0 || t->fun_id == 0 || t->fun_id > static_cast<int>(functions_.size()))
    return GucCode::CommandError;
  const GucFunction& f = functions_[static_cast<std::size_t>(t->fun_id - 1)];
  const auto& page = pages_[static_cast<std::size_t>(t->page)];
  t->args.clear();
  t->live.assign(f.vars.size(), std::nullopt);
  for (std::size_t k = 0; k < f.param_has_default.size(); ++k) {
    const auto v = page.find(f.vars[k]);
    if (v != page.end()) {
      t->args.emplace_back(f.vars[k], v->second);
    } else if (!f.param_has_default[k]) {
      t->args.emplace_back(f.vars[k], 0.0);  // a C local nobody set reads 0
    } else {
      continue;  // the function's default
    }
    t->live[k] = t->args.back().second;
  }
  t->active = t->start = true;
  t->sts = GucThreadSts{1, 0, 0.0, f.first_line};
  return GucCode::Success;
}

GucCode GucProgram::stop_thread(double thread) {
  Thread* t = thread_at(thread);
  if (t == nullptr) return GucCode::ParameterError;
  t->active = t->start = t->paused = false;
  t->sts.run = 0;
  return GucCode::Success;
}

GucCode GucProgram::pause_thread(double thread) {
  Thread* t = thread_at(thread);
  if (t == nullptr) return GucCode::ParameterError;
  if (!t->active || t->paused) return GucCode::CommandError;
  t->paused = true;
  t->sts.run = 2;
  return GucCode::Success;
}

std::pair<GucCode, GucThreadSts> GucProgram::thread_status(double thread) const {
  const Thread* t = thread_at(thread);
  if (t == nullptr) return {GucCode::ParameterError, {}};
  return {GucCode::Success, t->sts};
}

bool GucProgram::any_active() const {
  return std::any_of(threads_.begin(), threads_.end(), [](const Thread& t) { return t.active; });
}

// -- variables -------------------------------------------------------------------------------------------------------------
std::optional<std::vector<std::string>> GucProgram::names_of(int page, double id, const std::string& function,
                                                             int count) const {
  if (!loaded_) return std::nullopt;
  const std::vector<std::string>* names = nullptr;
  if (page == kGlobalPage) {
    if (function.empty()) names = &global_names_;
  } else if (!function.empty()) {
    if (const GucFunction* f = function_named(function)) names = &f->vars;
  }
  if (names == nullptr || !whole_in(id, 0, static_cast<double>(names->size()) - count)) return std::nullopt;
  const auto first = names->begin() + static_cast<std::ptrdiff_t>(id);
  return std::vector<std::string>(first, first + count);
}

GucCode GucProgram::set_var_value(double page, double id, const std::string& function,
                                  const std::vector<double>& values, double count) {
  if (!whole_in(page, kGlobalPage, kPages - 1)) return GucCode::ParameterError;
  if (!whole_in(count, 1, kMaxCount) || values.size() < static_cast<std::size_t>(count)) return GucCode::ParameterError;
  const int n = static_cast<int>(count);
  for (int k = 0; k < n; ++k)
    if (!whole_in(values[static_cast<std::size_t>(k)], kDintMin, kDintMax)) return GucCode::ParameterError;
  const int p = static_cast<int>(page);
  const auto names = names_of(p, id, function, n);
  if (!names) return GucCode::CommandError;
  for (int k = 0; k < n; ++k) {
    const double v = values[static_cast<std::size_t>(k)];
    if (p == kGlobalPage)
      globals_[static_cast<std::size_t>(id) + static_cast<std::size_t>(k)] = v;
    else
      pages_[static_cast<std::size_t>(p)][(*names)[static_cast<std::size_t>(k)]] = v;
  }
  return GucCode::Success;
}

std::pair<GucCode, std::vector<double>> GucProgram::var_value(double page, double id, const std::string& function,
                                                             double count) const {
  if (!whole_in(page, kGlobalPage, kPages - 1)) return {GucCode::ParameterError, {}};
  if (!whole_in(count, 1, kMaxCount)) return {GucCode::CommandError, {}};
  const int p = static_cast<int>(page), n = static_cast<int>(count);
  const auto names = names_of(p, id, function, n);
  if (!names) return {GucCode::CommandError, {}};
  std::vector<double> out;
  if (p == kGlobalPage) {
    const auto first = globals_.begin() + static_cast<std::ptrdiff_t>(id);
    out.assign(first, first + n);
    return {GucCode::Success, out};
  }
  const auto& values = pages_[static_cast<std::size_t>(p)];
  const Thread* live = nullptr;  // the page's active thread: its locals as it has them now (L2233)
  for (const auto& t : threads_)
    if (t.page == p && t.active) {
      live = &t;
      break;
    }
  const GucFunction* f = live != nullptr ? &functions_[static_cast<std::size_t>(live->fun_id - 1)] : nullptr;
  for (const auto& name : *names) {
    double v = 0.0;
    if (const auto it = values.find(name); it != values.end()) v = it->second;
    if (f != nullptr) {
      const auto at = std::find(f->vars.begin(), f->vars.end(), name);
      const auto k = static_cast<std::size_t>(at - f->vars.begin());
      if (at != f->vars.end() && k < live->live.size() && live->live[k]) v = *live->live[k];
    }
    out.push_back(v);
  }
  return {GucCode::Success, out};
}

// -- the host's stepping -----------------------------------------------------------------------------------------------------
std::optional<GucStep> GucProgram::next_step(int after) {
  current_ = -1;
  for (int k = std::max(after + 1, 0); k < kThreads; ++k) {
    Thread& t = threads_[static_cast<std::size_t>(k)];
    if (!t.active || t.paused) continue;
    current_ = k;
    GucStep s{k, t.start, t.fun_id, {}};
    if (t.start) s.args = t.args;
    t.start = false;
    return s;
  }
  return std::nullopt;
}

std::optional<GucStep> GucProgram::stepped(int thread, GucStepEnd end, double value, int line,
                                           const std::vector<std::optional<double>>& locals) {
  record_step(thread, end, value, line, locals);
  return next_step(thread);
}

void GucProgram::record_step(int thread, GucStepEnd end, double value, int line,
                             const std::vector<std::optional<double>>& locals) {
  current_ = -1;
  if (thread < 0 || thread >= kThreads) throw std::invalid_argument("GucProgram.stepped: thread outside 0..31");
  if (end != GucStepEnd::Yielded && end != GucStepEnd::Returned && end != GucStepEnd::Raised)
    throw std::invalid_argument("GucProgram.stepped: end outside 0..2 (yielded, returned, raised)");
  Thread& t = threads_[static_cast<std::size_t>(thread)];
  if (!t.active) return;  // the step stopped its own thread (GT_StopThread)
  if (line > 0) t.sts.line = line;
  for (std::size_t k = 0; k < std::min(locals.size(), t.live.size()); ++k)
    if (locals[k]) t.live[k] = locals[k];
  if (end == GucStepEnd::Yielded) return;
  t.active = t.paused = false;
  t.sts.run = 0;
  if (end == GucStepEnd::Returned)
    t.sts.result = value;
  else
    t.sts.error = static_cast<int>(GucCode::CommandError);  // a failing motion function stops its thread (GS14)
}

void GucProgram::record_error(int code) {
  if (current_ >= 0) threads_[static_cast<std::size_t>(current_)].sts.error = code;
}

void GucProgram::set_global_values(const std::vector<double>& values) {
  if (values.size() != globals_.size())
    throw std::invalid_argument("GucProgram.set_global_values: " + std::to_string(values.size()) + " values for " +
                                std::to_string(globals_.size()) + " globals");
  globals_ = values;
}

}  // namespace servobench::vendor::googol
